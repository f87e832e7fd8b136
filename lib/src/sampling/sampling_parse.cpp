// SamplingMethod names: validate_method, parse_method, method_name (sampling_methods.h).
#include <algorithm>
#include <charconv>
#include <system_error>

#include "shpack/sampling_methods.h"

namespace shpack {
namespace {

struct NamedMethod {
  std::string_view name;
  SamplingMethod method;
};

// The spelling of every method, in SamplingMethod order.
constexpr NamedMethod kNames[] = {
    {"exact", SamplingMethod::Exact},
    {"center", SamplingMethod::Center},
    {"mip", SamplingMethod::Mip},
    {"mc", SamplingMethod::MonteCarlo},
    {"qmc", SamplingMethod::QuasiMonteCarlo},
    {"fib", SamplingMethod::Fibonacci},
    {"is", SamplingMethod::Importance},
    {"riemann", SamplingMethod::Riemann},
    {"cube", SamplingMethod::CubeThreeJs},
    {"cube-exact", SamplingMethod::CubeExact},
    {"lsq", SamplingMethod::LeastSquares},
};

constexpr bool names_in_enum_order() noexcept {
  for (std::size_t i = 0; i < std::size(kNames); ++i)
    if (kNames[i].method != static_cast<SamplingMethod>(i)) return false;
  return true;
}
static_assert(names_in_enum_order(), "method_name indexes kNames by SamplingMethod");

constexpr bool has_param(SamplingMethod m) noexcept {
  return m != SamplingMethod::Exact && m != SamplingMethod::Center;
}

// A whole decimal unsigned number: digits only, no sign, no spaces, no overflow.
template <class T>
bool parse_decimal(std::string_view text, T& value) noexcept {
  if (text.empty()) return false;
  for (char ch : text)
    if (ch < '0' || ch > '9') return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

Status validate_method(const MethodSpec& spec) noexcept {
  switch (spec.method) {
    case SamplingMethod::Exact:
    case SamplingMethod::Center:
      if (spec.param != 0)
        return Status::error(Errc::InvalidArgument, "exact and center take no parameter");
      return Status::success();
    case SamplingMethod::Mip:
      if (spec.param > 31) return Status::error(Errc::InvalidArgument, "mip:K needs 0 <= K <= 31");
      return Status::success();
    case SamplingMethod::LeastSquares:
      if (spec.param < kShCount) return Status::error(Errc::InvalidArgument, "lsq:N needs N >= 9");
      return Status::success();
    case SamplingMethod::Riemann:
    case SamplingMethod::CubeThreeJs:
    case SamplingMethod::CubeExact:
      if (spec.param > kMaxGridParam)
        return Status::error(Errc::InvalidArgument, "riemann:N and cube:N need N <= 2^30");
      [[fallthrough]];
    case SamplingMethod::MonteCarlo:
    case SamplingMethod::QuasiMonteCarlo:
    case SamplingMethod::Fibonacci:
    case SamplingMethod::Importance:
      if (spec.param < 1)
        return Status::error(Errc::InvalidArgument, "the sample count N must be >= 1");
      return Status::success();
  }
  return Status::error(Errc::InvalidArgument, "unknown sampling method");
}

Status parse_method(std::string_view text, MethodSpec& spec) noexcept {
  const std::size_t colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  const NamedMethod* found = nullptr;
  for (const NamedMethod& m : kNames)
    if (m.name == name) found = &m;
  if (found == nullptr) return Status::error(Errc::InvalidArgument, "unknown method name");

  MethodSpec parsed;
  parsed.method = found->method;
  if (has_param(parsed.method)) {
    if (colon == std::string_view::npos)
      return Status::error(Errc::InvalidArgument, "method needs a parameter, e.g. mc:4096");
    std::string_view rest = text.substr(colon + 1);
    const std::size_t colon2 = rest.find(':');
    if (colon2 != std::string_view::npos) {
      if (!uses_seed(parsed.method))
        return Status::error(Errc::InvalidArgument, "only mc, qmc and is take a seed");
      if (!parse_decimal(rest.substr(colon2 + 1), parsed.seed))
        return Status::error(Errc::InvalidArgument, "seed is not a decimal uint64");
      rest = rest.substr(0, colon2);
    }
    if (!parse_decimal(rest, parsed.param))
      return Status::error(Errc::InvalidArgument, "method parameter is not a decimal uint32");
  } else if (colon != std::string_view::npos) {
    return Status::error(Errc::InvalidArgument, "exact and center take no parameter");
  }
  if (Status st = validate_method(parsed); !st.ok()) return st;
  spec = parsed;
  return Status::success();
}

MethodName method_name(const MethodSpec& spec) noexcept {
  MethodName out;
  const auto index = static_cast<std::size_t>(spec.method);
  const std::string_view name = index < std::size(kNames) ? kNames[index].name : "unknown";
  char* p = out.text.data();
  char* const end = p + out.text.size() - 1;  // keep room for the NUL
  p = std::copy(name.begin(), name.end(), p);
  if (index < std::size(kNames) && has_param(spec.method)) {
    *p++ = ':';
    p = std::to_chars(p, end, spec.param).ptr;
    if (uses_seed(spec.method) && spec.seed != kDefaultMethodSeed) {
      *p++ = ':';
      p = std::to_chars(p, end, spec.seed).ptr;
    }
  }
  *p = '\0';
  return out;
}

}  // namespace shpack
