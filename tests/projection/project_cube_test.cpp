// Tests of project_cube (lib/include/shpack/project_cube.h) and of the exact texel
// integrals behind it (lib/src/cube_moments.h).
//
// Oracle: tensor Gauss-Legendre quadrature (support/gauss_legendre.h) of Y_i(d) da db / r^3
// over a texel, composite over sub-squares of side <= 1/8, 12 points per side, summed in
// long double. On a sub-square of side h the integrand is analytic with its nearest complex
// singularity at distance >= 1 (where 1 + a^2 + b^2 = 0), so the error is below
// (h/2)^24 ~ 1e-29 of the integral: the oracle is exact to the rounding of its terms. The
// basis is sh_basis.h's polynomials, pinned against the slow Legendre oracle in
// basis_test.cpp; the slow oracle itself takes theta = acos(z), which loses ~u/theta near
// the poles (5e-13 at the +-Z face centres for N = 4096), too much to measure this code.
//
// Every one of the nine local moments (cube_moments.h) is pinned by the per-texel test:
// on face +Z (U = +x, V = -y, N = +z) the world integrals are I3 = m1, I1 = -m2, I2 = m3,
// I4 = -m4, I7 = m5, I5 = -m6, I8 = m7 - m8, I6 = -(m7 + m8); the other faces pin the
// face maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/project_cube.h"
#include "shpack/sh_basis.h"
#include "support/gauss_legendre.h"
#include "support/test_util.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;

// ---------------------------------------------------------------------------------------
// Oracle

using shpack_test::kEps;

Dir3 face_point(int face, double a, double b) {
  const CubeFaceAxes& f = kCubeFaceAxes[face];
  return {f.normal.x + a * f.u_axis.x + b * f.v_axis.x, f.normal.y + a * f.u_axis.y + b * f.v_axis.y,
          f.normal.z + a * f.u_axis.z + b * f.v_axis.z};
}

Dir3 normalized(Dir3 p) {
  const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  return {p.x / r, p.y / r, p.z / r};
}

// int over [a0,a1] x [b0,b1] of face `face` of g(d) Y_i(d) dw for i = 0..8, and of g(d) dw
// at index 9, where g is a callable of the direction.
template <class G>
std::array<long double, 10> quadrature(int face, double a0, double a1, double b0, double b1, G g) {
  const shpack_test::GaussRule q = shpack_test::gauss_legendre(12);
  const int sub = std::max(1, static_cast<int>(std::ceil((a1 - a0) * 8.0 - 1e-9)));
  std::array<long double, 10> sum{};
  const double ha = (a1 - a0) / sub, hb = (b1 - b0) / sub;
  for (int sa = 0; sa < sub; ++sa) {
    for (int sb = 0; sb < sub; ++sb) {
      const double ca = a0 + (sa + 0.5) * ha, cb = b0 + (sb + 0.5) * hb;
      for (std::size_t i = 0; i < q.nodes.size(); ++i) {
        for (std::size_t j = 0; j < q.nodes.size(); ++j) {
          const double a = ca + 0.5 * ha * q.nodes[i], b = cb + 0.5 * hb * q.nodes[j];
          const double r2 = 1.0 + a * a + b * b;
          const double weight = 0.25 * ha * hb * q.weights[i] * q.weights[j] / (r2 * std::sqrt(r2));
          const Dir3 d = normalized(face_point(face, a, b));
          const double gd = g(d);
          const std::array<double, kShCount> y = eval_basis(d.x, d.y, d.z);
          for (int k = 0; k < kShCount; ++k) sum[k] += static_cast<long double>(weight * gd) * y[k];
          sum[9] += static_cast<long double>(weight * gd);
        }
      }
    }
  }
  return sum;
}

double corner(std::uint32_t i, std::uint32_t n) { return (2.0 * i - static_cast<double>(n)) / n; }

// The oracle for texel (x, y): int Y_i dw (0..8) and the solid angle (9).
std::array<long double, 10> texel_oracle(std::uint32_t n, int face, std::uint32_t x, std::uint32_t y) {
  return quadrature(face, corner(x, n), corner(x + 1, n), corner(y, n), corner(y + 1, n),
                    [](const Dir3&) { return 1.0; });
}

// ---------------------------------------------------------------------------------------
// Cube images

struct Cube {
  std::uint32_t n;
  std::array<std::vector<float>, kCubeFaceCount> rgb;

  explicit Cube(std::uint32_t size) : n(size) {
    for (auto& f : rgb) f.assign(std::size_t{3} * n * n, 0.0f);
  }
  float* texel(int face, std::uint32_t x, std::uint32_t y) {
    return rgb[face].data() + 3 * (std::size_t{y} * n + x);
  }
  void set(int face, std::uint32_t x, std::uint32_t y, float r, float g, float b) {
    float* p = texel(face, x, y);
    p[0] = r;
    p[1] = g;
    p[2] = b;
  }
  void fill(float v) {
    for (auto& f : rgb) std::fill(f.begin(), f.end(), v);
  }
  std::array<ImageView, kCubeFaceCount> views() const {
    std::array<ImageView, kCubeFaceCount> v;
    for (int f = 0; f < kCubeFaceCount; ++f) v[f] = make_view(rgb[f].data(), n, n, 3);
    return v;
  }
};

ShL2 project(const Cube& cube, SamplingMethod method, ProjectStats* stats = nullptr, unsigned threads = 1) {
  ProjectOptions options;
  options.method = method;
  options.threads = threads;
  ShL2 sh;
  const Status st = project_cube(cube.views(), options, sh, stats);
  EXPECT_TRUE(st.ok()) << errc_name(st.code) << ": " << st.what << " face " << st.face;
  return sh;
}

Dir3 texel_centre(int face, std::uint32_t n, std::uint32_t x, std::uint32_t y) {
  return normalized(face_point(face, 2.0 * (x + 0.5) / n - 1.0, 2.0 * (y + 0.5) / n - 1.0));
}

double sh_value(const std::array<double, kShCount>& c, const Dir3& d) {
  const std::array<double, kShCount> y = eval_basis(d.x, d.y, d.z);
  double v = 0.0;
  for (int i = 0; i < kShCount; ++i) v += c[i] * y[i];
  return v;
}

// ---------------------------------------------------------------------------------------
// Solid angles and uniform cubes

TEST(ProjectCube, SolidAnglesSumTo4Pi) {
  // Each texel's solid angle is a difference of edge terms that telescopes along a column,
  // so the sum is 4 pi to the rounding of the last subtractions: a few u per texel,
  // random in sign; 1e-12 is a loose bound for up to 6 * 255^2 texels (summed in long double).
  for (std::uint32_t n : {1u, 2u, 3u, 16u, 255u}) {
    for (SamplingMethod method : {SamplingMethod::Exact, SamplingMethod::Center}) {
      long double sum = 0.0L;
      for (int f = 0; f < kCubeFaceCount; ++f) {
        for (std::uint32_t y = 0; y < n; ++y) {
          for (std::uint32_t x = 0; x < n; ++x) {
            std::array<double, kShCount> w{};
            ASSERT_TRUE(cube_texel_basis_integrals(n, static_cast<CubeFace>(f), x, y, method, w).ok());
            sum += w[0] / kY0;
          }
        }
      }
      EXPECT_NEAR(static_cast<double>(sum), 4.0 * kPi, 1e-12 * 4.0 * kPi)
          << "N=" << n << " method=" << static_cast<int>(method);
    }
  }
}

TEST(ProjectCube, UniformCubeIsPureL00) {
  // L = v everywhere: L00 = v * k0 * 4 pi = 2 sqrt(pi) v; the cube's symmetry group (the
  // octahedral group, which also maps texels to texels) has no invariant in bands 1 and 2,
  // so the others vanish up to rounding: tolerance 64 eps * L00 (a few roundings per face
  // sum, six faces).
  const float values[3] = {1.0f, 2.0f, 0.5f};
  for (std::uint32_t n : {1u, 2u, 3u, 16u, 255u}) {
    for (SamplingMethod method : {SamplingMethod::Exact, SamplingMethod::Center}) {
      Cube cube(n);
      for (int f = 0; f < kCubeFaceCount; ++f)
        for (std::uint32_t y = 0; y < n; ++y)
          for (std::uint32_t x = 0; x < n; ++x) cube.set(f, x, y, values[0], values[1], values[2]);
      const ShL2 sh = project(cube, method);
      for (int c = 0; c < kChannelCount; ++c) {
        const double l00 = 2.0 * std::sqrt(kPi) * values[c];
        EXPECT_NEAR(sh.c[c][0], l00, 64 * kEps * l00) << "N=" << n << " c=" << c;
        for (int i = 1; i < kShCount; ++i)
          EXPECT_NEAR(sh.c[c][i], 0.0, 64 * kEps * l00) << "N=" << n << " c=" << c << " i=" << i;
      }
    }
  }
}

TEST(ProjectCube, OneByOneFacesHaveClosedForms) {
  // Six uniform faces with values v_f. From the antiderivatives at the face corners
  // (cube_moments.h; every F_k is odd in a and in b, so a whole face is 4 F_k(1, 1)):
  //   solid angle of a face      4 atan(1/sqrt3)              = 2 pi / 3
  //   int d_n over a face        4 atan(1/sqrt2) / sqrt2      = Phi
  //   int (d_a^2 - d_n^2)        4 F_7(1, 1) = -(4/(3 sqrt3)) (2/2 + 1/2) = -2/sqrt3
  // so on the +-Z faces int (3z^2 - 1) = -(m7 + m8) = 4/sqrt3, on the four others -2/sqrt3;
  // int (x^2 - y^2) is 2/sqrt3 on +-X, -2/sqrt3 on +-Y, 0 on +-Z; products are odd: 0.
  const double phi = 4.0 * std::atan(1.0 / std::sqrt(2.0)) / std::sqrt(2.0);
  const double q = 2.0 / std::sqrt(3.0);
  const float v[6] = {1.0f, 2.0f, 3.0f, 5.0f, 7.0f, 11.0f};  // +X -X +Y -Y +Z -Z
  Cube cube(1);
  for (int f = 0; f < kCubeFaceCount; ++f) cube.set(f, 0, 0, v[f], 2.0f * v[f], 0.0f);
  const ShL2 sh = project(cube, SamplingMethod::Exact);
  std::array<double, kShCount> want{};
  want[0] = kY0 * (2.0 * kPi / 3.0) * (v[0] + v[1] + v[2] + v[3] + v[4] + v[5]);
  want[1] = kY1 * phi * (v[2] - v[3]);
  want[2] = kY1 * phi * (v[4] - v[5]);
  want[3] = kY1 * phi * (v[0] - v[1]);
  want[6] = kY20 * (2.0 * q * (v[4] + v[5]) - q * (v[0] + v[1] + v[2] + v[3]));
  want[8] = kY22 * q * ((v[0] + v[1]) - (v[2] + v[3]));
  for (int i = 0; i < kShCount; ++i) {
    // A few roundings of terms of size <= 30: 32 eps * 30.
    EXPECT_NEAR(sh.c[0][i], want[i], 32 * kEps * 30) << "i=" << i;
    EXPECT_NEAR(sh.c[1][i], 2.0 * want[i], 64 * kEps * 30) << "i=" << i;
    EXPECT_EQ(sh.c[2][i], 0.0) << "i=" << i;
  }
}

// ---------------------------------------------------------------------------------------
// The face table, pinned by bright texels

// Face normals and the direction of the top-left corner (x = 0, y = 0: a = b = -1) of each
// face, worked out by hand from the table in docs/conventions.md: N_f - U_f - V_f.
constexpr Dir3 kNormal[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
constexpr Dir3 kTopLeft[6] = {{1, 1, 1}, {-1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {-1, 1, 1}, {1, 1, -1}};

Dir3 l1_vector(const ShL2& sh, int c = 0) { return {sh.c[c][3], sh.c[c][1], sh.c[c][2]}; }

TEST(ProjectCube, CentreTexelLightsTheFaceNormal) {
  // N = 3: texel (1, 1) is centred on the normal and symmetric about it, so the L1 vector
  // (x, y, z) = (L3, L1, L2) points exactly along N_f: off-axis components are rounding
  // (8 eps of the on-axis one).
  for (SamplingMethod method : {SamplingMethod::Exact, SamplingMethod::Center}) {
    for (int f = 0; f < kCubeFaceCount; ++f) {
      Cube cube(3);
      cube.set(f, 1, 1, 1.0f, 1.0f, 1.0f);
      const Dir3 l1 = l1_vector(project(cube, method));
      const double along = l1.x * kNormal[f].x + l1.y * kNormal[f].y + l1.z * kNormal[f].z;
      EXPECT_GT(along, 0.0) << "face " << f << " l1 " << l1;
      const Dir3 off = {l1.x - along * kNormal[f].x, l1.y - along * kNormal[f].y, l1.z - along * kNormal[f].z};
      EXPECT_LE(std::fabs(off.x) + std::fabs(off.y) + std::fabs(off.z), 8 * kEps * along)
          << "face " << f << " l1 " << l1;
    }
  }
}

TEST(ProjectCube, TopLeftTexelLightsTheTopLeftCorner) {
  // N = 16: texel (0, 0) is the 1/16-wide square at the corner a = b = -1; its L1 vector
  // points at its own centroid direction, within 1/16 rad of the corner direction (the
  // texel's angular size): cos >= cos(1/16) > 0.998. Each sign of (L3, L1, L2) must be the
  // sign of the hand-computed corner direction.
  for (int f = 0; f < kCubeFaceCount; ++f) {
    Cube cube(16);
    cube.set(f, 0, 0, 1.0f, 0.0f, 0.0f);
    const Dir3 l1 = l1_vector(project(cube, SamplingMethod::Exact));
    const Dir3 want = normalized(kTopLeft[f]);
    EXPECT_EQ(std::signbit(l1.x), std::signbit(want.x)) << "face " << f << " l1 " << l1 << " want " << want;
    EXPECT_EQ(std::signbit(l1.y), std::signbit(want.y)) << "face " << f << " l1 " << l1 << " want " << want;
    EXPECT_EQ(std::signbit(l1.z), std::signbit(want.z)) << "face " << f << " l1 " << l1 << " want " << want;
    const Dir3 got = normalized(l1);
    EXPECT_GT(got.x * want.x + got.y * want.y + got.z * want.z, 0.998) << "face " << f << " l1 " << l1;
  }
}

// ---------------------------------------------------------------------------------------
// Exactness: every texel integral against the oracle

TEST(ProjectCube, ExactTexelIntegralsMatchQuadrature) {
  // Error model (cube_moments.h): a texel's moments are D(b1) - D(b0) of edge terms that are
  // accurate to a few u of their size O(h |f|), so the error is c u / h of the texel's solid
  // angle, h = 2/N, u = eps/2, with c = |D| / (h |dD| / h) * (a few): c ~ 3-4 where the
  // integrand is small next to its row antiderivative (band 2 near b = +-1). Measured maxima
  // (x86-64, g++ 12, glibc 2.36), in units of k_i * Omega_texel, and in units of u/h:
  //   N = 1: 5.4e-16 (9.8)   N = 3: 1.5e-15 (9.2)   N = 16: 7.2e-15 (8.1)
  //   N = 1024: 4.1e-13 (7.3)   N = 4096: 1.6e-12 (7.2)
  // Bound: 32 u/h + 4 eps, over 3x the worst measured. (Differencing corner values instead
  // gives ~4 u |F| / (h^2 |f|): 3.8e-10 at N = 1024 and 1.2e-9 at N = 4096, measured.)
  std::mt19937_64 rng(0x5eed);
  for (std::uint32_t n : {1u, 2u, 3u, 16u, 1024u, 4096u}) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> texels;
    if (n <= 16) {
      for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t x = 0; x < n; ++x) texels.emplace_back(x, y);
    } else {
      const std::uint32_t m = n - 1, h = n / 2;
      for (std::uint32_t x : {0u, 1u, h - 1, h, m - 1, m})
        for (std::uint32_t y : {0u, 1u, h - 1, h, m - 1, m}) texels.emplace_back(x, y);
      std::uniform_int_distribution<std::uint32_t> any(0, m);
      for (int k = 0; k < 24; ++k) texels.emplace_back(any(rng), any(rng));
    }
    const double tolerance = 16.0 * kEps * (n / 2.0) + 4.0 * kEps;  // 32 u/h + 4 eps
    double worst = 0.0;
    for (int f = 0; f < kCubeFaceCount; ++f) {
      for (auto [x, y] : texels) {
        std::array<double, kShCount> got{};
        ASSERT_TRUE(cube_texel_basis_integrals(n, static_cast<CubeFace>(f), x, y, SamplingMethod::Exact, got).ok());
        const std::array<long double, 10> want = texel_oracle(n, f, x, y);
        const double omega = static_cast<double>(want[9]);
        for (int i = 0; i < kShCount; ++i) {
          const double err = std::fabs(got[i] - static_cast<double>(want[i])) / (kBasisScale[i] * omega);
          worst = std::max(worst, err);
          EXPECT_LE(err, tolerance) << "N=" << n << " face=" << f << " x=" << x << " y=" << y << " i=" << i
                                << " got=" << got[i] << " want=" << static_cast<double>(want[i]);
        }
      }
    }
    std::printf("[ measured ] N=%u: max |exact - quadrature| / (k_i Omega) = %.2e\n", n, worst);
  }
}

TEST(ProjectCube, SingleBrightTexelProjectsToItsIntegral) {
  // One texel of radiance 1 and the rest 0: the projection adds only zeros and exact
  // products by 1 to that texel's weights, so it equals cube_texel_basis_integrals bit for
  // bit; and at 1e6 it equals 1e6 times the oracle to 1e-12 (as above).
  for (std::uint32_t n : {1u, 5u, 16u}) {
    for (int f = 0; f < kCubeFaceCount; ++f) {
      for (auto [x, y] : {std::pair<std::uint32_t, std::uint32_t>{0, 0}, {n - 1, 0}, {n / 2, n / 3}, {n - 1, n - 1}}) {
        for (SamplingMethod method : {SamplingMethod::Exact, SamplingMethod::Center}) {
          Cube cube(n);
          cube.set(f, x, y, 1.0f, 1.0f, 1.0f);
          const ShL2 sh = project(cube, method);
          std::array<double, kShCount> w{};
          ASSERT_TRUE(cube_texel_basis_integrals(n, static_cast<CubeFace>(f), x, y, method, w).ok());
          for (int i = 0; i < kShCount; ++i)
            EXPECT_EQ(sh.c[1][i], w[i]) << "N=" << n << " face=" << f << " x=" << x << " y=" << y << " i=" << i;
        }
        Cube bright(n);
        bright.set(f, x, y, 1e6f, 0.0f, 0.0f);
        const ShL2 sh = project(bright, SamplingMethod::Exact);
        const std::array<long double, 10> want = texel_oracle(n, f, x, y);
        for (int i = 0; i < kShCount; ++i) {
          EXPECT_NEAR(sh.c[0][i], 1e6 * static_cast<double>(want[i]), 1e-12 * 1e6 * kBasisScale[i] * static_cast<double>(want[9]))
              << "N=" << n << " face=" << f << " x=" << x << " y=" << y << " i=" << i;
        }
      }
    }
  }
}

TEST(ProjectCube, SunInACornerTexelOverADimSky) {
  // A 1e6 texel in the corner texel (0, 0) of +X (the cube corner (1, 1, 1)) over a sky of
  // 0.25. Expected: 0.25 * (2 sqrt(pi), 0, ...) + (1e6 - 0.25) * oracle(texel). The sky's
  // share of L00 is 0.886 next to the sun's ~45; with compensated sums the total is good to
  // a few u of the largest term, so 1e-13 relative to the sun term (4.5e-12) still sees a
  // sky texel's share (0.25 * Omega * k0 ~ 2e-4) many times over. Float accumulation would
  // err by u_float * 1e6 ~ 0.06 per texel.
  const std::uint32_t n = 32;
  for (unsigned threads : {1u, 2u}) {
    Cube cube(n);
    cube.fill(0.25f);
    cube.set(0, 0, 0, 1e6f, 1e6f, 1e6f);
    const ShL2 sh = project(cube, SamplingMethod::Exact, nullptr, threads);
    const std::array<long double, 10> sun = texel_oracle(n, 0, 0, 0);
    for (int i = 0; i < kShCount; ++i) {
      const double sky = i == 0 ? 0.25 * 2.0 * std::sqrt(kPi) : 0.0;
      const double want = sky + (1e6 - 0.25) * static_cast<double>(sun[i]);
      const double scale = 1e6 * kBasisScale[i] * static_cast<double>(sun[9]);
      EXPECT_NEAR(sh.c[0][i], want, 1e-13 * scale) << "i=" << i << " threads=" << threads;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Convergence on smooth input

// A random L2 function: L(d) = sum_i c_i Y_i(d).
std::array<double, kShCount> random_l2(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<double, kShCount> c{};
  for (double& v : c) v = u(rng);
  c[0] = 4.0;
  return c;
}

double max_error(const ShL2& sh, const std::array<double, kShCount>& want) {
  double e = 0.0;
  for (int i = 0; i < kShCount; ++i) e = std::max(e, std::fabs(sh.c[0][i] - want[i]));
  return e;
}

TEST(ProjectCube, CenterConvergesAsHSquared) {
  // Band-limited L sampled at texel centres. The centre rule with exact weights errs by
  // O(h^2) per texel (midpoint rule), so halving h divides the error by 4 (+ O(h^2)): the
  // ratio must be in [3.5, 4.5] (measured 4.007, 4.002). Float texels add ~6e-8 |L| random
  // error, far below the 6e-5 error at N = 64.
  std::mt19937_64 rng(0x5eed);
  const std::array<double, kShCount> c = random_l2(rng);
  std::vector<double> errors;
  for (std::uint32_t n : {16u, 32u, 64u}) {
    Cube cube(n);
    for (int f = 0; f < kCubeFaceCount; ++f)
      for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t x = 0; x < n; ++x) {
          const float v = static_cast<float>(sh_value(c, texel_centre(f, n, x, y)));
          cube.set(f, x, y, v, v, v);
        }
    errors.push_back(max_error(project(cube, SamplingMethod::Center), c));
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double ratio = errors[k - 1] / errors[k];
    EXPECT_GE(ratio, 3.5) << "errors " << errors[k - 1] << " -> " << errors[k];
    EXPECT_LE(ratio, 4.5) << "errors " << errors[k - 1] << " -> " << errors[k];
  }
}

TEST(ProjectCube, ExactIsTheProjectionOfThePiecewiseConstantCube) {
  // Texel values = texel averages of a band-limited L (from the oracle). Exact must equal
  // the oracle's projection of that piecewise-constant cube, sum_t v_t int_t Y_i, to the
  // per-texel accuracy above (1e-12 of sum_t |v_t| k_i Omega_t); and, as a projection of a
  // piecewise-constant approximation, converge to c at O(h^2): ratio in [3.5, 4.5]
  // (measured 3.951, 3.988).
  std::mt19937_64 rng(0x5eed + 1);
  const std::array<double, kShCount> c = random_l2(rng);
  std::vector<double> errors;
  for (std::uint32_t n : {8u, 16u, 32u}) {
    Cube cube(n);
    std::array<long double, kShCount> want{};
    long double scale = 0.0L;
    for (int f = 0; f < kCubeFaceCount; ++f) {
      for (std::uint32_t y = 0; y < n; ++y) {
        for (std::uint32_t x = 0; x < n; ++x) {
          const std::array<long double, 10> w = texel_oracle(n, f, x, y);
          long double integral = 0.0L;
          for (int i = 0; i < kShCount; ++i) integral += c[i] * w[i];
          const float v = static_cast<float>(integral / w[9]);
          cube.set(f, x, y, v, v, v);
          for (int i = 0; i < kShCount; ++i) want[i] += v * w[i];
          scale += std::fabs(v) * w[9];
        }
      }
    }
    const ShL2 sh = project(cube, SamplingMethod::Exact);
    for (int i = 0; i < kShCount; ++i)
      EXPECT_NEAR(sh.c[0][i], static_cast<double>(want[i]), 1e-12 * kBasisScale[i] * static_cast<double>(scale))
          << "N=" << n << " i=" << i;
    errors.push_back(max_error(sh, c));
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double ratio = errors[k - 1] / errors[k];
    EXPECT_GE(ratio, 3.5) << "errors " << errors[k - 1] << " -> " << errors[k];
    EXPECT_LE(ratio, 4.5) << "errors " << errors[k - 1] << " -> " << errors[k];
  }
}

TEST(ProjectCube, AgreesWithEquirectOnASmoothFunction) {
  // L(d) = exp(kappa d.w0) is smooth but not band-limited; Funk-Hecke gives its exact
  // coefficients 4 pi i_l(kappa) Y_i(w0) with the modified spherical Bessel functions
  //   i0 = sinh k / k,  i1 = cosh k / k - sinh k / k^2,  i2 = (3/k^2 + 1) sinh k / k - 3 cosh k / k^2.
  // A cube (N x N faces) and an equirect (4N x 2N: texels of similar size) sampled at texel
  // centres and projected with SamplingMethod::Exact both err by O(h^2), h = 2/N; their leading
  // terms differ, so their difference is O(h^2) too. When N doubles each error and the
  // difference must fall by 4 (ratio in [3.5, 4.5]; measured 3.999 to 4.008), and at N = 64
  // they agree to h^2 L00 (h^2 = 9.8e-4; measured difference 2.7e-5 L00).
  const double kappa = 2.0;
  const Dir3 w0 = normalized({1.0, 2.0, -0.5});
  const double sk = std::sinh(kappa), ck = std::cosh(kappa);
  const double il[3] = {sk / kappa, ck / kappa - sk / (kappa * kappa),
                        (3.0 / (kappa * kappa) + 1.0) * sk / kappa - 3.0 * ck / (kappa * kappa)};
  std::array<double, kShCount> exact{};
  const std::array<double, kShCount> y0 = eval_basis(w0.x, w0.y, w0.z);
  for (int i = 0; i < kShCount; ++i) exact[i] = 4.0 * kPi * il[kBand[i]] * y0[i];
  auto L = [&](const Dir3& d) { return std::exp(kappa * (d.x * w0.x + d.y * w0.y + d.z * w0.z)); };

  std::vector<double> cube_err, eq_err, diff;
  for (std::uint32_t n : {16u, 32u, 64u}) {
    Cube cube(n);
    for (int f = 0; f < kCubeFaceCount; ++f)
      for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t x = 0; x < n; ++x) {
          const float v = static_cast<float>(L(texel_centre(f, n, x, y)));
          cube.set(f, x, y, v, v, v);
        }
    const ShL2 cube_sh = project(cube, SamplingMethod::Exact);

    const std::uint32_t w = 4 * n, h = 2 * n;
    std::vector<float> eq(std::size_t{3} * w * h);
    for (std::uint32_t j = 0; j < h; ++j)
      for (std::uint32_t i = 0; i < w; ++i) {
        const float v = static_cast<float>(L(equirect_direction((i + 0.5) / w, (j + 0.5) / h)));
        for (int c = 0; c < 3; ++c) eq[3 * (std::size_t{j} * w + i) + c] = v;
      }
    ShL2 eq_sh;
    ASSERT_TRUE(project_equirect(make_view(eq.data(), w, h, 3), ProjectOptions{}, eq_sh).ok());
    cube_err.push_back(max_error(cube_sh, exact));
    eq_err.push_back(max_error(eq_sh, exact));
    double d = 0.0;
    for (int i = 0; i < kShCount; ++i) d = std::max(d, std::fabs(cube_sh.c[0][i] - eq_sh.c[0][i]));
    diff.push_back(d);
  }
  for (std::size_t k = 1; k < diff.size(); ++k) {
    for (const auto* e : {&cube_err, &eq_err, &diff}) {
      const double ratio = (*e)[k - 1] / (*e)[k];
      const char* what = e == &cube_err ? "cube" : e == &eq_err ? "equirect" : "cube - equirect";
      EXPECT_GE(ratio, 3.5) << what << ": " << (*e)[k - 1] << " -> " << (*e)[k];
      EXPECT_LE(ratio, 4.5) << what << ": " << (*e)[k - 1] << " -> " << (*e)[k];
    }
  }
  const double h = 2.0 / 64;
  EXPECT_LE(diff.back(), h * h * exact[0]) << "cube vs equirect at N = 64";
}

// ---------------------------------------------------------------------------------------
// Views, pixel formats, threads

Cube random_cube(std::uint32_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 4.0f);
  Cube cube(n);
  for (auto& f : cube.rgb)
    for (float& v : f) v = u(rng);
  return cube;
}

TEST(ProjectCube, BitIdenticalForAnyThreadCount) {
  // N = 200: four tiles of 64 rows, the last one partial. Tiles are reduced in a fixed
  // order whatever runs them.
  const Cube cube = random_cube(200, 0x5eed);
  for (SamplingMethod method : {SamplingMethod::Exact, SamplingMethod::Center}) {
    const ShL2 one = project(cube, method, nullptr, 1);
    for (unsigned threads : {2u, 3u, 0u}) EXPECT_EQ(one, project(cube, method, nullptr, threads)) << threads;
  }
}

TEST(ProjectCube, CrossesAndStripsAreViewsWithoutCopies) {
  // Faces placed in a horizontal cross, a vertical cross (-Z stored rotated by 180 degrees,
  // read back through negative strides) and a horizontal strip; unused cross cells hold
  // NaN, which must never be read. Each must project bit-identically to the loose faces.
  const std::uint32_t n = 7;
  const Cube cube = random_cube(n, 42);
  const ShL2 want = project(cube, SamplingMethod::Exact);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto place = [&](std::vector<float>& img, std::uint32_t width, int f, std::uint32_t col, std::uint32_t row, bool rot180) {
    for (std::uint32_t y = 0; y < n; ++y)
      for (std::uint32_t x = 0; x < n; ++x) {
        const std::uint32_t sx = rot180 ? n - 1 - x : x, sy = rot180 ? n - 1 - y : y;
        for (int c = 0; c < 3; ++c)
          img[3 * ((std::size_t{row} * n + y) * width + col * n + x) + c] = cube.rgb[f][3 * (std::size_t{sy} * n + sx) + c];
      }
  };
  auto cell_view = [&](const std::vector<float>& img, std::uint32_t width, std::uint32_t col, std::uint32_t row, bool rot180) {
    const std::int64_t pixel = 3 * sizeof(float), row_bytes = pixel * width;
    ImageView v = make_view(img.data(), n, n, 3);
    v.pixel_stride = pixel;
    v.row_stride = row_bytes;
    v.data = reinterpret_cast<const std::byte*>(img.data()) + (std::size_t{row} * n * width + col * n) * pixel;
    if (rot180) {  // start at the cell's last pixel and walk backwards
      v.data += (n - 1) * row_bytes + (n - 1) * pixel;
      v.pixel_stride = -pixel;
      v.row_stride = -row_bytes;
    }
    return v;
  };
  struct Cell {
    std::uint32_t col, row;
    bool rot180;
  };
  struct Layout {
    const char* name;
    std::uint32_t cols, rows;
    std::array<Cell, 6> cells;  // +X -X +Y -Y +Z -Z
  };
  const Layout layouts[] = {
      {"hcross", 4, 3, {{{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {3, 1, false}}}},
      {"vcross", 3, 4, {{{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {1, 3, true}}}},
      {"hstrip", 6, 1, {{{0, 0, false}, {1, 0, false}, {2, 0, false}, {3, 0, false}, {4, 0, false}, {5, 0, false}}}},
  };
  for (const Layout& l : layouts) {
    const std::uint32_t width = l.cols * n;
    std::vector<float> img(std::size_t{3} * width * l.rows * n, nan);
    std::array<ImageView, 6> views;
    for (int f = 0; f < 6; ++f) {
      place(img, width, f, l.cells[f].col, l.cells[f].row, l.cells[f].rot180);
      views[f] = cell_view(img, width, l.cells[f].col, l.cells[f].row, l.cells[f].rot180);
    }
    ShL2 got;
    const Status st = project_cube(views, ProjectOptions{}, got);
    ASSERT_TRUE(st.ok()) << l.name << ": " << st.what << " face " << st.face;
    EXPECT_EQ(got, want) << l.name;
  }
}

TEST(ProjectCube, HalfGreyAndRgbaFacesReadTheSameValues) {
  // Values k/8 in [0, 4) are exact in binary16 and binary32: the F16 cube, a grey cube
  // (1 channel, fed to R, G, B) and an RGBA cube (alpha ignored) project identically.
  const std::uint32_t n = 5;
  Cube rgb(n);
  std::vector<std::vector<std::uint16_t>> half(6);
  std::vector<std::vector<float>> grey(6), rgba(6);
  for (int f = 0; f < 6; ++f) {
    for (std::uint32_t t = 0; t < n * n; ++t) {
      const float v = static_cast<float>((f * 37 + t * 11) % 32) / 8.0f;
      rgb.set(f, t % n, t / n, v, v, v);
      grey[f].push_back(v);
      for (float c : {v, v, v, -7.0f}) rgba[f].push_back(c);
      // binary16 of k/8, 0 <= k < 32: exponent and mantissa by hand.
      const auto k = static_cast<std::uint32_t>(v * 8.0f);
      std::uint16_t h = 0;
      if (k != 0) {
        int e = 0;
        while ((k >> (e + 1)) != 0) ++e;  // k = 2^e * (1 + m/2^e)
        const std::uint32_t mant = (k - (1u << e)) << (10 - e);
        h = static_cast<std::uint16_t>(((e - 3 + 15) << 10) | mant);
      }
      for (int c = 0; c < 3; ++c) half[f].push_back(h);
    }
  }
  const ShL2 want = project(rgb, SamplingMethod::Exact);
  std::array<ImageView, 6> hv, gv, av;
  for (int f = 0; f < 6; ++f) {
    hv[f] = {reinterpret_cast<const std::byte*>(half[f].data()), PixelType::F16, n, n, 3, kAutoStride, kAutoStride};
    gv[f] = make_view(grey[f].data(), n, n, 1);
    av[f] = make_view(rgba[f].data(), n, n, 4);
  }
  for (const auto* views : {&hv, &gv, &av}) {
    ShL2 got;
    ProjectStats stats;
    ASSERT_TRUE(project_cube(*views, ProjectOptions{}, got, &stats).ok());
    EXPECT_EQ(got, want) << (views == &hv ? "f16" : views == &gv ? "grey" : "rgba");
    EXPECT_EQ(stats.negative_texels, 0u) << "alpha must be ignored";
  }
}

// ---------------------------------------------------------------------------------------
// Value policies and errors

TEST(ProjectCube, NonFiniteTexels) {
  const std::uint32_t n = 6;
  // NonFinite::Zero replaces the non-finite channel (only) by 0: `zeroed` is that cube.
  Cube bad = random_cube(n, 7);
  Cube zeroed = bad;
  bad.texel(3, 2, 1)[1] = std::numeric_limits<float>::quiet_NaN();
  bad.texel(5, 0, 4)[0] = std::numeric_limits<float>::infinity();
  bad.texel(3, 4, 5)[2] = -std::numeric_limits<float>::infinity();
  zeroed.texel(3, 2, 1)[1] = 0.0f;
  zeroed.texel(5, 0, 4)[0] = 0.0f;
  zeroed.texel(3, 4, 5)[2] = 0.0f;

  ShL2 sh;
  sh.c[0][0] = 123.0;
  ProjectStats stats;
  stats.max_value = -1.0;
  const Status st = project_cube(bad.views(), ProjectOptions{}, sh, &stats);
  EXPECT_EQ(st.code, Errc::NonFiniteTexel);
  EXPECT_EQ(st.face, 3u);  // the first in face, then row-major order
  EXPECT_EQ(st.x, 2u);
  EXPECT_EQ(st.y, 1u);
  EXPECT_EQ(sh.c[0][0], 123.0) << "radiance must be untouched on error";
  EXPECT_EQ(stats.max_value, -1.0) << "stats must be untouched on error";

  ProjectOptions zero;
  zero.nonfinite = NonFinite::Zero;
  ASSERT_TRUE(project_cube(bad.views(), zero, sh, &stats).ok());
  EXPECT_EQ(sh, project(zeroed, SamplingMethod::Exact));
  EXPECT_EQ(stats.nonfinite_texels, 3u);
  EXPECT_EQ(stats.first_nonfinite_x, 2u);
  EXPECT_EQ(stats.first_nonfinite_y, 1u);
}

TEST(ProjectCube, NegativeTexels) {
  const std::uint32_t n = 4;
  Cube cube = random_cube(n, 9);
  cube.texel(1, 3, 0)[0] = -2.0f;
  cube.texel(4, 1, 2)[2] = -0.5f;
  Cube clamped = cube;
  clamped.texel(1, 3, 0)[0] = 0.0f;
  clamped.texel(4, 1, 2)[2] = 0.0f;
  ProjectStats stats;
  const ShL2 kept = project(cube, SamplingMethod::Exact, &stats);
  EXPECT_EQ(stats.negative_texels, 2u);
  EXPECT_NE(kept, project(clamped, SamplingMethod::Exact));
  ProjectOptions clamp;
  clamp.negative = Negative::Clamp;
  ShL2 got;
  ASSERT_TRUE(project_cube(cube.views(), clamp, got, &stats).ok());
  EXPECT_EQ(got, project(clamped, SamplingMethod::Exact));
  EXPECT_EQ(stats.negative_texels, 2u);
}

TEST(ProjectCube, RejectsBadFaces) {
  Cube cube(4);
  ShL2 sh;
  auto views = cube.views();
  views[2].data = nullptr;
  Status st = project_cube(views, ProjectOptions{}, sh);
  EXPECT_EQ(st.code, Errc::BadView);
  EXPECT_EQ(st.face, 2u);

  views = cube.views();
  views[4].height = 3;  // not square
  st = project_cube(views, ProjectOptions{}, sh);
  EXPECT_EQ(st.code, Errc::BadView);
  EXPECT_EQ(st.face, 4u);

  const Cube small(3);
  views = cube.views();
  views[5] = small.views()[5];  // square, other size
  st = project_cube(views, ProjectOptions{}, sh);
  EXPECT_EQ(st.code, Errc::BadView);
  EXPECT_EQ(st.face, 5u);

  ProjectOptions options;
  options.method = static_cast<SamplingMethod>(7);
  EXPECT_EQ(project_cube(cube.views(), options, sh).code, Errc::InvalidArgument);

  std::array<double, kShCount> w{};
  EXPECT_EQ(cube_texel_basis_integrals(0, CubeFace::PosX, 0, 0, SamplingMethod::Exact, w).code, Errc::InvalidArgument);
  EXPECT_EQ(cube_texel_basis_integrals(4, CubeFace::PosX, 4, 0, SamplingMethod::Exact, w).code, Errc::InvalidArgument);
  EXPECT_EQ(cube_texel_basis_integrals(4, static_cast<CubeFace>(6), 0, 0, SamplingMethod::Exact, w).code, Errc::InvalidArgument);
}

TEST(ProjectCube, CenterUsesTheExactSolidAngle) {
  // Both methods give a texel the same solid angle (bit for bit), and Center's other
  // weights are Y_i(centre) times it.
  for (std::uint32_t n : {1u, 3u, 64u}) {
    for (int f = 0; f < kCubeFaceCount; ++f) {
      std::array<double, kShCount> exact{}, center{};
      ASSERT_TRUE(cube_texel_basis_integrals(n, static_cast<CubeFace>(f), n / 3, n - 1, SamplingMethod::Exact, exact).ok());
      ASSERT_TRUE(cube_texel_basis_integrals(n, static_cast<CubeFace>(f), n / 3, n - 1, SamplingMethod::Center, center).ok());
      EXPECT_EQ(exact[0], center[0]) << "N=" << n << " face=" << f;
      const double omega = center[0] / kY0;
      const Dir3 d = texel_centre(f, n, n / 3, n - 1);
      const std::array<double, kShCount> y = eval_basis(d.x, d.y, d.z);
      for (int i = 0; i < kShCount; ++i)
        EXPECT_NEAR(center[i], y[i] * omega, 8 * kEps * kBasisScale[i] * 2.0 * omega) << "N=" << n << " face=" << f << " i=" << i;
    }
  }
}

}  // namespace
}  // namespace shpack
