// validators.h - CLI11 checks for numeric options. CLI11's own NonNegativeNumber lets
// "nan" through (NaN fails no comparison); a NaN intensity would make every coefficient NaN.
#pragma once

#include <CLI/CLI.hpp>

namespace shpack::cli {

CLI::Validator finite_number();
CLI::Validator non_negative_finite_number();
// Digits only: CLI11 reads "-1" into an unsigned option as its largest value.
CLI::Validator unsigned_integer();

}  // namespace shpack::cli
