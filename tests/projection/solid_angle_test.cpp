// solid_angle_test.cpp - the texel solid angles of every image size sum to 4 pi: a constant
// unit image has L00 = int Y0 = 4 pi k0, for both methods (both use exact solid angles;
// neither renormalises).
#include <gtest/gtest.h>

#include <numbers>

#include "shpack/project.h"
#include "support/rgb_image.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

TEST(SolidAngle, ConstantImageSumsTo4Pi) {
  struct Size {
    std::uint32_t w, h;
  };
  for (Size s : {Size{1, 1}, Size{2, 1}, Size{1, 2}, Size{3, 2}, Size{7, 5}, Size{64, 32}, Size{1, 1000},
                 Size{1000, 1}, Size{1024, 512}, Size{4096, 3}})
    for (shpack::SamplingMethod m : {shpack::SamplingMethod::Exact, shpack::SamplingMethod::Center}) {
      RgbImage img(s.w, s.h);
      std::fill(img.rgb.begin(), img.rgb.end(), 1.0f);
      shpack::ProjectOptions opt;
      opt.method = m;
      shpack::ShL2 sh;
      const shpack::Status st = shpack::project_equirect(img.view(), opt, sh);
      ASSERT_TRUE(st.ok()) << describe(st);
      // Each texel weight is a product of a few correctly rounded functions (<= 8u); a row
      // is summed in double (<= (W - 1) u of the row total, project.h); rows are combined
      // with Neumaier's sum (<= 2u + O(H u^2)); the final k0 scaling adds 1u; dividing by
      // kY0 here another 2u. Total <= (W + 16) u relative, which is < 1e-12 relative for
      // every size here (W <= 4096).
      const double sum = sh.c[0][0] / shpack::kY0;
      const double tol = (s.w + 16.0) * kU * 4 * std::numbers::pi;
      EXPECT_NEAR(4 * std::numbers::pi, sum, tol)
          << "W=" << s.w << " H=" << s.h << " method=" << static_cast<int>(m);
      EXPECT_LT(tol / (4 * std::numbers::pi), 1e-12) << "W=" << s.w;
      EXPECT_EQ(sh.c[0], sh.c[1]) << "W=" << s.w << " H=" << s.h;
      EXPECT_EQ(sh.c[0], sh.c[2]) << "W=" << s.w << " H=" << s.h;
    }
}

}  // namespace
}  // namespace shpack_test
