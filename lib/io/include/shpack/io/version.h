// version.h - the version of shpack, from the top-level CMake project.
#pragma once

namespace shpack::io {

// "0.1.0"
const char* shpack_version() noexcept;

}  // namespace shpack::io
