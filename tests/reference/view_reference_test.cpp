// The reference E/pi against tests/support's brute force (irradiance_oracle.h), which shares
// no code with it: both claim a rigorous bound, so at every normal
//   |reference - oracle| <= reference.bound + oracle.bound  (+ rounding, 1e-12 of the mean).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shpack/pipeline.h"
#include "shpack/view_error.h"
#include "shpack/view_reference.h"
#include "support/irradiance_oracle.h"
#include "support/rgb_image.h"

namespace {

using shpack::Dir3;
using shpack_test::RgbImage;

shpack::ViewReference reference_of(const RgbImage& image, std::uint32_t band) {
  shpack::ViewReference ref;
  EXPECT_TRUE(ref.begin_equirect(image.width, image.height, {}).ok());
  shpack::ImageView view = image.view();
  EXPECT_TRUE(shpack::resolve_view(view).ok());
  for (std::uint32_t y = 0; y < image.height; y += band) {
    const std::uint32_t n = std::min(band, image.height - y);
    EXPECT_TRUE(ref.add_rows(view.rows(y, n), y).ok());
  }
  EXPECT_TRUE(ref.finish().ok());
  return ref;
}

void expect_within_bounds(const RgbImage& image, const shpack::ViewReference& ref, double max_bound_of_mean) {
  const shpack_test::IrradianceOracle oracle(image, 6);
  const std::array<double, 3> mean = ref.mean_e_over_pi();
  for (std::size_t i = 0; i < 200; ++i) {
    const Dir3 n = shpack::spherical_fibonacci(i, 200);
    const shpack::ReferenceValue r = ref.eval(n);
    const shpack_test::IrradianceEstimate o = oracle.eval(n);
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(std::abs(r.e_over_pi[c] - o.e_over_pi[c]), r.bound[c] + o.bound[c] + 1e-12 * mean[c])
          << "normal " << i << " channel " << c;
      // The bound is useful, not merely true: view_reference.h's estimate for the cell sizes.
      EXPECT_LE(r.bound[c], max_bound_of_mean * mean[c]) << "normal " << i;
    }
  }
}

TEST(ViewReference, AgreesWithTheBruteForceOnARandomMapWithinBothBounds) {
  RgbImage image = shpack_test::uniform_random_image(64, 32, 7, 0.0f, 1.0f);
  // A finest cell is 1 x 1 texel here: R <= dth/2 + dphi/2 = 0.098 + 0.049, and the cut band
  // costs about 2 R^2 = 4 % of the mean.
  expect_within_bounds(image, reference_of(image, 32), 0.06);
}

TEST(ViewReference, KeepsASunTexelAsItsOwnLeaf) {
  RgbImage image = shpack_test::uniform_random_image(256, 128, 11, 0.0f, 0.2f);
  image.set(100, 40, 5000.0f, 4000.0f, 3000.0f);  // carries ~30x the rest of the map's flux
  // Its leaf's radius is its diameter, dth + dphi = 0.037: its cut interval is at most
  // P R / pi ~ 30 x 4 x 0.037 / pi = 1.4 mean, the rest's ~ 2 R^2 with R = 0.05.
  expect_within_bounds(image, reference_of(image, 128), 1.5);
}

TEST(ViewReference, IsTheSameForAnyBandsOfRows) {
  const RgbImage image = shpack_test::uniform_random_image(300, 150, 3, -0.1f, 2.0f);
  const shpack::ViewReference whole = reference_of(image, 150), banded = reference_of(image, 7);
  for (std::size_t i = 0; i < 50; ++i) {
    const Dir3 n = shpack::spherical_fibonacci(i, 50);
    EXPECT_EQ(whole.eval(n).e_over_pi, banded.eval(n).e_over_pi);
    EXPECT_EQ(whole.eval(n).bound, banded.eval(n).bound);
  }
}

TEST(ViewReference, AUniformCubeMapIsItsRadianceEverywhere) {
  // E/pi of a uniform L is L at every normal; every texel of a cube face is added with the
  // projector's own integrals, which sum to 4 pi to rounding.
  const std::uint32_t n = 16;
  std::vector<float> face(std::size_t{3} * n * n, 0.75f);
  shpack::MapImage map;
  map.layout = shpack::Layout::Faces;
  for (auto& f : map.faces) f = shpack::make_view(face.data(), n, n, 3);
  shpack::ViewReference ref;
  ASSERT_TRUE(shpack::build_view_reference(map, {}, ref).ok());
  for (std::size_t i = 0; i < 100; ++i) {
    const shpack::ReferenceValue r = ref.eval(shpack::spherical_fibonacci(i, 100));
    for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(r.e_over_pi[c] - 0.75), r.bound[c] + 1e-12);
  }
}

TEST(ViewError, IsZeroForWhatUnityShowsExactlyAndSeesADirectionalLight) {
  // A uniform map: its L2 projection is exact, so Unity shows the truth to float rounding
  // (a few 2^-24 relative, 1e-4 %), and the measured error is within the reference's bound.
  RgbImage image(8, 4);
  for (float& v : image.rgb) v = 2.0f;
  const shpack::ViewReference ref = reference_of(image, 4);
  shpack::ViewSamples samples;
  ASSERT_TRUE(shpack::sample_view_reference(ref, samples).ok());
  shpack::ShL2 radiance;
  ASSERT_TRUE(shpack::project_equirect(image.view(), {}, radiance).ok());
  shpack::FinishedSh sh;
  ASSERT_TRUE(shpack::finish_projection(radiance, {}, sh).ok());
  const shpack::ViewError plain = shpack::unity_view_error(samples, {}, sh.shader, {});
  EXPECT_LE(plain.max_pct, plain.bound_pct + 1e-4);
  // A light that Unity adds on top is an error of exactly its Lambert term: max 100 x
  // intensity / mean at the normal facing it.
  shpack::UnitySunLight light;
  light.forward = {0, -1, 0};
  light.colour = {1, 1, 1};
  light.intensity = 0.5;
  const shpack::ViewError lit = shpack::unity_view_error(samples, {}, sh.shader, {&light, 1});
  EXPECT_NEAR(lit.max_pct, 100 * 0.5 / 2.0, plain.bound_pct + 0.5);  // the nearest direction is within 9 degrees
}

}  // namespace
