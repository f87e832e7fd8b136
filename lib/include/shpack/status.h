// status.h - the error type of the core library.
//
// The core never throws and never keeps hidden error state: every fallible call
// returns a Status by value. Why: asset importers and Unity native plugins are often
// built with -fno-exceptions, and exceptions cannot cross a C or P/Invoke boundary.
// `what` always points at a static string literal, so a Status is trivially copyable
// and needs no allocation.
#pragma once

#include <cstdint>

namespace shpack {

enum class Errc : std::uint8_t {
  Ok = 0,
  InvalidArgument,  // an option or parameter is out of its domain (what says which)
  BadView,          // an ImageView is malformed: null data, zero size, overlapping strides
  NonFiniteTexel,   // a NaN or Inf texel under NonFinite::Error; x, y, face locate the first
  BadSequence,      // a streaming call out of order (rows not contiguous, finish twice)
  OutOfMemory,      // a documented buffer or a worker thread could not be created
  ProbeInsideLight, // a probe lies inside (or on) a light's volume (lights.h)
  OutOfRange,       // a result does not fit its output type (Unity's float32 coefficients)
};

struct [[nodiscard]] Status {
  Errc code = Errc::Ok;
  const char* what = "ok";  // static literal, never owned
  std::uint32_t x = 0, y = 0, face = 0;  // where, for texel errors

  constexpr bool ok() const noexcept { return code == Errc::Ok; }
  static constexpr Status success() noexcept { return {}; }
  static constexpr Status error(Errc c, const char* w, std::uint32_t x = 0,
                                std::uint32_t y = 0, std::uint32_t face = 0) noexcept {
    return {c, w, x, y, face};
  }
};

// A short stable name for an error code ("nonfinite_texel", ...), for messages and logs.
const char* errc_name(Errc code) noexcept;

}  // namespace shpack
