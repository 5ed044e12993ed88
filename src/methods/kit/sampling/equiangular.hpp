#pragma once
// The C++ twin of methods/kit/sampling/equiangular.glsl: where a march's samples go
// along a view ray — even steps, or equiangular steps about a light (Kulla &
// Fajardo 2012, §3): sample u ∈ (0, 1) at the angle θ = mix(θa, θb, u) seen
// from the light's foot point on the ray, x = foot + h·tan θ, weight dθ·h/cos²θ.
// Since r² = h²/cos²θ, Σ w/r² over the samples is (θb − θa)/h exactly: the 1/r²
// peak beside a light is integrated exactly whatever N.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace airlight::kit {

struct Segment {
  double a = 0.0, b = 0.0;
  double foot = 0.0;  // distance along the ray of the point nearest the light
  double h = 0.0;     // the light's distance from the ray's line; 0: even steps
  double theta_a = 0.0, theta_b = 0.0;
};

Segment uniform_segment(double a, double b);

// Over [a, b] (b > a) of the ray eye + t·dir (unit) for a light at `light`;
// h is kept above 1e-4 of the interval and optics::min_light_distance, so a
// ray through the light still maps θ onto [a, b].
Segment equiangular_segment(double a, double b, const glm::dvec3& eye, const glm::dvec3& dir,
                            const glm::dvec3& light);

// Distance along the ray (x) and weight (y) of the sample at u of n.
glm::dvec2 segment_sample(const Segment& s, double u, int n);

}  // namespace airlight::kit
