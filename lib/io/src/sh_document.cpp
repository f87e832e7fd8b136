#include "shpack/io/sh_document.h"

namespace shpack::io {

const char* method_name(Method method) noexcept {
  switch (method) {
    case Method::Exact: return "exact";
    case Method::Center: return "center";
  }
  return "unknown";
}

}  // namespace shpack::io
