#include "face_pattern.h"

namespace shpack::cli {

std::string expand_face_pattern(std::string pattern, std::string_view name) {
  for (std::size_t at = pattern.find(kFacePlaceholder); at != std::string::npos;
       at = pattern.find(kFacePlaceholder, at + name.size())) {
    pattern.replace(at, kFacePlaceholder.size(), name);
  }
  return pattern;
}

}  // namespace shpack::cli
