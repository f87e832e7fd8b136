// replace_all.h - text with every occurrence of one string replaced by another.
#pragma once

#include <string>
#include <string_view>

namespace shpack::cli {

// `text` with every `from` replaced by `to`, left to right, never inside a replacement;
// `text` unchanged when `from` is empty.
std::string replace_all(std::string text, std::string_view from, std::string_view to);

}  // namespace shpack::cli
