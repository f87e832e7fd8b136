// checked_math.h (private) - unsigned 64-bit arithmetic that says when it overflows, for
// every size and offset computed from a file's numbers (gltf_mesh.cpp).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

namespace shpack::scene::detail {

// a * b and a + b, or nothing when the result does not fit in 64 bits.
inline std::optional<std::uint64_t> checked_mul(std::uint64_t a, std::uint64_t b) {
  std::uint64_t r;
  if (__builtin_mul_overflow(a, b, &r)) return std::nullopt;
  return r;
}
inline std::optional<std::uint64_t> checked_add(std::uint64_t a, std::uint64_t b) {
  std::uint64_t r;
  if (__builtin_add_overflow(a, b, &r)) return std::nullopt;
  return r;
}

// Saturating forms, for counts compared against a budget (the maximum means "too many").
inline std::uint64_t saturating_mul(std::uint64_t a, std::uint64_t b) {
  return checked_mul(a, b).value_or(std::numeric_limits<std::uint64_t>::max());
}
inline std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
  return checked_add(a, b).value_or(std::numeric_limits<std::uint64_t>::max());
}

}  // namespace shpack::scene::detail
