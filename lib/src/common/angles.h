// The core's one name for pi and for a degree in radians. Each file once defined its own,
// which files compiled as one translation unit (CMake's unity builds) cannot hold.
#pragma once

#include <numbers>

namespace shpack {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace shpack
