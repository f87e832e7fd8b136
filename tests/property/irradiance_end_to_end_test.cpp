// irradiance_end_to_end_test.cpp - the headline property: for band-limited
// lighting written to an EXR file and read back, Unity's shader evaluated on shpack's
// packed float vectors equals the brute-force E(n)/pi of that image, at 256 well-spread
// normals, within a tolerance derived from three separately checked parts:
//
//  (A) projection: shpack's radiance coefficients equal the oracle's Gauss-Legendre
//      texel-integral projection of the same image (1e-12 relative, derived below);
//  (B) packing: ShadeSH9 (float, transcribed from UnityCG.cginc) on the seven vectors
//      equals the double sum_i sh_i P_i(n) within float rounding (unity_shader.h);
//  (C) physics: the double L2 reconstruction sum_l (A_l/pi) sum_m L_lm Y_lm(n), with A_l and
//      Y from the oracle (not shpack's constants), equals the brute-force E(n)/pi of the
//      image within the L2 truncation bound S sqrt(R) (sh_oracle.h) plus the brute-force
//      quadrature bound (irradiance_oracle.h) plus (A)'s tolerance carried through.
//
// Why the truncation term is there at all: the image is the band-limited function averaged
// over each texel, and a piecewise-constant image is not band-limited. Its bands l >= 3
// carry the energy R = int L^2 - sum_{l<=2} L_lm^2 (computed exactly: int L^2 is a sum over
// texels, L_lm from the oracle), and that is what the L2 projection cannot represent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <random>

#include <unistd.h>

#include "shpack/convolution.h"
#include "shpack/project.h"
#include "shpack/unity_pack.h"
#include "support/band_limited.h"
#include "support/equirect_oracle.h"
#include "support/exr_file.h"
#include "support/irradiance_oracle.h"
#include "support/sh_oracle.h"
#include "support/sphere_points.h"
#include "support/test_util.h"
#include "support/unity_shader.h"

namespace shpack_test {
namespace {

using shpack::Dir3;
using shpack::ShL2;

// (A)'s tolerance for channel c, from project.h's numerics: every texel term
// v_t * (row weight) * (column factor) is within 16u of its value; each row is a plain
// double sum of W column terms (<= (W - 1) u of the sum of |terms|) and rows are combined
// with Neumaier's sum (2u). Each term of coefficient i is at most
// |v_t| int_t |Y_i| <= |v_t| Omega_t max|Y_i|, max|Y_i| = 2 k3 = 0.631 (index 6), so
//   |L_i - exact| <= (W + 32) u * 0.631 * sum_t |v_t| Omega_t.
// The oracle adds its rule's 1e-16 relative and ~4u of basis rounding per node on the same
// scale. So tol_c = (W + 40) u * 0.64 * int |L_c|, which is below 1e-12 of the coefficient
// norm for the images here (checked, so the tolerance cannot silently grow).
double projection_tol(std::uint32_t width, double abs_integral) {
  return (width + 40.0) * kU * 0.64 * abs_integral;
}

struct Worst {
  double value = 0;
  std::string where;
  void see(double v, const std::string& w) {
    if (v > value) value = v, where = w;
  }
};

TEST(IrradianceEndToEnd, BandLimitedLightingThroughAnExrFile) {
  const std::uint32_t W = 128, H = 64;
  const int kTrials = 3;
  const double S = truncation_kernel_norm();
  std::mt19937_64 rng(0x5eed);
  const std::vector<Dir3> normals = fibonacci_sphere(256);
  for (int trial = 0; trial < kTrials; ++trial) {
    SCOPED_TRACE("trial=" + std::to_string(trial));
    const BandLimitedRadiance f = random_band_limited(rng);
    const RgbImage rendered = render_texel_averages(W, H, f.function());

    // Written to a file and read back (lossless float EXR); everything below uses the
    // pixels as read.
    const auto path = std::filesystem::path(::testing::TempDir()) /
                      ("shpack_e2e_" + std::to_string(::getpid()) + "_" + std::to_string(trial) + ".exr");
    std::string error;
    ASSERT_TRUE(write_exr_rgb(path, rendered, error)) << error;
    RgbImage img;
    ASSERT_TRUE(read_exr_rgb(path, img, error)) << error;
    std::filesystem::remove(path);
    ASSERT_EQ(img.width, W);
    ASSERT_EQ(img.height, H);
    ASSERT_EQ(img.rgb, rendered.rgb) << "EXR round trip must be lossless";

    ShL2 radiance;
    const shpack::Status st = shpack::project_equirect(img.view(), {}, radiance);
    ASSERT_TRUE(st.ok()) << describe(st);

    // (A) projection.
    const ShL2 oracle = project_oracle(img);
    const std::array<double, 3> abs_int = abs_radiance_integral(img);
    std::array<double, 3> tol_a{};
    for (int c = 0; c < 3; ++c) {
      tol_a[c] = projection_tol(W, abs_int[c]);
      EXPECT_LE(tol_a[c], 1e-12 * channel_norm(oracle, c)) << "c=" << c;
      for (int i = 0; i < 9; ++i)
        EXPECT_NEAR(oracle.c[c][i], radiance.c[c][i], tol_a[c]) << "(A) c=" << c << " i=" << i;
      std::cout << "[ measure  ] trial " << trial << " c=" << c << ": (A) max|L - oracle|/|L| = "
                << channel_max_diff(radiance, oracle, c) / channel_norm(oracle, c) << "\n";
    }

    const ShL2 unity = shpack::radiance_to_unity_form(radiance);
    const shpack::UnityShaderVectors vectors = shpack::to_shader_vectors(unity);

    // Truncation energy R_c of the image's bands l >= 3; the subtraction of two values
    // ~|L|^2 adds <= 64u of the energy.
    const std::array<double, 3> energy = radiance_energy(img);
    std::array<double, 3> trunc_bound{};
    for (int c = 0; c < 3; ++c) {
      double low = 0;
      for (double v : oracle.c[c]) low += v * v;
      const double r = std::max(0.0, energy[c] - low) + 64 * kU * energy[c];
      trunc_bound[c] = S * std::sqrt(r);
    }

    const IrradianceOracle brute(img, 4);
    Worst b_ratio, c_ratio, e2e_ratio;
    double max_c_err = 0, max_quad = 0, min_e = 1e300, max_total_tol = 0;
    for (std::size_t k = 0; k < normals.size(); ++k) {
      const Dir3& n = normals[k];
      const IrradianceEstimate e = brute.eval(n);
      const std::array<float, 3> shader = unity_shade_sh9(vectors, n);
      const std::array<double, 9> y = unity_basis_slow(n.x, n.y, n.z);
      for (int c = 0; c < 3; ++c) {
        const std::string where = "k=" + std::to_string(k) + " c=" + std::to_string(c);
        // (B) packing and the shader's float arithmetic.
        const double recon_unity = reconstruct_unity_form(unity, c, n);
        const double tol_b = shade_sh9_rounding_bound(unity, c, n);
        EXPECT_NEAR(recon_unity, shader[c], tol_b) << "(B) " << where << " n=" << n;
        b_ratio.see(std::fabs(shader[c] - recon_unity) / tol_b, where);
        // shpack's convolution constants against the oracle's: both sums of 9 terms.
        const double recon = reconstruct_irradiance_over_pi(radiance, c, n);
        double abs_terms = 0, carried_a = 0;
        for (int i = 0; i < 9; ++i) {
          abs_terms += std::fabs(unity.c[c][i] * shpack::basis_polynomials(n.x, n.y, n.z)[i]);
          carried_a += cosine_lobe(shpack::kBand[i]) / std::numbers::pi * std::fabs(y[i]) * tol_a[c];
        }
        EXPECT_NEAR(recon, recon_unity, 64 * kU * abs_terms) << "convolution " << where;
        // (C) physics.
        const double tol_c = trunc_bound[c] + e.bound[c] + carried_a;
        EXPECT_NEAR(e.e_over_pi[c], recon, tol_c) << "(C) " << where << " n=" << n;
        c_ratio.see(std::fabs(recon - e.e_over_pi[c]) / tol_c, where);
        // End to end.
        const double tol = tol_b + 64 * kU * abs_terms + tol_c;
        EXPECT_NEAR(e.e_over_pi[c], shader[c], tol) << "end-to-end " << where << " n=" << n;
        e2e_ratio.see(std::fabs(shader[c] - e.e_over_pi[c]) / tol, where);
        max_c_err = std::max(max_c_err, std::fabs(recon - e.e_over_pi[c]));
        max_quad = std::max(max_quad, e.bound[c]);
        min_e = std::min(min_e, e.e_over_pi[c]);
        max_total_tol = std::max(max_total_tol, tol);
      }
    }
    // The test is only worth something if its tolerance is small against the signal: a
    // wrong constant, sign or slot moves E/pi by >= ~0.15 * 0.27 (the smallest weight
    // times the smallest C_i), so the tolerance must stay well below that.
    EXPECT_LT(max_total_tol, 0.01) << "tolerance too loose to catch a packing or sign error";
    std::cout << "[ measure  ] trial " << trial << ": truncation bound S sqrt(R) = " << trunc_bound[0] << ", "
              << trunc_bound[1] << ", " << trunc_bound[2] << "; max quadrature bound " << max_quad
              << "; max |recon - bruteforce| = " << max_c_err << "; min E/pi = " << min_e
              << "; max total tolerance " << max_total_tol << "\n"
              << "[ measure  ]   worst (B) error/bound " << b_ratio.value << " (" << b_ratio.where
              << "), (C) " << c_ratio.value << " (" << c_ratio.where << "), end-to-end " << e2e_ratio.value
              << " (" << e2e_ratio.where << ")\n";
  }
}

}  // namespace
}  // namespace shpack_test
