#include "shpack/study/method_sweep.h"

#include <algorithm>
#include <string>

namespace shpack::study {
namespace {

constexpr SamplingMethod kAllMethods[] = {
    SamplingMethod::Exact,      SamplingMethod::Center,         SamplingMethod::Mip,
    SamplingMethod::MonteCarlo, SamplingMethod::QuasiMonteCarlo, SamplingMethod::Fibonacci,
    SamplingMethod::Importance, SamplingMethod::Riemann,        SamplingMethod::CubeThreeJs,
    SamplingMethod::CubeExact,  SamplingMethod::LeastSquares,
};

std::vector<std::uint32_t> sweep_params(SamplingMethod method, bool quick) {
  switch (method) {
    case SamplingMethod::Exact:
    case SamplingMethod::Center:
      return {0};
    case SamplingMethod::Mip:
      return quick ? std::vector<std::uint32_t>{5, 3, 1} : std::vector<std::uint32_t>{6, 5, 4, 3, 2, 1};
    case SamplingMethod::Riemann:
    case SamplingMethod::CubeThreeJs:
    case SamplingMethod::CubeExact:
      return quick ? std::vector<std::uint32_t>{8, 32, 128}
                   : std::vector<std::uint32_t>{8, 16, 32, 64, 128, 256, 512};
    case SamplingMethod::MonteCarlo:
    case SamplingMethod::QuasiMonteCarlo:
    case SamplingMethod::Fibonacci:
    case SamplingMethod::Importance:
    case SamplingMethod::LeastSquares:
      break;
  }
  return quick ? std::vector<std::uint32_t>{64, 1024, 16384}
               : std::vector<std::uint32_t>{64, 256, 1024, 4096, 16384, 65536, 262144};
}

}  // namespace

std::string family_name(SamplingMethod method) {
  // method_name spells the family before the ':' of its parameter.
  const MethodName name = method_name({method, 0, kDefaultMethodSeed});
  const std::string_view text = name.view();
  return std::string(text.substr(0, text.find(':')));
}

std::vector<MethodSpec> method_sweep(SamplingMethod method, bool quick, std::uint64_t seed) {
  std::vector<MethodSpec> specs;
  for (const std::uint32_t param : sweep_params(method, quick)) specs.push_back({method, param, seed});
  return specs;
}

std::vector<MethodSpec> full_sweep(bool quick, std::uint64_t seed) {
  std::vector<MethodSpec> specs;
  for (const SamplingMethod method : kAllMethods) {
    const std::vector<MethodSpec> sweep = method_sweep(method, quick, seed);
    specs.insert(specs.end(), sweep.begin(), sweep.end());
  }
  return specs;
}

Status parse_method_list(std::string_view list, bool quick, std::uint64_t seed,
                         std::vector<MethodSpec>& out) {
  std::vector<MethodSpec> specs;
  while (true) {
    const std::size_t comma = list.find(',');
    const std::string_view item = list.substr(0, comma);
    if (item.empty()) return Status::error(Errc::InvalidArgument, "empty item in the method list");
    const auto family = std::find_if(std::begin(kAllMethods), std::end(kAllMethods),
                                     [&](SamplingMethod m) { return family_name(m) == item; });
    if (family != std::end(kAllMethods)) {
      const std::vector<MethodSpec> sweep = method_sweep(*family, quick, seed);
      specs.insert(specs.end(), sweep.begin(), sweep.end());
    } else {
      MethodSpec spec;
      spec.seed = seed;  // "mc:N:SEED" overrides it
      if (Status st = parse_method(item, spec); !st.ok()) return st;
      specs.push_back(spec);
    }
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
  out = std::move(specs);
  return Status::success();
}

double sample_count(const MethodSpec& spec, std::uint32_t width, std::uint32_t height) noexcept {
  const double n = spec.param;
  switch (spec.method) {
    case SamplingMethod::Exact:
    case SamplingMethod::Center:
      return double(width) * height;
    case SamplingMethod::Mip:
      return double(std::max(1u, width >> std::min(spec.param, 31u))) *
             std::max(1u, height >> std::min(spec.param, 31u));
    case SamplingMethod::Riemann: return 2 * n * n;
    case SamplingMethod::CubeThreeJs:
    case SamplingMethod::CubeExact: return 6 * n * n;
    case SamplingMethod::MonteCarlo:
    case SamplingMethod::QuasiMonteCarlo:
    case SamplingMethod::Fibonacci:
    case SamplingMethod::Importance:
    case SamplingMethod::LeastSquares:
      break;
  }
  return n;
}

}  // namespace shpack::study
