#include "shpack/io/version.h"

namespace shpack::io {

const char* shpack_version() noexcept { return SHPACK_VERSION; }

}  // namespace shpack::io
