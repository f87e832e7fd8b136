// equirect_texels.h (private) - what the light extraction reads of an equirect map, shared by
// the sun (sun_extraction.cpp) and the light candidates (light_candidates.cpp): the texels as
// the projector reads them (light_extraction.h's value policies), their patches of the sphere,
// the walk over a cap of the sphere, the level of a ring, and the writing of a fill level.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <vector>

#include "common/angles.h"
#include "projection/equirect_integrals.h"
#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/light_candidates.h"
#include "shpack/light_extraction.h"

namespace shpack::detail {

inline double dot(const Dir3& a, const Dir3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The angle between two unit vectors from their dot product (rounding clamped).
inline double angle_of(double cosine) { return std::acos(std::clamp(cosine, -1.0, 1.0)); }

// The texels of one resolved F32 equirect view, read as RGB whatever the channel count. Holds
// the sines and cosines of its rows' and columns' centre angles (2 (W + H) doubles; may throw
// std::bad_alloc), so that a texel's centre costs two products.
class EquirectTexels {
 public:
  EquirectTexels(const ImageView& image, const SunSearch& search)
      : image_(image), search_(search), sin_theta_(image.height), cos_theta_(image.height),
        cos_lon_(image.width), sin_lon_(image.width) {
    for (std::uint32_t y = 0; y < image.height; ++y) {
      const double theta = equirect_theta((y + 0.5) / image.height);
      sin_theta_[y] = std::sin(theta), cos_theta_[y] = std::cos(theta);
    }
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const double lon = equirect_lon((x + 0.5) / image.width);
      cos_lon_[x] = std::cos(lon), sin_lon_[x] = std::sin(lon);
    }
  }

  std::uint32_t width() const { return image_.width; }
  std::uint32_t height() const { return image_.height; }
  std::array<double, 3> rgb(std::uint32_t x, std::uint32_t y) const {
    const std::byte* texel = image_.pixel(x, y);
    std::array<double, 3> out;
    for (int c = 0; c < 3; ++c) {
      float v;
      std::memcpy(&v, texel + 4 * (image_.channels >= 3 ? c : 0), sizeof v);
      out[c] = !std::isfinite(v) || (v < 0 && search_.negative == Negative::Clamp) ? 0.0 : v;
    }
    return out;
  }
  double luminance(std::uint32_t x, std::uint32_t y) const { return luminance(rgb(x, y)); }
  double luminance(const std::array<double, 3>& v) const {
    return search_.luminance[0] * v[0] + search_.luminance[1] * v[1] + search_.luminance[2] * v[2];
  }
  // equirect_direction((x + 0.5) / W, (y + 0.5) / H), the same products of the same values.
  Dir3 centre(std::uint32_t x, std::uint32_t y) const {
    return {sin_theta_[y] * cos_lon_[x], cos_theta_[y], sin_theta_[y] * sin_lon_[x]};
  }
  // The texel's patch (conventions.h): its theta integrals (per unit of longitude) and its
  // longitude integrals.
  ThetaIntegrals row(std::uint32_t y) const {
    return theta_integrals(std::numbers::pi * y / image_.height, std::numbers::pi * (y + 1) / image_.height);
  }
  LonIntegrals column(std::uint32_t x) const {
    return lon_integrals((0.5 - static_cast<double>(x + 1) / image_.width) * 2 * std::numbers::pi,
                         (0.5 - static_cast<double>(x) / image_.width) * 2 * std::numbers::pi);
  }
  double solid_angle(std::uint32_t x, std::uint32_t y) const { return row(y).solid * column(x).length; }

  // Calls f(x, y, angle) for every texel whose centre is within `radius` (radians) of the unit
  // vector `d`, in row-major order, scanning only the rows and columns that can hold one.
  template <class F>
  void within(const Dir3& d, double radius, F f) const {
    const double theta = angle_of(d.y);
    const auto first =
        static_cast<std::uint32_t>(std::max(0.0, std::floor((theta - radius) / std::numbers::pi * height())));
    const auto last = static_cast<std::uint32_t>(
        std::min<double>(height(), std::ceil((theta + radius) / std::numbers::pi * height()) + 1));
    const double cos_radius = std::cos(radius);
    const ColumnSpan span = columns_within(d, radius);
    for (std::uint32_t y = first; y < last; ++y)
      for (const auto& [begin, end] : span.ranges)
        for (std::uint32_t x = begin; x < end; ++x) {
          const double c = dot(centre(x, y), d);
          if (c >= cos_radius) f(x, y, std::acos(std::min(c, 1.0)));
        }
  }

  // `radius` (the largest angle from `d` to a texel centre) widened by half a texel diagonal at
  // the widest row it reaches, so that a ring starting there is clear of the texels' patches.
  double padded_radius(const Dir3& d, double radius) const {
    const double row_sin = std::min(1.0, std::sin(angle_of(d.y)) + std::sin(radius));
    return radius + 0.5 * std::hypot(std::numbers::pi / height(), 2 * std::numbers::pi / width() * row_sin);
  }

 private:
  // Up to two column ranges [begin, end), in increasing order, holding every column whose
  // centre can be within the radius: a cap of angular radius r about a direction at polar angle
  // theta (not holding a pole) spans the longitudes lon(d) +- asin(sin r / sin theta), widened
  // by one column each way against rounding. The order of the texels within() visits is the
  // order of a scan of every column, so what it adds up does not depend on the narrowing.
  struct ColumnSpan {
    std::array<std::array<std::uint32_t, 2>, 2> ranges{};
  };
  ColumnSpan columns_within(const Dir3& d, double radius) const {
    const auto w = static_cast<std::int64_t>(width());
    ColumnSpan all;
    all.ranges[0] = {0, width()};
    const double sin_theta = std::hypot(d.x, d.z);
    if (radius >= 0.5 * std::numbers::pi || std::sin(radius) >= sin_theta) return all;
    const double half = std::asin(std::sin(radius) / sin_theta);
    // Column x has its centre at lon = (0.5 - (x + 0.5)/W) 2 pi, so x = (0.5 - lon/(2 pi)) W - 0.5.
    const double centre = (0.5 - std::atan2(d.z, d.x) / (2 * std::numbers::pi)) * width() - 0.5;
    const double reach = half / (2 * std::numbers::pi) * width();
    const auto lo = static_cast<std::int64_t>(std::floor(centre - reach)) - 1;
    const auto hi = static_cast<std::int64_t>(std::ceil(centre + reach)) + 2;  // exclusive
    if (hi - lo >= w) return all;
    const std::int64_t a = ((lo % w) + w) % w, b = a + (hi - lo);  // [a, b), b may pass W
    ColumnSpan span;
    if (b <= w) {
      span.ranges[0] = {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)};
    } else {
      span.ranges[0] = {0, static_cast<std::uint32_t>(b - w)};
      span.ranges[1] = {static_cast<std::uint32_t>(a), width()};
    }
    return span;
  }

  ImageView image_;
  SunSearch search_;
  std::vector<double> sin_theta_, cos_theta_, cos_lon_, sin_lon_;
};

// The solid-angle-weighted mean of the texels from `inner` to `outer` (radians) of `d`, per
// channel, and the ring's solid angle (0: no texel centre in the ring).
struct RingLevel {
  std::array<double, 3> level{};
  double solid = 0;
};
inline RingLevel ring_level(const EquirectTexels& texels, const Dir3& d, double inner, double outer) {
  std::array<double, 3> sum{};
  RingLevel ring;
  texels.within(d, outer, [&](std::uint32_t x, std::uint32_t y, double angle) {
    if (angle < inner) return;
    const double solid = texels.solid_angle(x, y);
    const std::array<double, 3> v = texels.rgb(x, y);
    for (int c = 0; c < 3; ++c) sum[c] += v[c] * solid;
    ring.solid += solid;
  });
  if (ring.solid > 0)
    for (int c = 0; c < 3; ++c) ring.level[c] = sum[c] / ring.solid;
  return ring;
}

// Whether `pixels` is the writable memory of the resolved view: packed F32 texels at the
// view's own address, as make_view makes them.
inline bool writable_view(const ImageView& view, const float* pixels) {
  const std::int64_t texel = 4 * std::int64_t{view.channels};
  return view.type == PixelType::F32 && pixels != nullptr && view.pixel_stride == texel &&
         view.row_stride == texel * view.width && view.data == reinterpret_cast<const std::byte*>(pixels);
}

// Sets texel t of a writable view (writable_view) to `value`: R, G, B, or the grey channel.
inline void write_texel(const ImageView& view, float* pixels, LightTexel t, const std::array<double, 3>& value) {
  float* texel = pixels + (std::size_t{t.y} * view.width + t.x) * view.channels;
  for (std::uint32_t c = 0; c < (view.channels >= 3 ? 3u : 1u); ++c) texel[c] = static_cast<float>(value[c]);
}

}  // namespace shpack::detail
