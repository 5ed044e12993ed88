// Where a march's samples go along a view ray (march.glsl): even steps, or
// equiangular steps about a light (Kulla & Fajardo 2012, §3, deterministic).
// The C++ twin is methods/kit/sampling/equiangular.hpp; twins/equiangular_twin_test.cpp
// holds the two together.
#include "optics/numerics.glsl"
#include "optics/light.glsl"

// The interval [a, b] along the view ray that one march covers, and how u maps
// onto it: uniform steps (`even`, h = 0), or equiangular about the light's foot
// point (h > 0). `even` is h = 0 as a constant where the segment's kind is
// one, as in a march unrolled over the lights: what depends on it folds away.
struct Segment {
  float a, b;
  float foot;  // distance along the ray of the point nearest the light
  float h;     // the light's distance from the ray's line
  float theta_a, theta_b;  // atan((a − foot)/h), atan((b − foot)/h)
  bool even;
};

Segment uniform_segment(float a, float b) { return Segment(a, b, 0.0, 0.0, 0.0, 0.0, true); }

// Equiangular steps over [a, b] (b > a) of the ray eye + t·dir for a light at
// `light`. h = |Δ − foot·dir|, not sqrt(|Δ|² − foot²), which cancels for a light
// near the ray (Nilsson eq. 2.16; docs/decisions.md, Numerics). A ray through the light has
// h = 0 and ∫dx/r² diverges: h is kept above 1e-4 of the interval, which
// still maps θ onto [a, b] exactly (any h > 0 does), only less peaked.
Segment equiangular_segment(float a, float b, vec3 eye, vec3 dir, vec3 light) {
  vec3 delta = light - eye;
  float foot = dot(delta, dir);
  float h = max(length(delta - foot * dir), max(1e-4 * (b - a), MIN_LIGHT_DISTANCE));
  return Segment(a, b, foot, h, atan2_accurate(a - foot, h), atan2_accurate(b - foot, h), false);
}

// Distance along the ray (x) and weight (y) of the sample at u ∈ (0, 1) of n.
vec2 segment_sample(Segment s, float u, int n) {
  if (s.even) return vec2(mix(s.a, s.b, u), (s.b - s.a) / float(n));
  float y = s.h * tan(mix(s.theta_a, s.theta_b, u));
  return vec2(s.foot + y, (s.theta_b - s.theta_a) / float(n) * (s.h + y * y / s.h));  // h/cos²θ = h + y²/h
}

// Equiangular samples at u = u0, u0 + du, … of n in order (a march's range of
// sample indices), without a tan each: θ advances by the same δ, so tan θ
// follows by tan(θ + δ) = (tan θ + tan δ)/(1 − tan θ·tan δ), a division a
// sample instead of llvmpipe's tan. An error in θ carries over unchanged from
// step to step, so the k-th sample errs by about k roundings
// (twins/equiangular_twin_test.cpp). θ stays inside (−π/2, π/2), so the
// denominator does not vanish; past the last sample the walk is not read.
struct EquiangularWalk {
  float tan_theta, tan_delta;
  float dtheta;  // (θb − θa)/n, the weight's angle step
};

EquiangularWalk equiangular_walk(Segment s, float u0, float du, int n) {
  float span = s.theta_b - s.theta_a;
  return EquiangularWalk(tan(s.theta_a + u0 * span), tan(du * span), span / float(n));
}

// The walk's sample, as segment_sample's: then step_walk to the next.
vec2 walk_sample(Segment s, EquiangularWalk w) {
  return vec2(s.foot + s.h * w.tan_theta, w.dtheta * s.h * (1.0 + w.tan_theta * w.tan_theta));  // h/cos²θ
}

void step_walk(inout EquiangularWalk w) {
  w.tan_theta = (w.tan_theta + w.tan_delta) / (1.0 - w.tan_theta * w.tan_delta);
}
