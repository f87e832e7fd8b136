// sampling_projectors.h (private) - one entry point per method of sampling_methods.h,
// called by project_with_method with a resolved view and a validated spec.
#pragma once

#include <cstdint>

#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/sampling_methods.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack::detail {

// mip:K (sampling_mip.cpp).
Status project_mip(const ImageView& image, std::uint32_t levels, const ProjectOptions& options,
                   ShL2& radiance, ProjectStats* stats) noexcept;

// mc:N, qmc:N, fib:N: equal weights 4 pi / N (sampling_point_sets.cpp).
Status project_point_set(const ImageView& image, const MethodSpec& spec,
                         const ProjectOptions& options, ShL2& radiance,
                         ProjectStats* stats) noexcept;

// is:N (sampling_importance.cpp).
Status project_importance(const ImageView& image, std::uint32_t n, std::uint64_t seed,
                          const ProjectOptions& options, ShL2& radiance,
                          ProjectStats* stats) noexcept;

// riemann:N (sampling_riemann.cpp).
Status project_riemann(const ImageView& image, std::uint32_t n, const ProjectOptions& options,
                       ShL2& radiance, ProjectStats* stats) noexcept;

// cube:N (exact_solid_angle false) and cube-exact:N (sampling_cube.cpp).
Status project_cube(const ImageView& image, std::uint32_t n, bool exact_solid_angle,
                    const ProjectOptions& options, ShL2& radiance, ProjectStats* stats) noexcept;

// lsq:N (sampling_least_squares.cpp).
Status project_least_squares(const ImageView& image, std::uint32_t n, const ProjectOptions& options,
                             ShL2& radiance, ProjectStats* stats) noexcept;

}  // namespace shpack::detail
