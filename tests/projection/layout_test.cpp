#include "shpack/layout.h"

#include <gtest/gtest.h>

#include <string>

namespace shpack {
namespace {

TEST(Layout, TwoToOneIsEquirect) {
  EXPECT_EQ(resolve_layout(Layout::Auto, 1024, 512), Layout::Equirect);
  EXPECT_EQ(resolve_layout(Layout::Auto, 2, 1), Layout::Equirect);
  // No overflow at the largest sizes.
  EXPECT_EQ(resolve_layout(Layout::Auto, 4294967294u, 2147483647u), Layout::Equirect);
}

TEST(Layout, OneTexelIsUniform) { EXPECT_EQ(resolve_layout(Layout::Auto, 1, 1), Layout::Equirect); }

TEST(Layout, OtherShapesAreNotDetected) {
  EXPECT_EQ(resolve_layout(Layout::Auto, 512, 512), Layout::Auto);  // ambiguous square
  EXPECT_EQ(resolve_layout(Layout::Auto, 300, 200), Layout::Auto);
  EXPECT_EQ(resolve_layout(Layout::Auto, 1025, 512), Layout::Auto);
  EXPECT_EQ(resolve_layout(Layout::Auto, 512, 1024), Layout::Auto);
}

TEST(Layout, AnExplicitLayoutIsKept) {
  EXPECT_EQ(resolve_layout(Layout::Equirect, 300, 200), Layout::Equirect);
}

TEST(Layout, NamesAreTheCliAndJsonNames) {
  EXPECT_STREQ(layout_name(Layout::Auto), "auto");
  EXPECT_STREQ(layout_name(Layout::Equirect), "equirect");
  EXPECT_STREQ(layout_name(Layout::HorizontalCross), "hcross");
  EXPECT_STREQ(layout_name(Layout::VerticalCross), "vcross");
  EXPECT_STREQ(layout_name(Layout::HorizontalStrip), "hstrip");
  EXPECT_STREQ(layout_name(Layout::VerticalStrip), "vstrip");
  EXPECT_STREQ(layout_name(Layout::Octahedral), "octahedral");
  EXPECT_STREQ(layout_name(Layout::Angular), "angular");
  EXPECT_STREQ(layout_name(Layout::MirrorBall), "mirrorball");
  EXPECT_STREQ(layout_name(Layout::Faces), "faces");
}

TEST(Layout, CubeShapesAreDetected) {
  EXPECT_EQ(resolve_layout(Layout::Auto, 1024, 768), Layout::HorizontalCross);
  EXPECT_EQ(resolve_layout(Layout::Auto, 768, 1024), Layout::VerticalCross);
  EXPECT_EQ(resolve_layout(Layout::Auto, 1536, 256), Layout::HorizontalStrip);
  EXPECT_EQ(resolve_layout(Layout::Auto, 256, 1536), Layout::VerticalStrip);
  EXPECT_EQ(resolve_layout(Layout::Auto, 4, 3), Layout::HorizontalCross);  // N = 1
  // 4:3 with a width that is not 4N has no whole faces.
  EXPECT_EQ(resolve_layout(Layout::Auto, 1026, 769), Layout::Auto);
  EXPECT_EQ(resolve_layout(Layout::Auto, 4294967292u, 3221225469u), Layout::HorizontalCross);  // no overflow
}

TEST(Layout, ProblemsListTheLayoutsThatFit) {
  EXPECT_EQ(layout_shape_problem(Layout::Auto, 1024, 512), "");
  EXPECT_EQ(layout_shape_problem(Layout::Auto, 512, 512),
            "the layout of a 512x512 image is ambiguous: it fits octahedral, angular and mirrorball");
  EXPECT_EQ(layout_shape_problem(Layout::Auto, 300, 200),
            "the layout of a 300x200 image cannot be detected: it fits no layout (2:1 equirect, 4:3 hcross, "
            "3:4 vcross, 6:1 hstrip, 1:6 vstrip, square octahedral, angular or mirrorball)");
  EXPECT_EQ(layout_shape_problem(Layout::VerticalCross, 1024, 768),
            "a 1024x768 image is not a vcross (3N x 4N); its shape fits hcross");
  EXPECT_EQ(layout_shape_problem(Layout::MirrorBall, 300, 200),
            "a 300x200 image is not a mirrorball (N x N); its shape fits no layout (2:1 equirect, 4:3 hcross, "
            "3:4 vcross, 6:1 hstrip, 1:6 vstrip, square octahedral, angular or mirrorball)");
  EXPECT_EQ(layout_shape_problem(Layout::Equirect, 300, 200), "");  // equirect reads any shape when named
  for (const Layout l : {Layout::HorizontalCross, Layout::VerticalStrip, Layout::Angular})
    EXPECT_EQ(layout_shape_problem(l, 1, 1), "") << layout_name(l);  // a uniform environment
}

}  // namespace
}  // namespace shpack
