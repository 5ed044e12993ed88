#include "optics/media.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/phase.hpp"

namespace airlight::optics {
namespace {

// Medium σt = 0.1 (σs 0.06 + σa 0.04); unit box [0,1]³ with σs 0.5, σa 0.25, HG 0.5.
Scene foggy_box() {
  Scene s;
  s.medium.sigma_s = glm::vec3(0.0625f);
  s.medium.sigma_a = glm::vec3(0.0375f);
  Volume v;
  v.min = {0, 0, 0};
  v.max = {1, 1, 1};
  v.sigma_s = {0.5f, 0.25f, 0.0f};
  v.sigma_a = glm::vec3(0.25f);
  v.phase.lobes = {PhaseLobe{PhaseType::henyey_greenstein, 0.5f, 1.0f}};
  s.volumes.push_back(v);
  return s;
}

// Hand computations; 1e-6 absolute: the coefficients are floats.
TEST(Media, OpticalDepthThroughABox) {
  const Scene s = foggy_box();
  // Along x through the box: 4 m of medium + 1 m of box.
  const glm::dvec3 tau = optical_depth(s, {-1, 0.5, 0.5}, {3, 0.5, 0.5});
  EXPECT_NEAR(tau.x, 4 * 0.1 + 0.75, 1e-6);
  EXPECT_NEAR(tau.y, 4 * 0.1 + 0.5, 1e-6);
  EXPECT_NEAR(tau.z, 4 * 0.1 + 0.25, 1e-6);
  // Diagonal corner to corner and beyond: √3 inside the box, 2√3 in all.
  const glm::dvec3 d = optical_depth(s, {0, 0, 0}, {2, 2, 2});
  EXPECT_NEAR(d.x, 2 * std::sqrt(3.0) * 0.1 + std::sqrt(3.0) * 0.75, 1e-6);
  // Ending inside the box.
  EXPECT_NEAR(optical_depth(s, {0.5, -1, 0.5}, {0.5, 0.5, 0.5}).x, 1.5 * 0.1 + 0.5 * 0.75, 1e-6);
  EXPECT_EQ(optical_depth(s, {2, 2, 2}, {2, 2, 2}), glm::dvec3(0.0));
}

TEST(Media, LightLegs) {
  Scene s = foggy_box();
  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0, -1, 0};
  // Only bounded volumes absorb sunlight (docs/design.md §1): from below the box up through it.
  EXPECT_NEAR(light_leg_depth(s, sun, {0.5, -3, 0.5}).x, 0.75, 1e-6);
  EXPECT_EQ(light_leg_depth(s, sun, {3, -3, 0.5}), glm::dvec3(0.0));
  Light point;
  point.position = {0.5, 2, 0.5};
  EXPECT_NEAR(light_leg_depth(s, point, {0.5, -1, 0.5}).x, 3 * 0.1 + 0.75, 1e-6);
  s.light_model.type = LightModelType::simplified;  // Nilsson eq. 2.15: T = 1
  EXPECT_EQ(light_leg_depth(s, point, {0.5, -1, 0.5}), glm::dvec3(0.0));
  EXPECT_EQ(eye_leg_depth(s, {0.5, -1, 0.5}, {0.5, 3, 0.5}), glm::dvec3(0.0));
}

TEST(Media, BeamLegRunsBackToTheAperture) {
  Scene s = foggy_box();
  // A beam down through the box, its aperture at y = 3 (σt medium 0.1, box 0.75).
  Light beam;
  beam.type = LightType::directional;
  beam.direction = {0, -1, 0};
  beam.gobo_up = {0, 0, 1};
  beam.beam = Beam{{0.5f, 3.0f, 0.5f}, {4.0f, 4.0f}, 10.0f};
  // Below the box: 4 m from the aperture, 1 m of them in the box.
  EXPECT_NEAR(light_leg_depth(s, beam, {0.5, -1, 0.5}).x, 4 * 0.1 + 0.75, 1e-6);
  // Inside the box: 2.5 m from the aperture, the top 0.5 m of the box.
  EXPECT_NEAR(light_leg_depth(s, beam, {0.5, 0.5, 0.5}).x, 2.5 * 0.1 + 0.5 * 0.75, 1e-6);
  // Off the axis, beside the box: medium only.
  EXPECT_NEAR(light_leg_depth(s, beam, {2, -1, 2}).x, 4 * 0.1, 1e-6);
  // At the aperture and upstream of it (where the beam sends nothing): no leg.
  EXPECT_EQ(light_leg_depth(s, beam, {0.5, 3, 0.5}), glm::dvec3(0.0));
  EXPECT_EQ(light_leg_depth(s, beam, {0.5, 5, 0.5}), glm::dvec3(0.0));
  // A volume upstream of the aperture absorbs nothing of the beam...
  Volume above = s.volumes[0];
  above.min = {0, 4, 0};
  above.max = {1, 5, 1};
  s.volumes.push_back(above);
  EXPECT_NEAR(light_leg_depth(s, beam, {0.5, -1, 0.5}).x, 4 * 0.1 + 0.75, 1e-6);
  // ...but everything of an unbounded sun (docs/design.md §1: volumes only, to infinity).
  Light sun = beam;
  sun.beam.reset();
  EXPECT_NEAR(light_leg_depth(s, sun, {0.5, -1, 0.5}).x, 2 * 0.75, 1e-6);
  s.light_model.type = LightModelType::simplified;  // Nilsson eq. 2.15: T = 1
  EXPECT_EQ(light_leg_depth(s, beam, {0.5, -1, 0.5}), glm::dvec3(0.0));
}

TEST(Media, ScatteringAddsVolumes) {
  Scene s = foggy_box();
  const double iso = 1.0 / (4.0 * std::numbers::pi);
  const double hg = phase(s.volumes[0].phase, 0.3);
  EXPECT_NEAR(scattering(s, {2, 2, 2}, 0.3).x, 0.0625 * iso, 1e-9);
  EXPECT_NEAR(scattering(s, {0.5, 0.5, 0.5}, 0.3).x, 0.0625 * iso + 0.5 * hg, 1e-7);
  s.light_model.type = LightModelType::simplified;  // medium only, isotropic (eq. 2.14)
  EXPECT_NEAR(scattering(s, {0.5, 0.5, 0.5}, 0.3).x, 0.0625 * iso, 1e-9);
}

TEST(Media, VolumeCrossingsAreSortedInsideTheRange) {
  Scene s = foggy_box();
  Volume v2 = s.volumes[0];
  v2.min = {3, 0, 0};
  v2.max = {4, 1, 1};
  s.volumes.push_back(v2);
  const auto t = volume_crossings(s, {-1, 0.5, 0.5}, {1, 0, 0}, 0.0, 5.5);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_NEAR(t[0], 1.0, 1e-12);
  EXPECT_NEAR(t[1], 2.0, 1e-12);
  EXPECT_NEAR(t[2], 4.0, 1e-12);
  EXPECT_NEAR(t[3], 5.0, 1e-12);
  EXPECT_EQ(volume_crossings(s, {-1, 0.5, 0.5}, {1, 0, 0}, 1.5, 3.9).size(), 1u);
}

}  // namespace
}  // namespace airlight::optics
