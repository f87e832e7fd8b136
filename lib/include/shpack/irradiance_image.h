// irradiance_image.h - E/pi of a map as an image (`shpack irradiance`), so that a user sees
// what L2 keeps and loses, and how the seeds' irradiance maps converge.
//
// Each output texel holds E(d)/pi at its centre direction d (Unity's frame, conventions.h:
// the equirect mapping, or a cube face's D3D axes; cells of a cross that hold no face are 0),
// from one source:
//   Sh          what Unity's shader shows: shade_sh9 (unity_pack.h) of the finished L2 SH of
//               the map (pipeline.h, the conversion's options), in float, as Unity evaluates it.
//   Exact       the cosine convolution of the map's piecewise-constant texels, from the
//               reference of view_reference.h: exact where a cell of texels lies wholly on one
//               side of d's horizon, and within a stated bound where the horizon cuts it;
//               IrradianceImage::bound is the largest bound over the texels and channels.
//   Riemann N   the seeds' Riemann sum over a lat-long grid of n x 2n cell centres w_k,
//               n = max(1, round(sqrt(N / 2))), with the cells' exact solid angles dW_k:
//                 E(d)/pi = (1/pi) sum_k L(w_k) max(0, d . w_k) dW_k
//   MonteCarlo N  N directions w_k uniform on the sphere (std::mt19937_64 seeded by `seed`,
//               detail::sphere_point), the same for every texel:
//                 E(d)/pi = (4/N) sum_k L(w_k) max(0, d . w_k)          (pdf 1/(4 pi))
// where L(w) is the texel of an equirect map that w falls in (sampling_methods.h
// equirect_texel), under the conversion's value policies; Riemann and MonteCarlo read
// equirect maps only, as the sampling methods of `convert` do. Exact, Riemann and MonteCarlo
// apply the finish options as Sh gets them (pipeline.h): the value at d is the map's at R^T d
// for the rotation R, times the colour matrix and the intensity.
//
// Cost per output texel: Sh 9 multiply-adds; Exact a walk of the reference's tree (about
// 15 us); Riemann and MonteCarlo N multiply-adds. Texels are spread over `threads` threads
// by rows; the image does not depend on their number.
#pragma once

#include <cstdint>
#include <vector>

#include "shpack/layout.h"
#include "shpack/pipeline.h"
#include "shpack/status.h"

namespace shpack {

enum class IrradianceSource : std::uint8_t { Sh, Exact, Riemann, MonteCarlo };

struct IrradianceRequest {
  IrradianceSource source = IrradianceSource::Exact;
  std::uint32_t samples = 0;     // N of Riemann and MonteCarlo, >= 1
  std::uint64_t seed = 0;        // MonteCarlo
  Layout layout = Layout::Equirect;  // the output's: equirect or a single-image cube layout
  std::uint32_t size = 128;      // equirect: height (width 2 size); cubes: the face's side
  unsigned threads = 1;          // 0: all cores
};

struct IrradianceImage {
  std::uint32_t width = 0, height = 0;
  std::vector<float> rgb;  // packed RGB, row 0 at the top
  double bound = 0;        // Exact: the largest bound of any texel's E/pi; else 0
};

// The output's size and the direction of each texel centre (row-major); `used` is 0 for the
// texels of a cross's empty cells. Errors: InvalidArgument for a layout that is not equirect
// or a single-image cube layout, or a size that is 0 or makes an image over 2^26 texels.
Status irradiance_directions(Layout layout, std::uint32_t size, std::uint32_t& width, std::uint32_t& height,
                             std::vector<Dir3>& directions, std::vector<std::uint8_t>& used) noexcept;

// The image of `map` (stage 1's, with writable pixels for the options' transforms) from the
// request's source. Errors: InvalidArgument (a request out of its domain, Riemann or
// MonteCarlo on a map that is not equirect), those of convert_map and build_view_reference,
// OutOfMemory.
Status render_irradiance(const MapImage& map, const ConvertOptions& options, const IrradianceRequest& request,
                         IrradianceImage& out) noexcept;

}  // namespace shpack
