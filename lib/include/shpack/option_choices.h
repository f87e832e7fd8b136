// option_choices.h - the names a user gives the enumerated options of a conversion, and the
// value each name stands for: one table per option, read by `shpack convert`'s parser
// (cli/convert_command.cpp) and by the Python module (python/shpack_module.cpp), so that a
// name accepted by one is accepted by the other and means the same.
//
// The names are those of the documents too (layout_name, colorspace_name, kEngineFrames,
// json_writer.cpp's cube frames); tests/io/option_choices_test.cpp checks that they agree.
// Each table lists its choices in the order the help shows them, the default first.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "shpack/colorspace.h"
#include "shpack/conventions.h"
#include "shpack/engine_frame.h"
#include "shpack/layout.h"
#include "shpack/project.h"

namespace shpack {

template <class Enum>
struct OptionChoice {
  std::string_view name;
  Enum value;
};

// --layout: how one image holds the sphere. Layout::Faces is not among them: six faces are
// given as six files (--faces) or, in Python, as a (6, N, N, C) array.
inline constexpr std::array<OptionChoice<Layout>, 9> kLayoutChoices = {{
    {"auto", Layout::Auto},
    {"equirect", Layout::Equirect},
    {"hcross", Layout::HorizontalCross},
    {"vcross", Layout::VerticalCross},
    {"hstrip", Layout::HorizontalStrip},
    {"vstrip", Layout::VerticalStrip},
    {"octahedral", Layout::Octahedral},
    {"angular", Layout::Angular},
    {"mirrorball", Layout::MirrorBall},
}};

// --cube-frame: the world cube faces were made in (conventions.h).
inline constexpr std::array<OptionChoice<CubeFrame>, 3> kCubeFrameChoices = {{
    {"unity", CubeFrame::Unity},
    {"gl", CubeFrame::Gl},
    {"threejs", CubeFrame::ThreeJs},
}};

// --colorspace: the primaries of the input's linear RGB (colorspace.h).
inline constexpr std::array<OptionChoice<ColorSpace>, 6> kColorSpaceChoices = {{
    {"auto", ColorSpace::Auto},
    {"linear-rec709", ColorSpace::LinearRec709},
    {"acescg", ColorSpace::AcesCg},
    {"aces2065-1", ColorSpace::Aces2065_1},
    {"linear-p3-d65", ColorSpace::LinearP3D65},
    {"linear-rec2020", ColorSpace::LinearRec2020},
}};

// --nonfinite and --negative: the value policies of the projector (project.h).
inline constexpr std::array<OptionChoice<NonFinite>, 2> kNonFiniteChoices = {{
    {"error", NonFinite::Error},
    {"zero", NonFinite::Zero},
}};
inline constexpr std::array<OptionChoice<Negative>, 2> kNegativeChoices = {{
    {"keep", Negative::Keep},
    {"clamp", Negative::Clamp},
}};

// --frame: the frame of the JSON document's radiance_sh, named as engine_frame.h names them.
inline constexpr std::array<OptionChoice<EngineFrame>, kEngineFrames.size()> kEngineFrameChoices = [] {
  std::array<OptionChoice<EngineFrame>, kEngineFrames.size()> choices{};
  for (std::size_t k = 0; k < kEngineFrames.size(); ++k)
    choices[k] = {kEngineFrames[k].name, static_cast<EngineFrame>(k)};
  return choices;
}();

// The choice named `text`, ignoring ASCII case as the command line does ("EQUIRECT" is
// "equirect"), or null when none is.
template <class Enum, std::size_t N>
constexpr const OptionChoice<Enum>* find_choice(const std::array<OptionChoice<Enum>, N>& choices,
                                                std::string_view text) noexcept {
  const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  for (const OptionChoice<Enum>& choice : choices) {
    if (choice.name.size() != text.size()) continue;
    bool same = true;
    for (std::size_t k = 0; k < text.size() && same; ++k) same = lower(text[k]) == choice.name[k];
    if (same) return &choice;
  }
  return nullptr;
}

// "{auto,equirect,...}": the names, as the command line's error lists them.
template <class Enum, std::size_t N>
std::string choice_list(const std::array<OptionChoice<Enum>, N>& choices) {
  std::string list = "{";
  for (const OptionChoice<Enum>& choice : choices) {
    if (list.size() > 1) list.append(",");
    list.append(choice.name);
  }
  list.append("}");
  return list;
}

}  // namespace shpack
