// Where a march's samples go along a view ray (march.glsl): even steps, or
// equiangular steps about a light (Kulla & Fajardo 2012, §3, deterministic).
// The C++ twin is methods/kit/sampling/equiangular.hpp; twins/equiangular_twin_test.cpp
// holds the two together.
#include "optics/numerics.glsl"
#include "optics/light.glsl"

// The interval [a, b] along the view ray that one march covers, and how u maps
// onto it: h = 0 uniform steps, h > 0 equiangular about the light's foot point.
struct Segment {
  float a, b;
  float foot;  // distance along the ray of the point nearest the light
  float h;     // the light's distance from the ray's line
  float theta_a, theta_b;  // atan((a − foot)/h), atan((b − foot)/h)
};

Segment uniform_segment(float a, float b) { return Segment(a, b, 0.0, 0.0, 0.0, 0.0); }

// Equiangular steps over [a, b] (b > a) of the ray eye + t·dir for a light at
// `light`. h = |Δ − foot·dir|, not sqrt(|Δ|² − foot²), which cancels for a light
// near the ray (Nilsson eq. 2.16; docs/decisions.md, Numerics). A ray through the light has
// h = 0 and ∫dx/r² diverges: h is kept above 1e-4 of the interval, which
// still maps θ onto [a, b] exactly (any h > 0 does), only less peaked.
Segment equiangular_segment(float a, float b, vec3 eye, vec3 dir, vec3 light) {
  vec3 delta = light - eye;
  float foot = dot(delta, dir);
  float h = max(length(delta - foot * dir), max(1e-4 * (b - a), MIN_LIGHT_DISTANCE));
  return Segment(a, b, foot, h, atan2_accurate(a - foot, h), atan2_accurate(b - foot, h));
}

// Distance along the ray (x) and weight (y) of the sample at u ∈ (0, 1) of n.
vec2 segment_sample(Segment s, float u, int n) {
  if (s.h == 0.0) return vec2(mix(s.a, s.b, u), (s.b - s.a) / float(n));
  float y = s.h * tan(mix(s.theta_a, s.theta_b, u));
  return vec2(s.foot + y, (s.theta_b - s.theta_a) / float(n) * (s.h + y * y / s.h));  // h/cos²θ = h + y²/h
}
