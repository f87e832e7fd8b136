// method_sweep.h - which methods and parameters `shpack bench` measures.
//
// Each method is swept over about three decades of cost, from too coarse to be useful to
// past the point where its error is below what a user can see:
//   mc, qmc, fib, is, lsq   N = 64, 256, ..., 262144 (x4)      quick: 64, 1024, 16384
//   riemann, cube,          N = 8, 16, ..., 512 (x2)           quick: 8, 32, 128
//   cube-exact
//   mip                     K = 6, 5, ..., 1                   quick: 5, 3, 1
//   exact, center           one run each
// The seed goes to every spec; only mc, qmc and is use it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "shpack/sampling_methods.h"
#include "shpack/status.h"

namespace shpack::study {

// "exact", "mc", "cube-exact", ...: the spelling of parse_method without a parameter.
std::string family_name(SamplingMethod method);

// The specs of one method's sweep, cheapest first.
std::vector<MethodSpec> method_sweep(SamplingMethod method, bool quick, std::uint64_t seed);

// Every method's sweep, in SamplingMethod order.
std::vector<MethodSpec> full_sweep(bool quick, std::uint64_t seed);

// A comma-separated list: a method name alone ("mc") means its sweep, a full spec
// ("mc:4096", "mip:2") that one run. InvalidArgument (what says why) for an empty list or
// item, an unknown name, or a spec that parse_method rejects; `out` is left unchanged then.
Status parse_method_list(std::string_view list, bool quick, std::uint64_t seed,
                         std::vector<MethodSpec>& out);

// The number of radiance values a spec reads for a W x H map: its cost in the convergence
// fits. N for the point methods, 2 N^2 for riemann, 6 N^2 for the cubes, the small map's
// texels for mip, and W H for exact and center.
double sample_count(const MethodSpec& spec, std::uint32_t width, std::uint32_t height) noexcept;

}  // namespace shpack::study
