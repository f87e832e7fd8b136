// One analytic environment (layout_render.h: a random band-limited part plus a small bright
// lobe and a small bright disc, closed-form SH) rendered by the test code into every layout
// at several sizes: each projection equals the closed form within the tolerance derived from
// that layout's discretisation (layout_render.h), and the error falls as the size grows.
// Measured errors are printed ("[ measure  ]").
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "layout_render.h"
#include "shpack/cube_layout.h"
#include "shpack/project.h"
#include "shpack/project_cube.h"
#include "shpack/project_sphere_map.h"
#include "shpack/sh_basis.h"
#include "support/gauss_legendre.h"
#include "support/test_util.h"

namespace shpack_layout_test {
namespace {

using shpack::ShL2;

struct Outcome {
  double error = 0;      // max_c,i |got - exact| / max |exact|
  double worst_fraction = 0;  // max_c,i |got - exact| / tolerance
  double cut = 0;        // the solid angle of the texels the cap's edge may cross
};

// Compares one projection with the closed form, coefficient by coefficient. The rendering's
// own quadrature error on the smooth part (two densities of its rule, on this very image) is
// added to the tolerance: sum_t Omega_t |s_t - s_t,fine| max|Y_i|, times 2 in case the fine
// rule is only half as close as it looks, with s_t = f_t - K_c cover_t (the cap's rendering
// error needs no estimate: projection_tolerance bounds it whatever it is).
Outcome check(const std::string& what, const ShL2& got, const AnalyticEnvironment& f, const Rendering& coarse,
              const std::vector<Texel>& fine_texels) {
  const ShL2 exact = f.exact();
  double scale = 0;
  for (const auto& ch : exact.c)
    for (double v : ch) scale = std::fmax(scale, std::fabs(v));
  Outcome out;
  out.cut = cut_solid_angle(coarse.texels, f);
  for (int c = 0; c < 3; ++c) {
    const auto smooth = [&](const Texel& t) { return t.average[c] - f.cap[c] * t.cap_cover; };
    double render_error = 0;
    for (std::size_t t = 0; t < coarse.texels.size(); ++t)
      render_error += 2.0 * coarse.texels[t].solid_angle * std::fabs(smooth(coarse.texels[t]) - smooth(fine_texels[t])) *
                      std::sqrt(5.0 / (4 * std::numbers::pi));
    for (int i = 0; i < shpack::kShCount; ++i) {
      const double tol = projection_tolerance(coarse.texels, f, c, i) + render_error;
      const double err = std::fabs(got.c[c][i] - exact.c[c][i]);
      EXPECT_LE(err, tol) << what << " c=" << c << " i=" << i << " got " << got.c[c][i] << " exact " << exact.c[c][i];
      out.error = std::fmax(out.error, err / scale);
      out.worst_fraction = std::fmax(out.worst_fraction, err / tol);
    }
  }
  return out;
}

void report(const std::string& layout, const std::vector<std::uint32_t>& sizes, const std::vector<Outcome>& outcomes) {
  std::cout << "[ measure  ] " << layout << ": max |error| / max |L|";
  for (std::size_t k = 0; k < sizes.size(); ++k)
    std::cout << "  N=" << sizes[k] << ": " << outcomes[k].error << " (" << outcomes[k].worst_fraction
              << " of tol; cut by the disc's edge " << outcomes[k].cut << " sr)";
  std::cout << "\n";
  // The error falls as the texels shrink (O(h^2) for the smooth part: each doubling should
  // divide it by ~4), and so does the ring of texels the disc's edge crosses (O(h)).
  for (std::size_t k = 1; k < outcomes.size(); ++k) {
    EXPECT_LT(outcomes[k].error, outcomes[k - 1].error) << layout << " N=" << sizes[k];
    EXPECT_LT(outcomes[k].cut, outcomes[k - 1].cut) << layout << " N=" << sizes[k];
  }
}

class LayoutProof : public ::testing::Test {
 protected:
  AnalyticEnvironment f = make_environment(0x5eed);
};

// The disc's closed form (layout_render.h) against its integral in the disc's own polar
// coordinates, where it is the smooth region theta in [0, r], phi in [0, 2 pi):
// d = cos(theta) s + sin(theta) (cos(phi) e1 + sin(phi) e2), dw = sin(theta) dtheta dphi.
// Y_i(d) sin(theta) is a trigonometric polynomial of frequency <= 3 in theta and <= 2 in phi,
// so 8 equally spaced phi are exact and 8 Gauss-Legendre nodes over r = 0.052 leave
// gl_relative_bound(r, 3, 8) ~ 1e-43. What remains is rounding: 64 terms, each below
// K max|Y| Omega_cap, at 2^-53 each: 64 * 1.1e-16 = 7e-15 of K max|Y| Omega_cap; 1e-13 allows 14x.
TEST_F(LayoutProof, TheDiscsClosedFormIsItsIntegral) {
  AnalyticEnvironment disc = f;  // the disc alone
  disc.band_limited = {};
  disc.lobe = {};
  const shpack::Dir3 s = disc.cap_axis;
  // e1 perpendicular to s (s is far from +Y), e2 = s x e1.
  const double n1 = std::hypot(s.z, s.x);
  const shpack::Dir3 e1{s.z / n1, 0.0, -s.x / n1};
  const shpack::Dir3 e2{s.y * e1.z - s.z * e1.y, s.z * e1.x - s.x * e1.z, s.x * e1.y - s.y * e1.x};
  const shpack_test::GaussRule g = shpack_test::gauss_legendre(8);
  const int phis = 8;
  const double r = disc.cap_radius, pi = std::numbers::pi;
  std::array<double, shpack::kShCount> integral{};
  for (std::size_t k = 0; k < g.nodes.size(); ++k) {
    const double theta = 0.5 * r * (1.0 + g.nodes[k]), w_theta = 0.5 * r * g.weights[k] * std::sin(theta);
    for (int j = 0; j < phis; ++j) {
      const double phi = 2 * pi * j / phis, w = w_theta * 2 * pi / phis;
      const double a = std::cos(theta), b = std::sin(theta) * std::cos(phi), c = std::sin(theta) * std::sin(phi);
      const std::array<double, 9> y = shpack::eval_basis(a * s.x + b * e1.x + c * e2.x, a * s.y + b * e1.y + c * e2.y,
                                                         a * s.z + b * e1.z + c * e2.z);
      for (int i = 0; i < shpack::kShCount; ++i) integral[i] += w * y[i];
    }
  }
  const ShL2 exact = disc.exact();
  const double omega_cap = 2 * pi * (1 - std::cos(r));
  for (int ch = 0; ch < 3; ++ch) {
    const double tol = 1e-13 * disc.cap[ch] * std::sqrt(5.0 / (4 * pi)) * omega_cap;
    for (int i = 0; i < shpack::kShCount; ++i)
      EXPECT_NEAR(exact.c[ch][i], disc.cap[ch] * integral[i], tol) << "c=" << ch << " i=" << i;
  }
}

TEST_F(LayoutProof, Equirect) {
  const std::vector<std::uint32_t> sizes = {8, 16, 32, 64};
  std::vector<Outcome> outcomes;
  for (const std::uint32_t n : sizes) {
    const Rendering r = render_equirect(2 * n, n, f), fine = render_equirect(2 * n, n, f, true);
    ShL2 got;
    ASSERT_TRUE(shpack::project_equirect(shpack::make_view(r.rgb.data(), 2 * n, n, 3), {}, got).ok());
    outcomes.push_back(check("equirect n=" + std::to_string(n), got, f, r, fine.texels));
  }
  report("equirect", sizes, outcomes);
}

TEST_F(LayoutProof, CubeLayoutsAndFaces) {
  // The faces are rendered once per size; the crosses and strips are made of them, so all
  // five cube layouts project the same texels through different views: identical results.
  const std::vector<std::uint32_t> sizes = {4, 8, 16, 32};
  std::vector<Outcome> outcomes;
  for (const std::uint32_t n : sizes) {
    const std::array<Rendering, 6> faces = render_cube_faces(n, f), fine = render_cube_faces(n, f, true);
    Rendering all;
    std::vector<Texel> fine_texels;
    for (int k = 0; k < 6; ++k) {
      all.texels.insert(all.texels.end(), faces[k].texels.begin(), faces[k].texels.end());
      fine_texels.insert(fine_texels.end(), fine[k].texels.begin(), fine[k].texels.end());
    }
    std::array<shpack::ImageView, 6> views;
    for (int k = 0; k < 6; ++k) views[k] = shpack::make_view(faces[k].rgb.data(), n, n, 3);
    ShL2 from_faces;
    ASSERT_TRUE(shpack::project_cube(views, {}, from_faces).ok());
    outcomes.push_back(check("faces n=" + std::to_string(n), from_faces, f, all, fine_texels));
    for (const shpack::CubeLayout layout : {shpack::CubeLayout::HorizontalCross, shpack::CubeLayout::VerticalCross,
                                            shpack::CubeLayout::HorizontalStrip, shpack::CubeLayout::VerticalStrip}) {
      const Rendering image = assemble_cube_image(layout, faces);
      std::array<shpack::ImageView, 6> cells;
      ASSERT_TRUE(shpack::cube_face_views(shpack::make_view(image.rgb.data(), image.width, image.height, 3), layout, cells).ok());
      ShL2 got;
      ASSERT_TRUE(shpack::project_cube(cells, {}, got).ok());
      EXPECT_EQ(got, from_faces) << "layout " << static_cast<int>(layout) << " n=" << n;
    }
  }
  report("cube (faces, hcross, vcross, hstrip, vstrip)", sizes, outcomes);
}

void sphere_map_proof(const AnalyticEnvironment& f, shpack::SphereMap map, const std::string& name) {
  const std::vector<std::uint32_t> sizes = {8, 16, 32};
  std::vector<Outcome> outcomes;
  for (const std::uint32_t n : sizes) {
    const Rendering r = render_sphere_map(map, n, f), fine = render_sphere_map(map, n, f, true);
    ShL2 got;
    ASSERT_TRUE(shpack::project_sphere_map(shpack::make_view(r.rgb.data(), n, n, 3), map, {}, got).ok());
    outcomes.push_back(check(name + " n=" + std::to_string(n), got, f, r, fine.texels));
  }
  report(name, sizes, outcomes);
}

TEST_F(LayoutProof, Octahedral) { sphere_map_proof(f, shpack::SphereMap::Octahedral, "octahedral"); }
TEST_F(LayoutProof, Angular) { sphere_map_proof(f, shpack::SphereMap::Angular, "angular"); }
TEST_F(LayoutProof, MirrorBall) { sphere_map_proof(f, shpack::SphereMap::MirrorBall, "mirrorball"); }

}  // namespace
}  // namespace shpack_layout_test
