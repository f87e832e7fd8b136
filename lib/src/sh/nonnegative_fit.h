// nonnegative_fit.h (private) - the nearest non-negative L2 irradiance (window.h, Optimal).
//
// Problem. One channel in Unity form s (E/pi(n) = sum_i s_i P_i(n), sh_basis.h), projected
// t. Among the s whose E/pi is >= 0 in every unit direction n, find the one nearest to t in
// the RMS of E/pi over the sphere:
//
//   minimise  (1/4pi) int (sum_i (s_i - t_i) P_i(n))^2 dn  subject to  P(n) . s >= 0 for all n.
//
// Weights. P_i = Y_i / k_i and the Y_i are orthonormal (int Y_i Y_j dn = delta_ij), so
// (1/4pi) int P_i P_j dn = delta_ij / (4 pi k_i^2) = delta_ij (k0 / k_i)^2, k0^2 = 1/(4pi):
// the objective is sum_i w_i (s_i - t_i)^2 with w_i = (k0 / k_i)^2 = (1, 1/3 x3, 1/15, 1/15,
// 4/5, 1/15, 4/15) (e.g. the mean of (3z^2 - 1)^2 over the sphere is 9/5 - 2 + 1 = 4/5). In
// u_i = sqrt(w_i) s_i = (k0 / k_i) s_i it is the Euclidean distance ||u - u0||, and the
// constraint of direction n is b(n) . u >= 0 with b_i(n) = P_i(n) / sqrt(w_i).
//
// The feasible set is a closed convex cone (an intersection of half-spaces through 0, one
// per direction), so the answer is unique: the Euclidean projection of u0 onto it.
//
// Method: cutting planes with the exact minimum on the sphere (sh_minimum.h) as the
// separation oracle. Over the planes found so far, the projection onto the polyhedral cone
// {u : B u >= 0} is, by Moreau's decomposition (u0 = its projection onto the cone plus its
// projection onto the polar cone {-B^T lambda : lambda >= 0}), u = u0 + B^T lambda with
// lambda = argmin_{lambda >= 0} ||u0 + B^T lambda||: a non-negative least-squares problem
// with one column per plane, solved by Lawson and Hanson's active-set method [C. L. Lawson,
// R. J. Hanson, "Solving Least Squares Problems", 1974, ch. 23]. Then the argmin of the new
// E/pi is found; if E/pi there is below -kFitTolerance x RMS its plane is added and the NNLS
// re-solved from the previous multipliers (warm start). Why NNLS: its gradient on column k is
// -b_k . u = -(E/pi at n_k), so an active-set step brings in the most violated plane; only
// linearly independent columns (at most 9) are ever passive, so repeated or nearly repeated
// directions cost nothing; each step is a least-squares solve by Householder QR of at most
// 9 columns (the normal equations, whose condition is squared, are never formed); the
// residual falls monotonically, so it terminates; and every iterate has lambda >= 0, so
// the result is always a projection onto the cone of the planes found (stationarity holds
// by construction).
//
// Finish. The loop stops when the minimum is >= -kFitTolerance x the RMS of the input E/pi,
// or after kMaxFitPlanes planes. Then coefficient 0 is raised by the remaining
// deficit: a constant raises E/pi by the same amount everywhere, so the minimum becomes >= 0
// (checked again with minimum_on_sphere, raised by an ulp more until it is, rounding
// included; once on the scaled numbers, once more on the result). That costs at most the raise in RMS (the RMS of a constant c is |c|; triangle
// inequality); since the polyhedral cone contains the true feasible set, its projection is no
// farther from t than the true answer, so the result is within `raise` of the optimum in RMS.
//
// Scale. The problem is homogeneous (t -> a t gives s -> a s, a > 0), and every threshold is
// relative to the RMS of the input: it is solved for t scaled by a power of 2 into
// max |t_i| in [0.5, 1), exactly, so that a 1e-6 and a 1e6 map take the same steps (bit for
// bit when a is a power of 2, but for the last rounding correction), the scaled E/pi is
// exactly the result's up to the scale, and the result is non-negative even where
// sh_minimum.h's squares would over- or underflow (|t_i| beyond about 1e+-150).
#pragma once

#include <array>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"

namespace shpack {

// The cutting-plane loop's stop: minimum of E/pi >= -kFitTolerance x the RMS of the input
// E/pi. Far below float32's rounding of the packed coefficients (6e-8 relative).
inline constexpr double kFitTolerance = 1e-9;
// The iteration cap: the most planes the loop adds (each one oracle call and one NNLS).
inline constexpr int kMaxFitPlanes = 64;

struct NonnegativeFit {
  std::array<double, kShCount> unity_form{};  // the result: E/pi >= 0 everywhere
  int planes = 0;                             // planes the loop added (<= kMaxFitPlanes)
  double raise = 0;                           // added to coefficient 0 at the end
  // The certificate of the last QP, in the input's units: w_i (s_i - raise [i = 0] - t_i) =
  // sum_k multipliers[k] P_i(directions[k]), multipliers >= 0 (zero for planes that left
  // the active set), E/pi(directions[k]) = raise, to kFitTolerance x RMS, where a
  // multiplier is > 0.
  std::array<Dir3, kMaxFitPlanes> directions{};
  std::array<double, kMaxFitPlanes> multipliers{};
};

// Weight w_i = (k0 / k_i)^2 of coefficient i in the RMS of E/pi over the sphere (above).
constexpr double rms_weight(int i) noexcept { return kY0 / kBasisScale[i] * (kY0 / kBasisScale[i]); }

// The nearest non-negative E/pi to channel `channel` of `unity_form`. Preconditions, which
// window.cpp checks: finite coefficients and a negative minimum on the sphere (window.cpp
// also leaves a channel with coefficient 0 < 0 alone, window.h says why). Uses the stack
// only (about 8 KB).
NonnegativeFit nearest_nonnegative(const ShL2& unity_form, int channel) noexcept;

// The same problem in L1 (--l1: band 2 is 0 and stays 0), in closed form. E/pi = s0 + s . n,
// n = (x, y, z) in the order of s = (s3, s1, s2), has its minimum s0 - |s| (at n = -s/|s|),
// and the weights are (1, 1/3, 1/3, 1/3): minimise (s0 - t0)^2 + |s - t|^2 / 3 subject to
// s0 >= |s|. In u = (s0, s / sqrt 3) that is the Euclidean projection onto the cone
// u0 >= sqrt 3 |u'|; for t0 >= 0 > t0 - |t| (a ringing channel with a positive mean: the
// preconditions of nearest_nonnegative) it lies on the cone's boundary ray through t:
//   s0 = (3 t0 + |t|) / 4,  s = s0 t / |t|
// (the projection of (t0, |t|/sqrt 3) onto the direction (sqrt 3, 1) / 2), then s0 raised by
// ulps until minimum_on_sphere is >= 0. Planes 0, no certificate.
NonnegativeFit nearest_nonnegative_l1(const ShL2& unity_form, int channel) noexcept;

}  // namespace shpack
