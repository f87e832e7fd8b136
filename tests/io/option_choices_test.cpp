// The tables of option names (option_choices.h) against the names the documents write, and
// find_choice's case rule, which is the command line's.
#include "shpack/option_choices.h"

#include <gtest/gtest.h>

#include <string>

namespace shpack {
namespace {

TEST(OptionChoices, NamesAreTheNamesOfTheDocuments) {
  for (const auto& choice : kLayoutChoices) EXPECT_EQ(choice.name, layout_name(choice.value));
  for (const auto& choice : kColorSpaceChoices) EXPECT_EQ(choice.name, colorspace_name(choice.value));
  for (const auto& choice : kEngineFrameChoices) EXPECT_EQ(choice.name, engine_frame_spec(choice.value).name);
  EXPECT_EQ(kLayoutChoices.front().value, Layout::Auto);  // each table starts with its default
  EXPECT_EQ(kColorSpaceChoices.front().value, ColorSpace::Auto);
  EXPECT_EQ(kCubeFrameChoices.front().value, CubeFrame::Unity);
  EXPECT_EQ(kNonFiniteChoices.front().value, NonFinite::Error);
  EXPECT_EQ(kNegativeChoices.front().value, Negative::Keep);
  EXPECT_EQ(kEngineFrameChoices.front().value, EngineFrame::Unity);
}

TEST(OptionChoices, EveryValueOnceAndEveryLayoutButFaces) {
  for (std::size_t k = 0; k < kLayoutChoices.size(); ++k) {
    EXPECT_EQ(kLayoutChoices[k].value, static_cast<Layout>(k)) << kLayoutChoices[k].name;
    EXPECT_NE(kLayoutChoices[k].value, Layout::Faces);
  }
  EXPECT_EQ(kLayoutChoices.size(), static_cast<std::size_t>(Layout::Faces));
  for (std::size_t k = 0; k < kEngineFrameChoices.size(); ++k)
    EXPECT_EQ(kEngineFrameChoices[k].value, static_cast<EngineFrame>(k));
}

TEST(OptionChoices, FindIgnoresCaseOnlyAndListsAsTheCommandLine) {
  ASSERT_NE(find_choice(kLayoutChoices, "EquiRect"), nullptr);
  EXPECT_EQ(find_choice(kLayoutChoices, "EquiRect")->value, Layout::Equirect);
  EXPECT_EQ(find_choice(kColorSpaceChoices, "ACEScg")->value, ColorSpace::AcesCg);
  EXPECT_EQ(find_choice(kLayoutChoices, "equirect "), nullptr);
  EXPECT_EQ(find_choice(kLayoutChoices, "equi"), nullptr);
  EXPECT_EQ(find_choice(kLayoutChoices, "faces"), nullptr);
  EXPECT_EQ(find_choice(kLayoutChoices, ""), nullptr);
  EXPECT_EQ(choice_list(kNonFiniteChoices), "{error,zero}");
  EXPECT_EQ(choice_list(kCubeFrameChoices), "{unity,gl,threejs}");
}

}  // namespace
}  // namespace shpack
