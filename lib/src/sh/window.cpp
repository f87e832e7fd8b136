#include "shpack/window.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "common/angles.h"
#include "sh/nonnegative_fit.h"
#include "shpack/sh_minimum.h"

namespace shpack {
namespace {

// sin(x)/x, with its limit 1 at 0.
double sinc(double x) noexcept { return x == 0.0 ? 1.0 : std::sin(x) / x; }

// Sloan's family: w_l = sinc(pi l / W)^4 for l < W, else 0.
std::array<double, 3> sloan_factors(double width) noexcept {
  std::array<double, 3> f = {1.0, 0.0, 0.0};
  for (int l = 1; l < 3; ++l)
    if (l < width) f[l] = std::pow(sinc(kPi * l / width), 4);
  return f;
}

double channel_minimum(const ShL2& sh, int channel, const std::array<double, 3>& f) noexcept {
  ShL2 w;
  for (int i = 0; i < kShCount; ++i) w.c[channel][i] = f[kBand[i]] * sh.c[channel][i];
  return minimum_on_sphere(w, channel).value;
}

// The widest W with a non-negative minimum, by bisection on W in (1, W_hi]: at W <= 1 the
// window leaves only L00 >= 0. W_hi = 1e6 makes w_l within 1e-11 of 1.
std::array<double, 3> sloan_channel(const ShL2& sh, int channel, bool& impossible) noexcept {
  impossible = false;
  const std::array<double, 3> none = {1.0, 1.0, 1.0};
  if (channel_minimum(sh, channel, none) >= 0.0) return none;
  if (sh.c[channel][0] < 0.0) {
    impossible = true;
    return none;
  }
  double lo = 1.0, hi = 1e6;  // minimum(lo) >= 0 > minimum(hi)
  for (int it = 0; it < 100 && hi - lo > 1e-12 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (channel_minimum(sh, channel, sloan_factors(mid)) >= 0.0 ? lo : hi) = mid;
  }
  return sloan_factors(lo);
}

// Optimal (window.h, nonnegative_fit.h) on channel `channel`: `out` holds the input there.
void optimal_channel(const ShL2& in, int channel, bool l1, ShL2& out, WindowResult& r) noexcept {
  for (const double s : in.c[channel])
    if (!std::isfinite(s)) return;  // nothing to fit; finish_projection's float32 check refuses it
  if (minimum_on_sphere(in, channel).value >= 0.0) return;
  if (in.c[channel][0] < 0.0) {
    r.impossible[channel] = true;
    return;
  }
  const NonnegativeFit fit = l1 ? nearest_nonnegative_l1(in, channel) : nearest_nonnegative(in, channel);
  out.c[channel] = fit.unity_form;
  r.planes[channel] = fit.planes;
}

// The RMS over the sphere of out - in over that of in, from the weights of nonnegative_fit.h
// (both divided by max |in_i| first, so no square overflows).
double relative_rms_change(const ShL2& in, const ShL2& out, int channel) noexcept {
  double largest = 0.0;
  for (const double s : in.c[channel]) largest = std::max(largest, std::fabs(s));
  if (!(largest > 0.0) || out.c[channel] == in.c[channel]) return 0.0;
  double change = 0.0, before = 0.0;
  for (int i = 0; i < kShCount; ++i) {
    const double d = (out.c[channel][i] - in.c[channel][i]) / largest, s = in.c[channel][i] / largest;
    change += rms_weight(i) * d * d;
    before += rms_weight(i) * s * s;
  }
  return std::sqrt(change / before);
}

}  // namespace

Status parse_window(std::string_view text, Window& window) noexcept {
  struct Named {
    std::string_view name;
    WindowKind kind;
    bool has_width;
  };
  constexpr Named kNames[] = {{"none", WindowKind::None, false},       {"unity", WindowKind::Unity, false},
                              {"sloan", WindowKind::Sloan, false},     {"optimal", WindowKind::Optimal, false},
                              {"hanning", WindowKind::Hanning, true},  {"lanczos", WindowKind::Lanczos, true}};
  const std::size_t colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  for (const Named& n : kNames) {
    if (n.name != name) continue;
    if (!n.has_width) {
      if (colon != std::string_view::npos) return Status::error(Errc::InvalidArgument, "this window takes no width");
      window = {n.kind, 0.0};
      return Status::success();
    }
    if (colon == std::string_view::npos)
      return Status::error(Errc::InvalidArgument, "hanning and lanczos need a width, e.g. hanning:3");
    const std::string_view number = text.substr(colon + 1);
    double width = 0.0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), width);
    if (ec != std::errc() || end != number.data() + number.size() || !(width > 0.0) || !std::isfinite(width))
      return Status::error(Errc::InvalidArgument, "the window width must be a finite number > 0");
    window = {n.kind, width};
    return Status::success();
  }
  return Status::error(Errc::InvalidArgument, "unknown window (none, hanning:W, lanczos:W, unity, sloan, optimal)");
}

WindowName window_name(const Window& window) noexcept {
  WindowName out{};
  const char* name = window.kind == WindowKind::Unity     ? "unity"
                     : window.kind == WindowKind::Sloan   ? "sloan"
                     : window.kind == WindowKind::Optimal ? "optimal"
                     : window.kind == WindowKind::Hanning ? "hanning"
                     : window.kind == WindowKind::Lanczos ? "lanczos"
                                                          : "none";
  char* end = std::strncpy(out.text, name, sizeof out.text - 1) + std::strlen(name);
  if (window.kind == WindowKind::Hanning || window.kind == WindowKind::Lanczos) {
    *end++ = ':';
    end = std::to_chars(end, out.text + sizeof out.text - 1, window.width).ptr;  // shortest round trip
  }
  *end = '\0';
  return out;
}

Status window_factors(const Window& window, std::array<double, 3>& f) noexcept {
  switch (window.kind) {
    case WindowKind::None:
      f = {1.0, 1.0, 1.0};
      return Status::success();
    case WindowKind::Unity:
      f = {1.0, 0.922066, 0.731864};
      return Status::success();
    case WindowKind::Hanning:
    case WindowKind::Lanczos:
      if (!(window.width > 0.0) || !std::isfinite(window.width))
        return Status::error(Errc::InvalidArgument, "window width must be a finite number > 0");
      f = {1.0, 0.0, 0.0};
      for (int l = 1; l < 3; ++l) {
        if (l >= window.width) continue;
        const double x = kPi * l / window.width;
        f[l] = window.kind == WindowKind::Hanning ? 0.5 * (1.0 + std::cos(x)) : sinc(x);
      }
      return Status::success();
    case WindowKind::Sloan:
      return Status::error(Errc::InvalidArgument, "the sloan window depends on the data");
    case WindowKind::Optimal:
      return Status::error(Errc::InvalidArgument, "the optimal fit scales no band");
  }
  return Status::error(Errc::InvalidArgument, "unknown window");
}

ShL2 apply_band_factors(const ShL2& sh, const std::array<std::array<double, 3>, 3>& factors) noexcept {
  ShL2 out;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) out.c[c][i] = factors[c][kBand[i]] * sh.c[c][i];
  return out;
}

Status apply_window(const ShL2& unity_form, const Window& window, ShL2& out, WindowResult* result,
                    bool l1) noexcept {
  WindowResult r;
  ShL2 windowed = unity_form;
  if (window.kind == WindowKind::Optimal) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    r.factors = {{{kNaN, kNaN, kNaN}, {kNaN, kNaN, kNaN}, {kNaN, kNaN, kNaN}}};
    for (int c = 0; c < kChannelCount; ++c) optimal_channel(unity_form, c, l1, windowed, r);
  } else if (window.kind == WindowKind::Sloan) {
    for (int c = 0; c < kChannelCount; ++c) r.factors[c] = sloan_channel(unity_form, c, r.impossible[c]);
  } else {
    std::array<double, 3> f;
    if (Status st = window_factors(window, f); !st.ok()) return st;
    r.factors = {f, f, f};
  }
  if (scales_bands(window.kind)) windowed = apply_band_factors(unity_form, r.factors);
  for (int c = 0; c < kChannelCount; ++c) r.rms_change[c] = relative_rms_change(unity_form, windowed, c);
  out = windowed;
  if (result != nullptr) *result = r;
  return Status::success();
}

}  // namespace shpack
