#include "shpack/pipeline.h"

#include <cmath>

#include "shpack/convolution.h"
#include "shpack/rotate.h"
#include "shpack/unity_pack.h"

namespace shpack {
Status check_finish_options(const FinishOptions& options) noexcept {
  if (!std::isfinite(options.intensity) || options.intensity < 0)
    return Status::error(Errc::InvalidArgument, "intensity must be finite and >= 0");
  if (!std::isfinite(options.rotate_deg))
    return Status::error(Errc::InvalidArgument, "rotation must be a finite number of degrees");
  return Status::success();
}

Status finish_projection(const ShL2& projected_radiance, const FinishOptions& options, FinishedSh& out) noexcept {
  if (Status st = check_finish_options(options); !st.ok()) return st;
  FinishedSh result;
  const ShL2 radiance = rotate_about_y(scaled(projected_radiance, options.intensity), options.rotate_deg);
  if (Status st = apply_window(radiance_to_unity_form(radiance), options.window, result.unity_form, &result.window);
      !st.ok())
    return st;
  result.radiance = apply_band_factors(radiance, result.window.factors);
  if (!fits_unity_float32(result.unity_form))
    return Status::error(Errc::OutOfRange, "the lighting is too bright for Unity's float32 coefficients");
  for (int c = 0; c < kChannelCount; ++c) result.min_e_over_pi[c] = minimum_on_sphere(result.unity_form, c);
  out = result;
  return Status::success();
}

}  // namespace shpack
