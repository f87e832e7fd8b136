// environment.h (private) - the scene's environment: its SH, projected once, and its radiance
// in one direction (for the effects that trace rays).
#pragma once

#include <vector>

#include "shpack/io/image_file.h"
#include "shpack/io/io_status.h"
#include "shpack/rotate.h"
#include "direction_distribution.h"
#include "shpack/scene/scene.h"
#include "tracer.h"

namespace shpack::bake {

class EnvironmentSource {
 public:
  // Projects the environment (an env map through the pipeline, io/convert.h, exactly as
  // `shpack convert` does: its colour space, intensity and rotation; a gradient or Preetham
  // sky in closed form). With `need_lookup`, an env map's pixels are also kept for
  // radiance(), in the same primaries. Errors name the scene file and the map.
  io::IoStatus load(const scene::Scene& scene, bool need_lookup, unsigned threads);

  const ShL2& sh() const noexcept { return sh_; }

  // Radiance arriving from unit direction d (Unity's frame): the texel of the rotated map that
  // contains d (the map is piecewise constant, as its projection takes it), or the gradient.
  Rgb radiance(const Vec3d& d) const noexcept;

  // Directions drawn by brightness (direction_distribution.h), for next-event estimation
  // toward the environment; built by load() with `need_lookup`. Empty for no environment.
  const DirectionDistribution& distribution() const noexcept { return distribution_; }

 private:
  void build_distribution();

  scene::SceneEnvironment env_;
  ShL2 sh_;
  io::ImageFile image_;
  Matrix3 rotation_{};  // R_y of the map's rotation; radiance(d) reads the map at R^T d
  DirectionDistribution distribution_;
};

}  // namespace shpack::bake
