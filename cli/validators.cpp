#include "validators.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "shpack/window.h"

namespace shpack::cli {
namespace {

// The whole string as a finite double, or nothing.
std::optional<double> parse_finite(const std::string& text) {
  double value = 0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars takes "-1" but not "+1"
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || stop != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return parse_finite(text) ? "" : "'" + text + "' is not a finite number";
      },
      "");  // the option's type name says what it takes
}

CLI::Validator non_negative_finite_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<double> value = parse_finite(text);
        return value && *value >= 0 ? "" : "'" + text + "' is not a finite number >= 0";
      },
      "");  // the option's type name says what it takes
}

CLI::Validator unsigned_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        return digits ? "" : "'" + text + "' is not an unsigned integer";
      },
      "");  // the option's type name says what it takes
}

CLI::Validator unsigned_in(std::uint64_t lo, std::uint64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (digits && error == std::errc() && stop == end && value >= lo && value <= hi) return "";
        return "'" + text + "' is not an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
      },
      "");
}

CLI::Validator window_text() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        Window window;
        const Status st = parse_window(text, window);
        return st.ok() ? std::string() : std::string(st.what);
      },
      "");
}

}  // namespace shpack::cli
