// window.h - deringing: per-band windows of L2 coefficients, and the nearest non-negative fit.
//
// L2 truncation of a small bright source rings: E/pi goes negative on a ring away from it
// (for a directional light of irradiance E the minimum is -19 E / (480 pi), 122.2 degrees
// from the light). A window multiplies band l by w_l (w_0 = 1, so L00 and the mean are
// kept). It is a convolution with a zonal kernel, so it commutes with the cosine-lobe
// convolution and can be applied to radiance, irradiance or Unity-form coefficients alike.
//
//  - WindowKind::Hanning, width W:  w_l = (1 + cos(pi l / W)) / 2 for l < W, else 0
//    [2] "Stupid SH Tricks", sec. "Windowing".
//  - WindowKind::Lanczos, width W:  w_l = sin(pi l / W) / (pi l / W) for l < W, else 0 [2].
//  - WindowKind::Unity: (1, 0.922066, 0.731864), the factors Unity's path-tracing baker
//    applies (ProbePostProcessing.compute); Unity applies them to direct light only, shpack
//    to the whole environment it is given.
//  - WindowKind::Sloan: P.-P. Sloan, "Deringing Spherical Harmonics" (2017): per channel,
//    the widest window of the family w_l = sinc(pi l / W)^4 (as Filament's cmgen) whose
//    result has a minimum of E/pi >= 0, found by bisection on W with the exact minimum of
//    sh_minimum.h; a channel that does not ring is left unchanged. It is possible exactly
//    when L00 >= 0 (W -> 0 leaves the constant L00); a channel with L00 < 0 is left
//    unwindowed and reported.
//  - WindowKind::Optimal: per channel, the non-negative E/pi nearest to the projection in
//    the RMS of E/pi over the sphere: a convex QP in the 9 coefficients with one linear
//    constraint per direction, solved by cutting planes with the exact minimum of
//    sh_minimum.h (lib/src/sh/nonnegative_fit.h derives it). It is not a window in the
//    sense above: it changes each coefficient on its own, L00 included (filling the ring
//    partly by raising the mean costs less than shrinking bands 1 and 2 alone), so it has
//    no per-band factors. It is never farther from the projection than sloan's result,
//    which is non-negative too (up to its tolerance, 1e-9 of the RMS of E/pi). A channel
//    that does not ring is left unchanged, bit for bit. A channel that rings with L00 < 0
//    has a negative mean E/pi, negative light in total: it is left unchanged and reported,
//    as by sloan (a nearest non-negative function exists, but it would replace such an
//    input rather than correct it).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

enum class WindowKind : std::uint8_t { None, Hanning, Lanczos, Unity, Sloan, Optimal };

// True for every kind but Optimal: the result is band l of the input times one factor w_l.
constexpr bool scales_bands(WindowKind kind) noexcept { return kind != WindowKind::Optimal; }

struct Window {
  WindowKind kind = WindowKind::None;
  double width = 0;  // W, in bands, for Hanning and Lanczos (> 0)
};

// Parses "none", "hanning:W", "lanczos:W", "unity", "sloan" or "optimal" (the CLI's --window).
Status parse_window(std::string_view text, Window& window) noexcept;

// The same text back, e.g. "hanning:2.5" (shortest form that parses to the same width).
struct WindowName {
  char text[40];
};
WindowName window_name(const Window& window) noexcept;

// The factors (w_0, w_1, w_2) of a fixed window (not Sloan, which depends on the data, nor
// Optimal, which has none).
Status window_factors(const Window& window, std::array<double, 3>& factors) noexcept;

// Multiplies band l of channel c by factors[c][l].
ShL2 apply_band_factors(const ShL2& sh, const std::array<std::array<double, 3>, 3>& factors) noexcept;

struct WindowResult {
  // Per channel, per band, as applied (scales_bands): out_c,i = factors[c][l_i] in_c,i.
  // Meaningless for Optimal, which scales no band: NaN there, so that no reader can take
  // them for factors.
  std::array<std::array<double, 3>, 3> factors{};
  std::array<bool, 3> impossible{};  // Sloan and Optimal: channel rings and has L00 < 0
  // Every kind: per channel, the RMS over the sphere of the change of E/pi, over the RMS of
  // E/pi before the window (0 when unchanged; Optimal's is <= 1 up to its tolerance, as
  // E/pi = 0 is one of its candidates).
  std::array<double, 3> rms_change{};
  std::array<int, 3> planes{};  // Optimal: directions its cutting-plane loop added (<= 64)
};

// Windows Unity-form coefficients (Sloan and Optimal need E/pi, i.e. Unity form). To keep
// radiance coefficients consistent, apply the same `result.factors` to them when
// scales_bands(window.kind); for Optimal the radiance is out_c,i / kUnityScale[i]
// (convolution.h). l1: band 2 of the input is 0 and must stay 0 (FinishOptions::l1): Sloan
// then finds the least windowing that makes the L1 function non-negative, and Optimal the
// nearest non-negative L1 function, in closed form (lib/src/sh/nonnegative_fit.h); the fixed
// windows scale bands, which keeps band 2 at 0.
Status apply_window(const ShL2& unity_form, const Window& window, ShL2& out, WindowResult* result = nullptr,
                    bool l1 = false) noexcept;

}  // namespace shpack
