#include "shpack/io/layout.h"

#include <gtest/gtest.h>

namespace shpack::io {
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
}

}  // namespace
}  // namespace shpack::io
