#include "shpack/io/preview.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "preview_draw.h"
#include "preview_text.h"
#include "shpack/conventions.h"
#include "shpack/io/map_source.h"
#include "shpack/layout.h"
#include "shpack/light_extraction.h"  // kRec709Luminance
#include "shpack/pipeline.h"
#include "shpack/rotate.h"
#include "shpack/unity_pack.h"
#include "shpack/view_reference.h"

namespace shpack::io {
namespace {

using detail::Rgb8;

constexpr std::uint32_t kMargin = 4;       // between panels

double luminance(const std::array<double, 3>& rgb) {
  return kRec709Luminance[0] * rgb[0] + kRec709Luminance[1] * rgb[1] + kRec709Luminance[2] * rgb[2];
}

// What Unity shows for normal n: ShadeSH9, plus each directional light's Lambert term
// colour * intensity * max(0, n . -forward) (unity_light.h; view_error.h measures the same).
std::array<double, 3> shade(const ShJsonContent& content, const Dir3& n) {
  const auto x = static_cast<float>(n.x), y = static_cast<float>(n.y), z = static_cast<float>(n.z);
  std::array<double, 3> v = {shade_sh9(content.shader, 0, x, y, z), shade_sh9(content.shader, 1, x, y, z),
                             shade_sh9(content.shader, 2, x, y, z)};
  for (const UnitySunLight& l : content.lights) {
    const double lambert = std::max(0.0, -(n.x * l.forward.x + n.y * l.forward.y + n.z * l.forward.z));
    for (int c = 0; c < 3; ++c) v[c] += l.colour[c] * l.intensity * lambert;
  }
  return v;
}

// A tone-mapped pixel, or the negative mark if a channel is below 0.
Rgb8 display(const std::array<double, 3>& value, double exposure, std::uint32_t x, std::uint32_t y) {
  if (value[0] < 0 || value[1] < 0 || value[2] < 0) return detail::negative_mark(x, y);
  return {detail::tone_map(value[0], exposure), detail::tone_map(value[1], exposure),
          detail::tone_map(value[2], exposure)};
}

void put(Rgb8Image& image, std::uint32_t x, std::uint32_t y, Rgb8 colour) {
  std::copy(colour.begin(), colour.end(), image.at(x, y));
}

// The pixel of an equirect panel that direction d falls in.
void panel_pixel(const Dir3& d, std::uint32_t width, std::uint32_t height, std::uint32_t& x, std::uint32_t& y) {
  const double u = 0.5 - std::atan2(d.z, d.x) / (2 * std::numbers::pi);
  const double t = std::acos(std::clamp(d.y, -1.0, 1.0)) / std::numbers::pi;
  x = std::min(width - 1, static_cast<std::uint32_t>(u * width));
  y = std::min(height - 1, static_cast<std::uint32_t>(t * height));
}

// A small ring around each light's direction (towards it: -forward) on an equirect panel.
void mark_lights(Rgb8Image& image, const PanelRect& panel, const ShJsonContent& content) {
  for (const UnitySunLight& l : content.lights) {
    std::uint32_t cx = 0, cy = 0;
    panel_pixel({-l.forward.x, -l.forward.y, -l.forward.z}, panel.width, panel.height, cx, cy);
    const int r = std::max(3, static_cast<int>(panel.height / 40));
    for (int k = 0; k < 8 * r; ++k) {
      const double a = 2 * std::numbers::pi * k / (8 * r);
      const long px = std::lround(cx + r * std::cos(a)), py = std::lround(cy + r * std::sin(a));
      if (px >= 0 && py >= 0 && px < panel.width && py < panel.height)
        put(image, panel.x + static_cast<std::uint32_t>(px), panel.y + static_cast<std::uint32_t>(py), {0, 255, 255});
    }
  }
}

// The axes on an equirect panel (conventions.h): +X at the centre, +Z a quarter from the
// left, -X at the edges, -Z three quarters; up at the top. A tick and its name below the panel.
void mark_axes(Rgb8Image& image, const PanelRect& panel, const detail::TextPainter& text) {
  const struct {
    double u;
    const char* name;
  } axes[] = {{0.25, "+Z"}, {0.5, "+X"}, {0.75, "-Z"}};
  for (const auto& a : axes) {
    const auto x = panel.x + static_cast<std::uint32_t>(a.u * panel.width);
    for (std::uint32_t y = 0; y < 4; ++y) put(image, x, panel.y + y, {255, 255, 255});
    text.draw(image, x + 2, panel.y + 2, a.name);
  }
  text.draw(image, panel.x + 2, panel.y + 2, "up");
}

// The direction of pixel (x, y) of a width x height equirect panel, and its solid angle.
Dir3 panel_direction(std::uint32_t x, std::uint32_t y, std::uint32_t width, std::uint32_t height) {
  return equirect_direction((x + 0.5) / width, (y + 0.5) / height);
}
double panel_solid_angle(std::uint32_t y, std::uint32_t width, std::uint32_t height) {
  const double t0 = std::numbers::pi * y / height, t1 = std::numbers::pi * (y + 1) / height;
  return (2.0 * std::numbers::pi / width) * 2.0 * std::sin(0.5 * (t0 + t1)) * std::sin(0.5 * (t1 - t0));
}

// "front": seen from -Z; "top": seen from +Y (preview.h). Outside the disc: background.
void draw_sphere(Rgb8Image& image, const PanelRect& rect, bool top, const ShJsonContent& content, double exposure) {
  for (std::uint32_t j = 0; j < rect.height; ++j) {
    for (std::uint32_t i = 0; i < rect.width; ++i) {
      const double sx = 2.0 * (i + 0.5) / rect.width - 1.0, sy = 1.0 - 2.0 * (j + 0.5) / rect.height;
      const double r2 = sx * sx + sy * sy;
      if (r2 >= 1.0) continue;
      const double depth = std::sqrt(1.0 - r2);
      const Dir3 n = top ? Dir3{sx, depth, sy} : Dir3{sx, sy, -depth};
      put(image, rect.x + i, rect.y + j, display(shade(content, n), exposure, rect.x + i, rect.y + j));
    }
  }
}

std::string number(double v, bool sign) {
  char text[32];
  std::snprintf(text, sizeof text, sign ? "%+.3g" : "%.3g", v);
  return text;
}

// The input map as the document's truth: any layout convert reads, through the same source
// (its colour matrix to Rec. 709 included), with NaN/Inf texels read as 0 as the view error
// reads them (view_reference.h).
// The input as it is stored (its own layout; six faces side by side, +X to -Z), fitted into
// max_w x max_h by nearest texels: RGB floats, NaN/Inf as 0, grey as R = G = B.
struct Thumbnail {
  std::uint32_t width = 0, height = 0;
  std::vector<std::array<double, 3>> rgb;
};

std::array<double, 3> texel_rgb(const ImageView& view, std::uint32_t x, std::uint32_t y) {
  const auto* p = reinterpret_cast<const float*>(view.pixel(x, y));
  std::array<double, 3> v{};
  for (int c = 0; c < 3; ++c) {
    const float f = p[view.channels >= 3 ? c : 0];
    v[c] = std::isfinite(f) ? f : 0.0;
  }
  return v;
}

Thumbnail thumbnail_of(const MapImage& map, std::uint32_t max_w, std::uint32_t max_h) {
  std::array<ImageView, kCubeFaceCount> faces = map.faces;
  const bool six = map.layout == Layout::Faces;
  ImageView one = map.image;
  if (six) {
    for (ImageView& f : faces) (void)resolve_view(f);
  } else {
    (void)resolve_view(one);
  }
  const std::uint32_t n = six ? faces[0].width : 0;
  const std::uint32_t w = six ? 6 * n : one.width, h = six ? n : one.height;
  const double scale = std::min(static_cast<double>(max_w) / w, static_cast<double>(max_h) / h);
  Thumbnail t;
  t.width = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(w * scale));
  t.height = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(h * scale));
  t.rgb.resize(std::size_t{t.width} * t.height);
  for (std::uint32_t y = 0; y < t.height; ++y)
    for (std::uint32_t x = 0; x < t.width; ++x) {
      const std::uint32_t sx = std::min(w - 1, static_cast<std::uint32_t>((x + 0.5) / scale));
      const std::uint32_t sy = std::min(h - 1, static_cast<std::uint32_t>((y + 0.5) / scale));
      t.rgb[std::size_t{y} * t.width + x] = six ? texel_rgb(faces[sx / n], sx % n, sy) : texel_rgb(one, sx, sy);
    }
  return t;
}

IoStatus load_reference(const PreviewSettings& settings, ViewReference& reference, std::optional<Matrix3>& matrix,
                        Thumbnail& thumbnail) {
  MapSource source;
  SourceOptions options;
  options.layout = settings.reference_layout;
  if (IoStatus st = source.open(settings.reference, options); !st.ok()) return st;
  MapImage map;
  if (IoStatus st = source.read_whole(map, 0); !st.ok()) return st;
  const ProjectOptions project{SamplingMethod::Exact, NonFinite::Zero, Negative::Keep, 0};
  if (Status st = build_view_reference(map, project, reference); !st.ok())
    return IoStatus::error(IoErrc::Core, settings.reference, st.what);
  matrix = source.info().colour.matrix;
  thumbnail = thumbnail_of(map, 2 * settings.size, settings.size);
  return IoStatus::success();
}

// k M v, and k |M| v for a bound (no matrix: the identity).
std::array<double, 3> to_output(const std::optional<Matrix3>& m, double k, const std::array<double, 3>& v,
                                bool absolute) {
  std::array<double, 3> out = v;
  if (m)
    for (int c = 0; c < 3; ++c) {
      out[c] = 0;
      for (int j = 0; j < 3; ++j) out[c] += (absolute ? std::abs((*m)[c][j]) : (*m)[c][j]) * v[j];
    }
  for (double& x : out) x *= k;
  return out;
}

}  // namespace

IoStatus render_preview(const ShJsonContent& content, const PreviewSettings& settings, Rgb8Image& image,
                        PreviewReport& report) {
  const std::uint32_t s = settings.size;
  if (s < 32 || s > 1024) {
    return IoStatus::error(IoErrc::InvalidArgument, "preview", "the size must be 32..1024 pixels");
  }
  std::optional<ViewReference> reference;
  std::optional<Matrix3> matrix;
  Thumbnail input;
  if (!settings.reference.empty()) {
    if (IoStatus st = load_reference(settings, reference.emplace(), matrix, input); !st.ok()) return st;
  }

  PreviewReport out;
  // The mean of what Unity shows over the sphere: the L00 terms, and a quarter of each light's
  // colour * intensity (the mean of max(0, n . l) over the sphere is 1/4).
  std::array<double, 3> mean = {content.unity_sh[0][0], content.unity_sh[1][0], content.unity_sh[2][0]};
  for (const UnitySunLight& l : content.lights)
    for (int c = 0; c < 3; ++c) mean[c] += 0.25 * l.colour[c] * l.intensity;
  out.mean_luminance = luminance(mean);
  out.exposure = out.mean_luminance > 0 ? 1.0 / out.mean_luminance : 1.0;

  // Layout: titles above the panels; the legend (row 1) and the colour bar (row 2) below.
  // Text that scales with the picture: a line a tenth of the spheres' size, 11 pixels at least.
  const detail::TextPainter text(std::max<std::uint32_t>(11, s / 10));
  const std::uint32_t kTitleHeight = text.line_height() + 4;  // a text line with its spacing
  out.truetype_text = text.truetype();
  const std::uint32_t row1 = kTitleHeight, legend = row1 + s + 2;
  out.front = {0, row1, s, s};
  out.top = {s + kMargin, row1, s, s};
  out.sh = {2 * (s + kMargin), row1, 2 * s, s};
  std::uint32_t height = legend + kTitleHeight;
  std::uint32_t row2 = 0;
  if (reference) {
    row2 = height + kTitleHeight;
    out.has_reference = true;
    out.reference = {0, row2, 2 * s, s};
    out.error = {2 * s + kMargin, row2, 2 * s, s};
    out.colour_bar = {out.error.x, row2 + s + 3, 2 * s, std::max<std::uint32_t>(8, text.line_height())};
    height = out.colour_bar.y + out.colour_bar.height + 2 + kTitleHeight;
    out.input = {0, height + kTitleHeight, input.width, input.height};  // row 3: the map itself
    height = out.input.y + out.input.height + 2;
  }
  image.width = std::max(out.sh.x + out.sh.width, out.error.x + out.error.width);
  image.height = height;
  image.pixels.assign(std::size_t{image.width} * image.height * 3, 0);
  detail::fill(image, {0, 0, image.width, image.height}, detail::kBackground);

  draw_sphere(image, out.front, false, content, out.exposure);
  draw_sphere(image, out.top, true, content, out.exposure);
  const std::uint32_t pw = 2 * s, ph = s;  // equirect panels
  double negative_solid = 0;
  std::vector<double> sh_luminance(std::size_t{pw} * ph);
  for (std::uint32_t y = 0; y < ph; ++y) {
    for (std::uint32_t x = 0; x < pw; ++x) {
      const std::array<double, 3> v = shade(content, panel_direction(x, y, pw, ph));
      if (v[0] < 0 || v[1] < 0 || v[2] < 0) negative_solid += panel_solid_angle(y, pw, ph);
      sh_luminance[std::size_t{y} * pw + x] = luminance(v);
      put(image, out.sh.x + x, out.sh.y + y, display(v, out.exposure, out.sh.x + x, out.sh.y + y));
    }
  }
  out.negative_fraction = negative_solid / (4.0 * std::numbers::pi);
  mark_lights(image, out.sh, content);
  mark_axes(image, out.sh, text);
  text.draw(image, out.front.x, 2, "front (from -Z)");
  text.draw(image, out.top.x, 2, "top (from +Y)");
  text.draw(image, out.sh.x, 2, content.lights.empty() ? "ShadeSH9 = E/\xCF\x80, centre +X" : "ShadeSH9 + lights (rings) = E/\xCF\x80");
  std::string legend_text = "stripes: E/\xCF\x80 < 0 (";
  legend_text.append(number(100.0 * out.negative_fraction, false)).append("% of the sphere). Reinhard, mean E/\xCF\x80 ");
  legend_text.append(number(out.mean_luminance, false)).append(" -> 0.5, sRGB");
  text.draw(image, 0, legend + 2, legend_text);

  if (reference) {
    const Matrix3 r = rotation_about_y(content.rotate_deg);
    std::vector<double> error(std::size_t{pw} * ph);
    double sum_sq = 0;
    for (std::uint32_t y = 0; y < ph; ++y) {
      for (std::uint32_t x = 0; x < pw; ++x) {
        // The document's environment is the map turned by R: E'(n) = E(R^T n) (rotate.h).
        const Dir3 n = panel_direction(x, y, pw, ph);
        const Dir3 v = {r[0][0] * n.x + r[1][0] * n.y + r[2][0] * n.z, r[0][1] * n.x + r[1][1] * n.y + r[2][1] * n.z,
                        r[0][2] * n.x + r[1][2] * n.y + r[2][2] * n.z};
        const ReferenceValue value = reference->eval(v);
        const std::array<double, 3> e_over_pi = to_output(matrix, content.intensity, value.e_over_pi, false);
        const std::array<double, 3> bound = to_output(matrix, content.intensity, value.bound, true);
        for (int c = 0; c < 3; ++c) out.reference_bound[c] = std::max(out.reference_bound[c], bound[c]);
        out.reference_bound_luminance = std::max(out.reference_bound_luminance, luminance(bound));
        const double e = sh_luminance[std::size_t{y} * pw + x] - luminance(e_over_pi);
        error[std::size_t{y} * pw + x] = e;
        out.max_abs_error = std::max(out.max_abs_error, std::fabs(e));
        sum_sq += e * e * panel_solid_angle(y, pw, ph);
        put(image, out.reference.x + x, out.reference.y + y,
            display(e_over_pi, out.exposure, out.reference.x + x, out.reference.y + y));
      }
    }
    out.rms_error = std::sqrt(sum_sq / (4.0 * std::numbers::pi));
    mark_axes(image, out.reference, text);
    out.error_scale = out.max_abs_error;
    const double scale = out.error_scale > 0 ? out.error_scale : 1.0;
    for (std::uint32_t y = 0; y < ph; ++y)
      for (std::uint32_t x = 0; x < pw; ++x)
        put(image, out.error.x + x, out.error.y + y, detail::error_colour(error[std::size_t{y} * pw + x] / scale));
    mark_lights(image, out.error, content);
    mark_axes(image, out.error, text);
    const PanelRect& bar = out.colour_bar;
    for (std::uint32_t x = 0; x < bar.width; ++x) {
      const Rgb8 colour = detail::error_colour(-1.0 + 2.0 * x / (bar.width - 1));
      for (std::uint32_t y = 0; y < bar.height; ++y) put(image, bar.x + x, bar.y + y, colour);
    }
    const std::uint32_t labels = bar.y + bar.height + 2;
    const std::string low = number(-out.error_scale, true), high = number(out.error_scale, true);
    text.draw(image, bar.x, labels, low);
    text.draw(image, bar.x + (bar.width - text.width("0")) / 2, labels, "0");
    text.draw(image, bar.x + bar.width - text.width(high), labels, high);

    text.draw(image, out.reference.x, row2 - kTitleHeight + 2, "reference: exact E/\xCF\x80 of the map");
    text.draw(image, out.error.x, row2 - kTitleHeight + 2, "error: shown - reference, luminance");
    const double bound_percent =
        out.mean_luminance > 0 ? 100.0 * out.reference_bound_luminance / out.mean_luminance : 0.0;
    std::string label = settings.reference_label;  // clipped to its panel
    while (label.size() > 4 && text.width(label) > out.reference.width) label = label.substr(0, label.size() - 4).append("...");
    text.draw(image, out.reference.x, bar.y, label);
    std::string bound_text = "error <= ";
    bound_text.append(number(bound_percent, false)).append("% of the mean");
    text.draw(image, out.reference.x, labels, bound_text);
    // The input as stored, with the document's colour matrix and intensity, the same tone mapping.
    for (std::uint32_t y = 0; y < input.height; ++y)
      for (std::uint32_t x = 0; x < input.width; ++x) {
        const std::array<double, 3> v =
            to_output(matrix, content.intensity, input.rgb[std::size_t{y} * input.width + x], false);
        const std::array<double, 3> shown = {std::max(0.0, v[0]), std::max(0.0, v[1]), std::max(0.0, v[2])};
        put(image, out.input.x + x, out.input.y + y, display(shown, out.exposure, out.input.x + x, out.input.y + y));
      }
    text.draw(image, out.input.x, out.input.y - kTitleHeight + 2, "input: the map as stored (radiance)");
  }
  report = out;
  return IoStatus::success();
}

}  // namespace shpack::io
