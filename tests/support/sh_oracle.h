// sh_oracle.h - the real SH basis by an independent, slow route (the test oracle).
//
// Associated Legendre functions by the standard three-term recurrence in spherical
// coordinates, after google/spherical-harmonics' EvalSHSlow, but WITHOUT the
// Condon-Shortley phase (-1)^m, which Unity's basis does not have
// (docs/conventions.md section 3):
//
//   Y_l^m = sqrt(2) K_l^m cos(m phi) P_l^m(cos theta)     m > 0
//   Y_l^0 = K_l^0 P_l^0(cos theta)
//   Y_l^m = sqrt(2) K_l^|m| sin(|m| phi) P_l^|m|(cos theta) m < 0
//   K_l^m = sqrt((2l + 1)/(4 pi) (l - m)!/(l + m)!)
//
// with theta the polar angle from +Z and phi = atan2(y, x), x, y, z being Unity's world
// axes. With this choice index l(l+1)+m reproduces Unity's table of polynomials
// (1, y, z, x, xy, yz, 3z^2-1, xz, x^2-y^2 times k_i) with the same signs; the tests in
// sh/basis_test.cpp check it against shpack's hard-coded polynomials.
#pragma once

#include <array>
#include <vector>

namespace shpack_test {

// P_l^m(x), 0 <= m <= l, |x| <= 1, without the Condon-Shortley phase.
double assoc_legendre(int l, int m, double x);

// Y_l^m(theta, phi) as above.
double sh_slow(int l, int m, double theta, double phi);

// The 9 L2 basis values Y_i at a unit direction (x, y, z) of Unity's frame, i = l(l+1)+m.
std::array<double, 9> unity_basis_slow(double x, double y, double z);

// All (lmax + 1)^2 values Y_{l(l+1)+m} at a unit direction.
std::vector<double> sh_slow_all(int lmax, double x, double y, double z);

// Zonal factor of the clamped cosine, A_l = 2 pi int_0^1 P_l(t) t dt (Ramamoorthi and
// Hanrahan 2001 eq. 8-9): pi, 2pi/3, then 0 for odd l and
// 2 pi (-1)^(l/2 - 1) / ((l + 2)(l - 1)) * l! / (2^l ((l/2)!)^2) for even l.
double cosine_lobe(int l);

// S = sqrt( sum_{l >= 3} (A_l / pi)^2 (2l + 1)/(4 pi) ), rounded up. For any radiance L
// whose bands l >= 3 carry energy R = int L^2 - sum_{l <= 2, m} L_lm^2 (Parseval),
// Cauchy-Schwarz and the addition theorem (sum_m Y_lm(n)^2 = (2l + 1)/(4 pi)) give, for
// every unit n,  |E(n)/pi - E_L2(n)/pi| <= S sqrt(R).
double truncation_kernel_norm();

}  // namespace shpack_test
