// E/pi as an image (irradiance_image.h): the texel directions of every output layout, the
// exact source against tests/support's brute force (irradiance_oracle.h) within both
// bounds, and all four sources on a uniform map, whose E/pi is its radiance everywhere, each
// within what its own rule allows (derived below).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "shpack/irradiance_image.h"
#include "support/irradiance_oracle.h"
#include "support/rgb_image.h"

namespace shpack {
namespace {

using shpack_test::RgbImage;

double dot(const Dir3& a, const Dir3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

MapImage map_of(RgbImage& image) {
  MapImage map;
  map.image = image.view();
  map.writable = image.rgb.data();
  return map;
}

IrradianceImage render(RgbImage image, IrradianceSource source, std::uint32_t samples = 0,
                       Layout layout = Layout::Equirect, std::uint32_t size = 16) {
  IrradianceRequest request;
  request.source = source;
  request.samples = samples;
  request.seed = 7;
  request.layout = layout;
  request.size = size;
  request.threads = 2;
  ConvertOptions options;
  IrradianceImage out;
  const Status st = render_irradiance(map_of(image), options, request, out);
  EXPECT_TRUE(st.ok()) << st.what;
  return out;
}

TEST(IrradianceImage, EveryLayoutsTexelsPointWhereItsFaceDoes) {
  std::uint32_t w = 0, h = 0;
  std::vector<Dir3> dirs;
  std::vector<std::uint8_t> used;
  ASSERT_TRUE(irradiance_directions(Layout::Equirect, 8, w, h, dirs, used).ok());
  EXPECT_EQ(w, 16u);
  EXPECT_EQ(h, 8u);
  EXPECT_EQ(dirs[3 * 16 + 5], equirect_direction(5.5 / 16, 3.5 / 8));
  // A cross: 6 of its 12 cells hold a face. The centre 2 x 2 texels of each face's cell point
  // along the face's normal within a texel's half-diagonal (the cell's middle is between them).
  const struct {
    Layout layout;
    std::uint32_t columns, rows;
  } cubes[] = {{Layout::HorizontalCross, 4, 3}, {Layout::VerticalCross, 3, 4}, {Layout::HorizontalStrip, 6, 1},
               {Layout::VerticalStrip, 1, 6}};
  constexpr std::uint32_t n = 8;
  for (const auto& cube : cubes) {
    ASSERT_TRUE(irradiance_directions(cube.layout, n, w, h, dirs, used).ok());
    EXPECT_EQ(w, cube.columns * n);
    EXPECT_EQ(h, cube.rows * n);
    EXPECT_EQ(std::count(used.begin(), used.end(), 1), 6 * n * n);
    for (int f = 0; f < kCubeFaceCount; ++f) {
      const CubeCell cell = cube_layout_cell(cube.layout == Layout::HorizontalCross ? CubeLayout::HorizontalCross
                                             : cube.layout == Layout::VerticalCross ? CubeLayout::VerticalCross
                                             : cube.layout == Layout::HorizontalStrip ? CubeLayout::HorizontalStrip
                                                                                      : CubeLayout::VerticalStrip,
                                             static_cast<CubeFace>(f));
      const std::size_t x = cell.column * n + n / 2, y = cell.row * n + n / 2;
      EXPECT_GT(dot(dirs[y * w + x], kCubeFaceAxes[f].normal), std::cos(std::hypot(1.0, 1.0) / n)) << f;
    }
  }
  // The vertical cross's -Z is stored turned by 180 degrees: the top-left texel of its cell is
  // the face's bottom-right, along +u and +v of the face: (-1, -1, ...) for -Z's u = -x, v = -y.
  ASSERT_TRUE(irradiance_directions(Layout::VerticalCross, n, w, h, dirs, used).ok());
  const Dir3 corner = dirs[(3 * n) * w + n];
  EXPECT_LT(corner.x, 0);
  EXPECT_LT(corner.y, 0);
  EXPECT_LT(corner.z, 0);
  EXPECT_EQ(irradiance_directions(Layout::Octahedral, n, w, h, dirs, used).code, Errc::InvalidArgument);
  EXPECT_EQ(irradiance_directions(Layout::Equirect, 0, w, h, dirs, used).code, Errc::InvalidArgument);
}

TEST(IrradianceImage, ExactIsTheBruteForceWithinBothBounds) {
  // A 64 x 32 map of varied texels with a bright spot: |exact - oracle| <= exact's bound (the
  // image's, the largest of any texel) + the oracle's, plus float rounding of the stored value
  // (2^-24 of it).
  RgbImage map(64, 32);
  for (std::uint32_t y = 0; y < 32; ++y)
    for (std::uint32_t x = 0; x < 64; ++x) map.set(x, y, 0.2f + 0.01f * (x % 7), 0.3f + 0.02f * (y % 5), 0.1f);
  map.set(40, 10, 500, 400, 300);
  const IrradianceImage image = render(map, IrradianceSource::Exact, 0, Layout::Equirect, 8);
  const shpack_test::IrradianceOracle oracle(map, 6);
  std::vector<Dir3> dirs;
  std::vector<std::uint8_t> used;
  std::uint32_t w = 0, h = 0;
  ASSERT_TRUE(irradiance_directions(Layout::Equirect, 8, w, h, dirs, used).ok());
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const shpack_test::IrradianceEstimate o = oracle.eval(dirs[i]);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(image.rgb[3 * i + c], o.e_over_pi[c], image.bound + o.bound[c] + 0x1p-23 * o.e_over_pi[c]) << i;
  }
}

TEST(IrradianceImage, EverySourceGivesAUniformMapsRadiance) {
  // L = 0.5 everywhere: E/pi = 0.5 at every normal.
  RgbImage uniform(64, 32);
  std::fill(uniform.rgb.begin(), uniform.rgb.end(), 0.5f);
  const auto expect_all = [](const IrradianceImage& image, double tolerance, const char* what) {
    for (float v : image.rgb) EXPECT_NEAR(v, 0.5, tolerance) << what;
  };
  // Sh: the L2 SH of a constant is exact; ShadeSH9 in float adds a few float roundings.
  expect_all(render(uniform, IrradianceSource::Sh), 1e-6, "sh");
  // Exact: every cell lies wholly above or below a normal's horizon or is bounded.
  const IrradianceImage exact = render(uniform, IrradianceSource::Exact);
  expect_all(exact, exact.bound + 1e-12, "exact");
  // Riemann over n x 2n cells (n = 64 for N = 8192): max(0, d . w) is 1-Lipschitz in w and a
  // cell lies within r = dtheta/2 + dphi/2 = pi/n of its centre, so the sum errs by at most
  // sum_k L dW_k r / pi = 4 L r = 2 pi / n = 0.098.
  expect_all(render(uniform, IrradianceSource::Riemann, 8192), 2 * std::numbers::pi / 64, "riemann");
  // Monte Carlo: each term 4 L c with c = max(0, d . w), E[c] = 1/4, E[c^2] = 1/6, so the
  // estimate's standard deviation is L sqrt((16/6 - 1) / N) = 0.5 sqrt(5 / (3 N)): 0.0101
  // for N = 4096; 6 sigma over the 512 texels (a one-in-10^6 tail each).
  expect_all(render(uniform, IrradianceSource::MonteCarlo, 4096), 6 * 0.5 * std::sqrt(5.0 / (3 * 4096)), "mc");
}

TEST(IrradianceImage, SampledSourcesReadEquirectMapsOnly) {
  RgbImage cross(64, 48);
  MapImage map = map_of(cross);
  map.layout = Layout::HorizontalCross;
  IrradianceRequest request;
  request.source = IrradianceSource::Riemann;
  request.samples = 100;
  IrradianceImage out;
  EXPECT_EQ(render_irradiance(map, {}, request, out).code, Errc::InvalidArgument);
  request.samples = 0;
  map.layout = Layout::Equirect;
  EXPECT_EQ(render_irradiance(map, {}, request, out).code, Errc::InvalidArgument);
}

}  // namespace
}  // namespace shpack
