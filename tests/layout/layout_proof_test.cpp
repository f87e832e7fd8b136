// One analytic environment (layout_render.h: a random band-limited part plus a small bright
// lobe, closed-form SH) rendered by the test code into every layout at several sizes: each
// projection equals the closed form within the tolerance derived from that layout's
// discretisation (layout_render.h), and the error falls as the size grows. Measured errors
// are printed ("[ measure  ]").
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
#include "support/test_util.h"

namespace shpack_layout_test {
namespace {

using shpack::ShL2;

struct Outcome {
  double error = 0;      // max_c,i |got - exact| / max |exact|
  double worst_fraction = 0;  // max_c,i |got - exact| / tolerance
};

// Compares one projection with the closed form, coefficient by coefficient. The rendering's
// own quadrature error (two densities of its rule, on this very image) is added to the
// tolerance: sum_t Omega_t |f_t - f_t,fine| max|Y_i|, times 2 in case the fine rule is only
// half as close as it looks.
Outcome check(const std::string& what, const ShL2& got, const AnalyticEnvironment& f, const Rendering& coarse,
              const std::vector<Texel>& fine_texels) {
  const ShL2 exact = f.exact();
  double scale = 0;
  for (const auto& ch : exact.c)
    for (double v : ch) scale = std::fmax(scale, std::fabs(v));
  Outcome out;
  for (int c = 0; c < 3; ++c) {
    double render_error = 0;
    for (std::size_t t = 0; t < coarse.texels.size(); ++t)
      render_error += 2.0 * coarse.texels[t].solid_angle *
                      std::fabs(coarse.texels[t].average[c] - fine_texels[t].average[c]) * std::sqrt(5.0 / (4 * std::numbers::pi));
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
    std::cout << "  N=" << sizes[k] << ": " << outcomes[k].error << " (" << outcomes[k].worst_fraction << " of tol)";
  std::cout << "\n";
  // The error falls as the texels shrink (O(h^2): each doubling should divide it by ~4).
  for (std::size_t k = 1; k < outcomes.size(); ++k)
    EXPECT_LT(outcomes[k].error, outcomes[k - 1].error) << layout << " N=" << sizes[k];
}

class LayoutProof : public ::testing::Test {
 protected:
  AnalyticEnvironment f = make_environment(0x5eed);
};

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
