// sphere_points.h - deterministic, well-spread unit vectors for tests.
#pragma once

#include <random>
#include <vector>

#include "shpack/conventions.h"

namespace shpack_test {

// Spherical Fibonacci points: z_k = 1 - (2k + 1)/n, azimuth k * golden angle. Every
// octant and both poles' neighbourhoods are covered; no point lies on a coordinate plane
// by construction for n >= 8, so sign tests see all three axes.
std::vector<shpack::Dir3> fibonacci_sphere(int n);

// A direction uniformly distributed on the sphere (normalised Gaussian vector).
shpack::Dir3 random_direction(std::mt19937_64& rng);

}  // namespace shpack_test
