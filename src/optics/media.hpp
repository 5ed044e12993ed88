#pragma once
// The media of a scene along a segment: the medium that fills space plus the
// bounded volumes (docs/design.md §1: their coefficients add; each phase weights its own
// share of the scattering).
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace airlight::optics {

// ∫ σt along the straight segment a → b, per channel (exact: homogeneous pieces).
glm::dvec3 optical_depth(const Scene& scene, const glm::dvec3& a, const glm::dvec3& b);

// Optical depth of the eye's leg a → b: optical_depth, or zero under the
// simplified light model (T = 1, Nilsson eq. 2.15).
glm::dvec3 eye_leg_depth(const Scene& scene, const glm::dvec3& a, const glm::dvec3& b);

// Optical depth of a light's leg from x: to the light's position for point and
// spot lights; for directional lights only through bounded volumes (the filling
// medium has no extinction on that leg, docs/design.md §1), along -direction; for a
// directional light with a beam, emitted at its aperture, along the segment
// from x back to the aperture's plane, x − s·direction with s = beam_depth(x)
// (0 for x upstream of the aperture): σt_medium·s plus the volumes' chords.
// Zero under the simplified light model (T = 1).
glm::dvec3 light_leg_depth(const Scene& scene, const Light& light, const glm::dvec3& x);

// Σ over media containing x of σs_m · p_m(cos θ): the scattered fraction per
// unit length per steradian. Under the simplified model: σs of the medium / 4π.
glm::dvec3 scattering(const Scene& scene, const glm::dvec3& x, double cos_theta);

// Bounded volumes split a ray into homogeneous pieces: the sorted parameters in
// (t0, t1) where the ray enters or leaves a volume (integration breaks there).
std::vector<double> volume_crossings(const Scene& scene, const glm::dvec3& origin,
                                     const glm::dvec3& dir, double t0, double t1);

}  // namespace airlight::optics
