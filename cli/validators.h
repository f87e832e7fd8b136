// validators.h - CLI11 checks for numeric options. CLI11's own NonNegativeNumber lets
// "nan" through (NaN fails no comparison); a NaN intensity would make every coefficient NaN.
// They have no description: --help shows each option's own type name (N, K, DEG, ...) and
// says its range in words, never a validator's name.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>

namespace shpack::cli {

CLI::Validator finite_number();
CLI::Validator non_negative_finite_number();
// Digits only: CLI11 reads "-1" into an unsigned option as its largest value.
CLI::Validator unsigned_integer();
// Digits only, a value from lo to hi.
CLI::Validator unsigned_in(std::uint64_t lo, std::uint64_t hi);
// A deringing window's text, as shpack::parse_window reads it (--window of convert, bake, merge).
CLI::Validator window_text();

}  // namespace shpack::cli
