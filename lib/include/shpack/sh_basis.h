// sh_basis.h - the real L2 spherical-harmonic basis in Unity's index order and its constants.
//
// References (cited below as [n]):
//  [1] R. Ramamoorthi, P. Hanrahan, "An Efficient Representation for Irradiance Environment
//      Maps", SIGGRAPH 2001 (basis constants, clamped-cosine zonal factors A_l).
//  [2] P.-P. Sloan, "Stupid Spherical Harmonics (SH) Tricks", GDC 2008.
//  [3] Unity, CGIncludes/UnityCG.cginc: SHEvalLinearL0L1, SHEvalLinearL2.
//  [4] Unity, UnityCsReference Runtime/Export/Math/SphericalHarmonicsL2.bindings.cs.
//  [5] docs/conventions.md (normative for this project), sections 3-6.
//
// Basis: real SH without the Condon-Shortley phase, Y_i = k_i * P_i(x, y, z) on the unit
// sphere, in Unity's frame (conventions.h). Index order is Unity's, i = l*(l+1) + m:
//
//   i      0    1    2    3    4    5    6        7    8
//   P_i    1    y    z    x    xy   yz   3z^2-1   xz   x^2-y^2
//   k_i    k0   k1   k1   k1   k2   k2   k3       k2   k4
//   l      0    1    1    1    2    2    2        2    2
//
// "L2" means these 9 coefficients (bands l = 0, 1, 2).
#pragma once

#include <array>
#include <cstddef>

namespace shpack {

inline constexpr int kShCount = 9;       // L2: 9 coefficients per channel
inline constexpr int kChannelCount = 3;  // linear R, G, B

// Basis constants [1] eq. 3, full double precision.
inline constexpr double kY0 = 0.282094791773878143;   // k0 = 1/(2 sqrt(pi))
inline constexpr double kY1 = 0.488602511902919922;   // k1 = sqrt(3)/(2 sqrt(pi))
inline constexpr double kY2 = 1.09254843059207907;    // k2 = sqrt(15)/(2 sqrt(pi))
inline constexpr double kY20 = 0.315391565252520006;  // k3 = sqrt(5)/(4 sqrt(pi)), i = 6
inline constexpr double kY22 = 0.546274215296039535;  // k4 = sqrt(15)/(4 sqrt(pi)), i = 8

// k_i for each index, from the table above.
inline constexpr std::array<double, kShCount> kBasisScale = {kY0, kY1, kY1, kY1, kY2,
                                                             kY2, kY20, kY2, kY22};

// Band l of each index.
inline constexpr std::array<int, kShCount> kBand = {0, 1, 1, 1, 2, 2, 2, 2, 2};

// Index of (l, m), -l <= m <= l (google/spherical-harmonics GetIndex).
constexpr int sh_index(int l, int m) noexcept { return l * (l + 1) + m; }

// Zonal-harmonic factors of the clamped cosine max(0, cos) [1] eq. 8:
// A0 = pi, A1 = 2 pi / 3, A2 = pi / 4. Stored divided by pi, since Unity wants E/pi.
inline constexpr std::array<double, 3> kCosineLobeOverPi = {1.0, 2.0 / 3.0, 0.25};

// Unity-form factors C_i = (A_l / pi) * k_i [5] section 5: sh[c][i] = C_i * L_c,i.
inline constexpr double kC0 = 0.282094791773878143;    // k0
inline constexpr double kC1 = 0.325735007935279948;    // 2 k1 / 3
inline constexpr double kC2 = 0.273137107648019768;    // k2 / 4
inline constexpr double kC3 = 0.0788478913131300015;   // k3 / 4
inline constexpr double kC4 = 0.136568553824009884;    // k4 / 4
inline constexpr std::array<double, kShCount> kUnityScale = {kC0, kC1, kC1, kC1, kC2,
                                                             kC2, kC3, kC2, kC4};

// Coefficients of an RGB L2 function, channel-major like Unity's SphericalHarmonicsL2
// ([4]: sh[channel, coefficient], flat index 9*channel + coefficient), so packing is a copy.
// What the numbers mean depends on where they come from: radiance L_c,i = int L_c Y_i dw
// (projection, lights), or Unity form C_i L_c,i (convolution.h).
struct ShL2 {
  std::array<std::array<double, kShCount>, kChannelCount> c{};

  friend bool operator==(const ShL2&, const ShL2&) = default;
};

// The 9 basis polynomials P_i at (x, y, z), unscaled (no k_i): the form Unity's shader
// evaluates [3]. The direction need not be normalised; callers pass unit vectors.
constexpr std::array<double, kShCount> basis_polynomials(double x, double y, double z) noexcept {
  return {1.0, y, z, x, x * y, y * z, 3.0 * z * z - 1.0, x * z, x * x - y * y};
}

// Y_i(x, y, z) = k_i P_i for a unit direction: the orthonormal basis.
constexpr std::array<double, kShCount> eval_basis(double x, double y, double z) noexcept {
  std::array<double, kShCount> p = basis_polynomials(x, y, z);
  for (int i = 0; i < kShCount; ++i) p[i] *= kBasisScale[i];
  return p;
}

// sum_i sh.c[ch][i] * P_i(n): with Unity-form coefficients this is E_ch(n)/pi, exactly what
// SHEvalLinearL0L1 + SHEvalLinearL2 compute from the packed vectors [3], in double.
double eval_unity_form(const ShL2& unity_form, int channel, double x, double y, double z) noexcept;

}  // namespace shpack
