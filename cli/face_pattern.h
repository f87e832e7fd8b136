// face_pattern.h - the {face} pattern of `convert --faces` and `irradiance --layout faces`.
//
// One pattern names six files: {face} becomes px nx py ny pz nz, Unity's face order +X -X
// +Y -Y +Z -Z (cube_layout.h).
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace shpack::cli {

inline constexpr std::string_view kFacePlaceholder = "{face}";
inline constexpr std::array<std::string_view, 6> kFaceNames = {"px", "nx", "py", "ny", "pz", "nz"};

// `pattern` with every {face} replaced by `name`.
std::string expand_face_pattern(std::string pattern, std::string_view name);

}  // namespace shpack::cli
