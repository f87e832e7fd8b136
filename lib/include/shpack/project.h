// project.h - projection of an equirectangular radiance image onto L2 SH.
//
// Contract. The image is taken for what it is: radiance that is constant over each texel
// (conventions.h gives each texel's patch of the sphere). The result is the radiance
// coefficients L_c,i = int L_c(w) Y_i(w) dw in Unity's frame (sh_basis.h), in double.
//
// Methods:
//  - SamplingMethod::Exact (default): every basis polynomial is integrated over every texel in
//    closed form, separately in theta and longitude, so the projection of the piecewise-
//    constant image has no quadrature error at all: a 1x1 image is a uniform environment,
//    a 2x1 image two exact hemispheres, a bright pole texel exactly its own integral.
//  - SamplingMethod::Center: the basis at the texel centre times the texel's exact solid angle,
//    the rule of most other tools; its error falls as h^2 on smooth input.
//
// Numerics. Texel values are summed in double along each row against per-column tables,
// rows are combined with Neumaier's compensated sum, in fixed tiles of kTileRows rows that
// are reduced in tile order, so the result is bit-identical for any thread count and any
// way of splitting the rows into add_rows calls.
//
// Memory. EquirectProjector allocates its column tables (4 doubles per column) in begin();
// nothing else is allocated except worker threads when ProjectOptions::threads != 1.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "shpack/image_view.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

// How a map is projected: the closed-form rules of this header (Exact, Center), which every
// layout has, and the sampling rules of other tools (sampling_methods.h), for comparison.
enum class SamplingMethod : std::uint8_t {
  Exact,            // "exact": closed-form texel integrals (project.h)
  Center,           // "center": basis at texel centres (project.h)
  Mip,              // "mip:K"
  MonteCarlo,       // "mc:N"
  QuasiMonteCarlo,  // "qmc:N"
  Fibonacci,        // "fib:N"
  Importance,       // "is:N"
  Riemann,          // "riemann:N"
  CubeThreeJs,      // "cube:N"
  CubeExact,        // "cube-exact:N"
  LeastSquares,     // "lsq:N"
};

// A texel with a NaN or Inf channel: fail with Errc::NonFiniteTexel, or replace each
// non-finite channel value by 0 (its finite channels are kept). Counted either way.
enum class NonFinite : std::uint8_t { Error, Zero };
// A texel with a finite negative channel: keep it (it is radiance as the file says; lossy
// compression makes small negatives), or replace each negative channel value by 0.
enum class Negative : std::uint8_t { Keep, Clamp };

struct ProjectOptions {
  // The closed-form projectors (this header, project_cube.h, project_sphere_map.h) take
  // Exact or Center and refuse the others with InvalidArgument; project_with_method
  // (sampling_methods.h) takes its MethodSpec instead.
  SamplingMethod method = SamplingMethod::Exact;
  NonFinite nonfinite = NonFinite::Error;
  Negative negative = Negative::Keep;
  unsigned threads = 1;  // worker threads; 0 = std::thread::hardware_concurrency()
};

// What the projection saw. Counts are of texels (a texel counts once whatever its
// channels), over the R, G, B channels that are projected.
struct ProjectStats {
  std::uint64_t nonfinite_texels = 0;  // at least one NaN or Inf channel
  std::uint64_t negative_texels = 0;   // at least one finite negative channel
  std::uint32_t first_nonfinite_x = 0, first_nonfinite_y = 0;  // valid if nonfinite_texels
  double max_value = 0;                // largest finite channel value (0 if none positive)
  // project_cube: the face (CubeFace order) of the first NaN/Inf texel, whose face-local
  // coordinates first_nonfinite_x, _y are; 0 for the other projections.
  std::uint32_t first_nonfinite_face = 0;
};

inline constexpr std::uint32_t kTileRows = 64;

// Streaming projection: begin() with the full image size, then add_rows() with
// consecutive bands of rows from the top (any band heights), then finish(). Memory is
// bounded by the caller's band, so a 16384 x 8192 map can be read scanline by scanline.
class EquirectProjector {
 public:
  EquirectProjector() noexcept;
  ~EquirectProjector();
  EquirectProjector(const EquirectProjector&) = delete;
  EquirectProjector& operator=(const EquirectProjector&) = delete;

  Status begin(std::uint32_t width, std::uint32_t height, const ProjectOptions& options) noexcept;
  // `rows` holds image rows [first_row, first_row + rows.height); first_row must be the
  // next row expected. rows.width must equal the image width.
  Status add_rows(const ImageView& rows, std::uint32_t first_row) noexcept;
  // Radiance coefficients; valid once every row was added.
  Status finish(ShL2& radiance, ProjectStats* stats = nullptr) noexcept;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// One-shot projection of a whole image.
Status project_equirect(const ImageView& image, const ProjectOptions& options, ShL2& radiance,
                        ProjectStats* stats = nullptr) noexcept;

}  // namespace shpack
