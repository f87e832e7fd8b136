// engine_frame_test.cpp - the frames of other engines (engine_frame.h): the mapped
// coefficients describe the same function, and a light from a known Unity direction ends up
// on the axis each engine's own axes put it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "shpack/engine_frame.h"
#include "shpack/sh_basis.h"
#include "support/sphere_points.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

using shpack::Dir3;
using shpack::EngineFrame;
using shpack::kShCount;

constexpr std::array<EngineFrame, 6> kFrames = {EngineFrame::Unity,   EngineFrame::ThreeJs, EngineFrame::Gltf,
                                                EngineFrame::Unreal,  EngineFrame::Blender, EngineFrame::Filament};

// sum_i c_i s_i Y_i(d): the function the engine's basis (with its signs s) makes of c.
double eval_in_engine(EngineFrame frame, const std::array<double, kShCount>& c, const Dir3& d) {
  const std::array<double, kShCount> y = shpack::eval_basis(d.x, d.y, d.z);
  const auto& sign = shpack::engine_frame_spec(frame).basis_sign;
  double sum = 0;
  for (int i = 0; i < kShCount; ++i) sum += c[i] * sign[i] * y[i];
  return sum;
}

// The mapped coefficients are the same function: g(A d) = f(d). Each side sums 9 terms of
// size <= |c| |Y| <= 1 * 1.1 with a few roundings each (the 6/8 mix adds 4), so the two
// agree within 9 * 1.1 * 8u < 1e-14; 1e-13 leaves room for libm-free arithmetic reordering.
TEST(EngineFrame, MappedCoefficientsAreTheSameFunction) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> coefficient(-1.0, 1.0);
  for (const EngineFrame frame : kFrames) {
    for (int trial = 0; trial < 50; ++trial) {
      std::array<double, kShCount> c;
      for (double& v : c) v = coefficient(rng);
      const std::array<double, kShCount> mapped = shpack::sh_to_engine_frame(frame, c);
      for (int k = 0; k < 20; ++k) {
        const Dir3 d = random_direction(rng);
        const double unity = eval_in_engine(EngineFrame::Unity, c, d);
        const double engine = eval_in_engine(frame, mapped, shpack::to_engine_frame(frame, d));
        ASSERT_NEAR(unity, engine, 1e-13) << shpack::engine_frame_spec(frame).name << " d=" << d;
      }
    }
  }
}

// Where each engine's axes put Unity's right (+X), up (+Y) and forward (+Z): the statements
// of docs/conventions.md, written out as vectors.
struct AxesCase {
  EngineFrame frame;
  Dir3 right, up, forward;
};
constexpr std::array<AxesCase, 6> kAxes = {{
    {EngineFrame::Unity, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
    {EngineFrame::ThreeJs, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}},  // the camera's view: -Z ahead
    {EngineFrame::Gltf, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},     // glTF 2.0: +Z forward, -X right
    {EngineFrame::Unreal, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}},    // X forward, Y right, Z up
    {EngineFrame::Blender, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   // front view: +Y ahead, Z up
    {EngineFrame::Filament, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}},  // cmgen's mirrored output
}};

// A directional light of irradiance E from Unity direction d has L_i = E Y_i(d)
// (docs/conventions.md section 5); its L2 irradiance E(n)/pi = E sum_i (A_l/pi) Y_i(d) Y_i(n)
// is largest at n = d. Mapped to the engine it must be largest, with the same value, on the
// engine axis the table names, and take Unity's value at -d on the opposite axis.
double e_over_pi(EngineFrame frame, const std::array<double, kShCount>& radiance, const Dir3& n) {
  std::array<double, kShCount> irradiance = radiance;
  for (int i = 0; i < kShCount; ++i) irradiance[i] *= shpack::kCosineLobeOverPi[shpack::kBand[i]];
  return eval_in_engine(frame, irradiance, n);
}

TEST(EngineFrame, LightFromKnownDirectionLandsOnTheEnginesAxis) {
  for (const AxesCase& axes : kAxes) {
    const char* name = shpack::engine_frame_spec(axes.frame).name;
    const std::array<std::pair<Dir3, Dir3>, 3> cases = {
        {{{1, 0, 0}, axes.right}, {{0, 1, 0}, axes.up}, {{0, 0, 1}, axes.forward}}};
    for (const auto& [unity_dir, engine_dir] : cases) {
      std::array<double, kShCount> light = shpack::eval_basis(unity_dir.x, unity_dir.y, unity_dir.z);
      for (double& v : light) v *= 2.5;  // E = 2.5
      const std::array<double, kShCount> mapped = shpack::sh_to_engine_frame(axes.frame, light);
      const Dir3 opposite = {-engine_dir.x, -engine_dir.y, -engine_dir.z};
      const Dir3 unity_opposite = {-unity_dir.x, -unity_dir.y, -unity_dir.z};
      // Sums of 9 terms below 2.5 * 1.2: 1e-14 is ~20 ulp of the peak (~1.1).
      EXPECT_NEAR(e_over_pi(EngineFrame::Unity, light, unity_dir), e_over_pi(axes.frame, mapped, engine_dir), 1e-14)
          << name << " light from " << unity_dir;
      EXPECT_NEAR(e_over_pi(EngineFrame::Unity, light, unity_opposite), e_over_pi(axes.frame, mapped, opposite), 1e-14)
          << name << " light from " << unity_dir;
      EXPECT_EQ(engine_dir, shpack::to_engine_frame(axes.frame, unity_dir)) << name;
    }
  }
}

// three.js users did by hand what --frame threejs does: negate indices 2, 5, 7 (the z mirror
// of conventions.h); glTF's x mirror negates 3 (x), 4 (xy) and 7 (xz). Both are exact.
TEST(EngineFrame, MirrorsAreSignChangesOnly) {
  std::array<double, kShCount> c;
  for (int i = 0; i < kShCount; ++i) c[i] = 1.0 + i;
  const std::array<double, kShCount> three = shpack::sh_to_engine_frame(EngineFrame::ThreeJs, c);
  const std::array<double, kShCount> gltf = shpack::sh_to_engine_frame(EngineFrame::Gltf, c);
  constexpr std::array<double, kShCount> kMirrorX = {1, 1, 1, -1, -1, 1, 1, -1, 1};
  for (int i = 0; i < kShCount; ++i) {
    EXPECT_EQ(shpack::kMirrorZSign[i] * c[i], three[i]) << i;
    EXPECT_EQ(kMirrorX[i] * c[i], gltf[i]) << i;
  }
  EXPECT_EQ(c, shpack::sh_to_engine_frame(EngineFrame::Unity, c));
}

// Unreal's SHBasisFunction3 (SHCommon.ush) writes V0 = (0.282095, -0.488603 y, 0.488603 z,
// -0.488603 x): a light straight up in Unreal (+Z, Unity's +Y) has a positive index 2 and
// zero 1 and 3; a light from Unreal +X (Unity +Z) has a NEGATIVE index 3.
TEST(EngineFrame, UnrealUsesCondonShortleySigns) {
  const std::array<double, kShCount> up = shpack::sh_to_engine_frame(EngineFrame::Unreal, shpack::eval_basis(0, 1, 0));
  EXPECT_NEAR(up[2], shpack::kY1, 1e-16);
  EXPECT_EQ(up[1], 0.0);
  EXPECT_EQ(up[3], 0.0);
  const std::array<double, kShCount> ahead =
      shpack::sh_to_engine_frame(EngineFrame::Unreal, shpack::eval_basis(0, 0, 1));
  EXPECT_NEAR(ahead[3], -shpack::kY1, 1e-16);
}

}  // namespace
}  // namespace shpack_test
