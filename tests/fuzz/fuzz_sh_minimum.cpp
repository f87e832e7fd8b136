// libFuzzer target: the exact minimum of E/pi (sh_minimum.h) and the deringing windows
// (window.h) given arbitrary coefficients and window texts.
// Coefficients are m * 10^e with m in [-1, 1] and e in [-30, 30] (a dynamic range of 60
// orders, zeros and exact repeats included), or raw doubles (NaN, Inf, denormals, 1e308).
// Properties, for the first kind: the minimum is attained at its unit direction, is not
// above the function at 26 probe directions (axes, face and corner diagonals), up to
// rounding, 64 u sum |s_i| (|P_i| <= 2); every per-band window keeps L00; after sloan and
// optimal each channel not reported impossible has a minimum >= 0, and a channel is
// impossible exactly when it rings with L00 < 0; optimal leaves a channel that does not ring
// bit for bit, ends within its plane cap, and is no farther in RMS than E/pi = 0 (nor than
// sloan's result) beyond its tolerance. For raw doubles: no crash, no sanitizer report,
// bounded time (the cutting-plane loop is capped). parse_window: whatever it
// accepts, window_name prints back to the same window.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string_view>

#include "shpack/sh_basis.h"
#include "shpack/sh_minimum.h"
#include "shpack/window.h"

namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

// Optimal's RMS change (window.h: over the RMS before) is no larger than sloan's, beyond
// optimal's tolerance (1e-9 of the RMS before) and rounding of the two ratios.
bool no_farther(const shpack::WindowResult& optimal, const shpack::WindowResult& sloan, int c) {
  return optimal.rms_change[c] <= sloan.rms_change[c] + 1e-9 + 1e-14;
}

struct Reader {
  const std::uint8_t* data;
  std::size_t size;
  std::uint8_t byte() {
    if (size == 0) return 0;
    --size;
    return *data++;
  }
  double raw() {
    std::uint64_t v = 0;
    for (int k = 0; k < 8; ++k) v = v << 8 | byte();
    double d;
    std::memcpy(&d, &v, sizeof d);
    return d;
  }
  double scaled() {  // m * 10^e, m in [-1, 1] (3 bytes), e in [-30, 30]
    const std::uint8_t e = byte();
    if (e == 0) return 0.0;
    const int m = (byte() << 16 | byte() << 8 | byte()) - (1 << 23);
    return m / double(1 << 23) * std::pow(10.0, static_cast<int>(e % 61) - 30);
  }
};

void check_window_text(std::string_view text) {
  shpack::Window w;
  if (!shpack::parse_window(text, w).ok()) return;
  shpack::Window again;
  if (!shpack::parse_window(shpack::window_name(w).text, again).ok() || again.kind != w.kind || again.width != w.width)
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in{data, size};
  const std::uint8_t mode = in.byte();
  if (mode % 4 == 3) {  // a window text
    check_window_text(std::string_view(reinterpret_cast<const char*>(in.data), in.size));
    return 0;
  }
  const bool raw = mode % 4 == 2;
  shpack::ShL2 sh;
  for (auto& channel : sh.c)
    for (double& s : channel) s = raw ? in.raw() : in.scaled();

  shpack::Window windows[6];
  const char* names[6] = {"none", "hanning:2.5", "lanczos:3", "unity", "sloan", "optimal"};
  for (int k = 0; k < 6; ++k)
    if (!shpack::parse_window(names[k], windows[k]).ok()) std::abort();

  for (int c = 0; c < shpack::kChannelCount; ++c) {
    const shpack::SphereMinimum m = shpack::minimum_on_sphere(sh, c);
    if (raw) continue;  // any result; the run itself is the test
    double scale = 0;
    for (double s : sh.c[c]) scale += std::fabs(s);
    const double tol = 64 * kU * 2 * scale;
    const shpack::Dir3 d = m.direction;
    const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(std::fabs(len - 1) <= 1e-12)) std::abort();
    if (!(std::fabs(shpack::eval_unity_form(sh, c, d.x, d.y, d.z) - m.value) <= tol)) std::abort();
    const double r2 = std::sqrt(0.5), r3 = std::sqrt(1.0 / 3.0);
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          const int nonzero = (x != 0) + (y != 0) + (z != 0);
          if (nonzero == 0) continue;
          const double f = nonzero == 1 ? 1.0 : nonzero == 2 ? r2 : r3;
          if (!(m.value <= shpack::eval_unity_form(sh, c, f * x, f * y, f * z) + tol)) std::abort();
        }
  }
  shpack::WindowResult sloan;
  for (const shpack::Window& w : windows) {
    shpack::ShL2 out;
    shpack::WindowResult result;
    if (!shpack::apply_window(sh, w, out, &result).ok()) std::abort();
    if (raw) continue;
    const bool optimal = w.kind == shpack::WindowKind::Optimal;
    for (int c = 0; c < shpack::kChannelCount; ++c) {
      const double before = shpack::minimum_on_sphere(sh, c).value;
      if (!optimal && out.c[c][0] != sh.c[c][0]) std::abort();
      if (w.kind != shpack::WindowKind::Sloan && !optimal) continue;
      if (result.impossible[c] != (sh.c[c][0] < 0 && before < 0)) std::abort();
      if (!result.impossible[c] && !(shpack::minimum_on_sphere(out, c).value >= 0)) std::abort();
      if (!optimal) continue;
      if (before >= 0 && out.c[c] != sh.c[c]) std::abort();
      if (result.planes[c] > 64 || !(result.rms_change[c] <= 1 + 1e-9 + 1e-14)) std::abort();
      if (!result.impossible[c] && !no_farther(result, sloan, c)) std::abort();
    }
    if (w.kind == shpack::WindowKind::Sloan) sloan = result;
  }
  return 0;
}
