#pragma once
// A check on the reference: L_air of docs/design.md §1 along single view rays by
// brute force, in double precision and sharing none of the reference's machinery
// (no Embree, no optics::airlight_quadrature, no optics::inscatter).
//
// Per light it cuts the view ray into pieces where the integrand is smooth —
// lit or not (its own Möller–Trumbore tests against every casting triangle),
// inside the spot's cone or its smooth edge, inside the beam's box, inside which
// volumes — by probing the ray densely: even probes, and one between every two
// consecutive points where a shadow ray grazes a caster's edge (so no shadow or
// lit gap is missed however narrow) or where the ray crosses a cone, the beam's
// box or a volume (optics' cone_intervals, beam_interval, volume_crossings, used
// only to place probes). Each change is bisected to 1e-9 of the ray's length and
// each lit piece integrated by adaptive Gauss–Kronrod (gk::integrate) to 1e-10 —
// over the angle seen from a point or spot light, where 1/r² is smooth. Of the
// optics it calls only the small functions tested against closed forms on their
// own: phase, radiant_intensity (cone falloff, gobo), light_map (beam, gobo).
//
// Slow (each probe tests the casters that reach the plane of the view ray and the
// light): for checks at chosen pixels of small scenes, not for images.
#include <airlight/scene.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "optics/airlight.hpp"

namespace airlight::reference {

struct BruteForceSettings {
  // Even probes along each view ray per light, besides those placed by shadow
  // edges and crossings: a safety net for anything those miss.
  int probes = 1024;
  double rel_tol = 1e-10;  // of each piece's Gauss–Kronrod integral
};

// L_air along `ray` (origin at the eye, unit dir), which ends at the first surface
// (any mesh) at view depth >= the camera's near plane, else at its far plane, as
// the reference's rays do.
glm::dvec3 brute_force_airlight(const Scene& scene, const optics::Ray& ray, const BruteForceSettings& settings = {});

// L_air at pixel (i, j) of a width × height image, through the pixel's centre on
// the reference's own camera ray (geometry::primary_ray).
glm::dvec3 brute_force_airlight(const Scene& scene, int width, int height, glm::ivec2 pixel,
                                const BruteForceSettings& settings = {});

// The same for a list of pixels (RGB, in the list's order), in parallel: for a
// harness that checks methods or the reference at chosen pixels.
std::vector<glm::dvec3> brute_force_airlight(const Scene& scene, int width, int height,
                                             const std::vector<glm::ivec2>& pixels,
                                             const BruteForceSettings& settings = {});

}  // namespace airlight::reference
