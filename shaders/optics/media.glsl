// GLSL twin of the geometry and extinction in src/optics/media.cpp: chords of
// segments and rays through the axis-aligned box volumes, and T(s) = exp(-σt s)
// (docs/design.md §1). Tested against the C++ by src/methods/kit/testing/twins/optics_twin_test.cpp.
#include "optics/constants.glsl"

// Slab test, as the C++ box_overlap: the part (x, y) of [t0, t1] where o + t·d is
// inside [lo, hi]; empty when !(x < y). A zero component of d is tested by the
// origin alone, so no 0/0 NaN can enter the min/max.
vec2 box_overlap(vec3 o, vec3 d, float t0, float t1, vec3 lo, vec3 hi) {
  vec2 t = vec2(t0, t1);
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0.0) {
      if (o[axis] < lo[axis] || o[axis] > hi[axis]) return vec2(0.0);
      continue;
    }
    float ta = (lo[axis] - o[axis]) / d[axis];
    float tb = (hi[axis] - o[axis]) / d[axis];
    t = vec2(max(t.x, min(ta, tb)), min(t.y, max(ta, tb)));
  }
  return t;
}

float overlap_length(vec2 t) { return t.x < t.y ? t.y - t.x : 0.0; }

// Length of the segment a → b inside the box (what optical_depth multiplies by
// a volume's σt). The unit direction keeps the same parametrization as C++.
float box_chord(vec3 a, vec3 b, vec3 lo, vec3 hi) {
  float len = length(b - a);
  if (!(len > 0.0)) return 0.0;
  return overlap_length(box_overlap(a, (b - a) / len, 0.0, len, lo, hi));
}

// Length of the ray origin + t·dir, t >= 0, inside the box: a directional
// light's leg toward the light (light_leg_depth). dir must be unit (the result
// is a length in t); dir = 0 gives +∞ inside the box, 0 outside.
float box_ray_chord(vec3 origin, vec3 dir, vec3 lo, vec3 hi) {
  return overlap_length(box_overlap(origin, dir, 0.0, positive_infinity(), lo, hi));
}

// Whether x is inside the closed box (media.cpp contains).
bool box_contains(vec3 x, vec3 lo, vec3 hi) {
  return all(greaterThanEqual(x, lo)) && all(lessThanEqual(x, hi));
}

// T(s) = exp(-σt s) per channel.
vec3 transmittance(vec3 sigma_t, float s) { return exp(-sigma_t * s); }
