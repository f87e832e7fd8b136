// project_with_method: resolve, validate, dispatch (sampling_methods.h).
#include "sampling/sampling_projectors.h"

namespace shpack {

Status project_with_method(const ImageView& image, const MethodSpec& spec,
                           const ProjectOptions& options, ShL2& radiance,
                           ProjectStats* stats) noexcept {
  ImageView view = image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  if (Status st = validate_method(spec); !st.ok()) return st;
  ProjectOptions equirect = options;
  switch (spec.method) {
    case SamplingMethod::Exact:
    case SamplingMethod::Center:
      equirect.method = spec.method == SamplingMethod::Exact ? SamplingMethod::Exact : SamplingMethod::Center;
      return project_equirect(view, equirect, radiance, stats);
    case SamplingMethod::Mip:
      return detail::project_mip(view, spec.param, options, radiance, stats);
    case SamplingMethod::MonteCarlo:
    case SamplingMethod::QuasiMonteCarlo:
    case SamplingMethod::Fibonacci:
      return detail::project_point_set(view, spec, options, radiance, stats);
    case SamplingMethod::Importance:
      return detail::project_importance(view, spec.param, spec.seed, options, radiance, stats);
    case SamplingMethod::Riemann:
      return detail::project_riemann(view, spec.param, options, radiance, stats);
    case SamplingMethod::CubeThreeJs:
    case SamplingMethod::CubeExact:
      return detail::project_cube(view, spec.param, spec.method == SamplingMethod::CubeExact,
                                  options, radiance, stats);
    case SamplingMethod::LeastSquares:
      return detail::project_least_squares(view, spec.param, options, radiance, stats);
  }
  return Status::error(Errc::InvalidArgument, "unknown sampling method");
}

}  // namespace shpack
