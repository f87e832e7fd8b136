// baseline_projection.h - the plain per-texel projection that shpack's exact path is
// measured against (the speed targets of docs/accuracy.md): for every texel the direction
// from sin/cos, the 9 basis values, the exact solid angle, double accumulation; no tables,
// no SIMD, no threads.
// It is the code a careful engineer writes first, kept only as a speed reference.
#pragma once

#include "shpack/image_view.h"
#include "shpack/sh_basis.h"

namespace shpack::bench {

// `rgb` is a tightly packed float RGB image; returns radiance coefficients (centre rule).
ShL2 baseline_project(const float* rgb, unsigned width, unsigned height);

}  // namespace shpack::bench
