#include "shpack/status.h"

namespace shpack {

const char* errc_name(Errc code) noexcept {
  switch (code) {
    case Errc::Ok: return "ok";
    case Errc::InvalidArgument: return "invalid_argument";
    case Errc::BadView: return "bad_view";
    case Errc::NonFiniteTexel: return "nonfinite_texel";
    case Errc::BadSequence: return "bad_sequence";
    case Errc::OutOfMemory: return "out_of_memory";
    case Errc::ProbeInsideLight: return "probe_inside_light";
    case Errc::OutOfRange: return "out_of_range";
  }
  return "unknown";
}

}  // namespace shpack
