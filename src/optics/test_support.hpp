#pragma once
// Scenes and measures shared by the optics tests.
#include <airlight/scene.hpp>
#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <numbers>

namespace airlight::optics::testing {

// A homogeneous isotropic medium filling space and nothing else.
inline Scene homogeneous_scene(float sigma_s, float sigma_a) {
  Scene s;
  s.medium.sigma_s = glm::vec3(sigma_s);
  s.medium.sigma_a = glm::vec3(sigma_a);
  return s;
}

inline Light point_light(const glm::vec3& position, float intensity) {
  Light l;
  l.type = LightType::point;
  l.position = position;
  l.intensity = glm::vec3(intensity);
  return l;
}

// A directional light with a beam (scene.hpp Beam): gobo_up orients its frame.
inline Light beam_light(const glm::vec3& direction, const glm::vec3& gobo_up, const Beam& beam,
                        float irradiance) {
  Light l;
  l.type = LightType::directional;
  l.direction = direction;
  l.gobo_up = gobo_up;
  l.irradiance = glm::vec3(irradiance);
  l.beam = beam;
  return l;
}

// The airlight of an unoccluded beam of irradiance E in a homogeneous medium
// with isotropic phase, along the part [a, b] of a view ray inside the beam:
// σs/(4π)·E·∫_a^b exp(−σt·(t + s(t))) dt, the eye's leg t and the light's leg
// s(t) = s0 + c·t from the aperture (c = view direction · light direction),
// exactly: σs/(4π)·E·exp(−σt·(s0 + (1 + c)·a))·(1 − exp(−k(b − a)))/k with
// k = σt·(1 + c), by expm1 so that k → 0 (looking up the beam) keeps its digits.
inline double beam_airlight(double sigma_s, double sigma_t, double E, double s0, double c, double a,
                            double b) {
  const double k = sigma_t * (1.0 + c);
  const double length = k == 0.0 ? b - a : -std::expm1(-k * (b - a)) / k;
  return sigma_s / (4.0 * std::numbers::pi) * E * std::exp(-sigma_t * (s0 + (1.0 + c) * a)) * length;
}

// |a - b| / |b|, and 0 when both are 0 (a zero reference needs a zero answer).
inline double relative_error(double a, double b) {
  if (a == b) return 0.0;
  return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

}  // namespace airlight::optics::testing
