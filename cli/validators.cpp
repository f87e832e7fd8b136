#include "validators.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <string>

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
      "NUMBER");
}

CLI::Validator non_negative_finite_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<double> value = parse_finite(text);
        return value && *value >= 0 ? "" : "'" + text + "' is not a finite number >= 0";
      },
      "NUMBER >= 0");
}

CLI::Validator unsigned_integer() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        return digits ? "" : "'" + text + "' is not an unsigned integer";
      },
      "UINT");
}

}  // namespace shpack::cli
