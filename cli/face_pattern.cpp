#include "face_pattern.h"

#include <utility>

#include "replace_all.h"

namespace shpack::cli {

std::string expand_face_pattern(std::string pattern, std::string_view name) {
  return replace_all(std::move(pattern), kFacePlaceholder, name);
}

}  // namespace shpack::cli
