// GLSL twin of src/optics/light.cpp: what a light sends toward a point (spot
// cone, gobo, a directional light's beam) and the distance falloff of each
// light model (docs/design.md §1).
// Tested against the C++ by src/methods/kit/testing/twins/optics_twin_test.cpp and
// cone_twin_test.cpp.
#include "optics/numerics.glsl"
#include "optics/media.glsl"

// Light model codes: the integer values of airlight::LightModelType.
const int LIGHT_MODEL_PHYSICAL = 0;
const int LIGHT_MODEL_SIMPLIFIED = 1;

// optics::min_light_distance: r is clamped here in every 1/r² (∫dx/r² diverges
// on a ray through the light).
const float MIN_LIGHT_DISTANCE = 1e-6;

// optics::spot_cone: 1 inside cone - edge, Hermite smoothstep in the angle down
// to 0 at cone; edge_rad <= 0 is the hard cut of Nilsson eq. 2.9 (1 iff angle <= cone).
// axis and dir are unit, dir points from the light. Angles in radians. The angle
// comes from angle_between (numerics.glsl), as in the C++: in float, acos near 1
// resolves angles only to ~3e-4 rad.
float spot_cone(vec3 axis, float cone_rad, float edge_rad, vec3 dir) {
  float angle = angle_between(axis, dir);
  if (edge_rad <= 0.0) return angle <= cone_rad ? 1.0 : 0.0;
  return smoothstep(0.0, 1.0, (cone_rad - angle) / edge_rad);  // GLSL smoothstep clamps
}

// optics::cone_intervals: the part of [t0, t1] of origin + t·dir (unit) inside
// the one-sided cone {x : angle(axis, x - apex) <= half_angle} (unit axis,
// radians), the lit set of spot_cone's hard cut (Nilsson §2.5, Eberly's
// line–cone intersection): up to two pieces of positive length, ascending; two
// only for half_angle > π/2, where a line may cross the dark backward cone.
struct ConeIntervals {
  int count;       // 0, 1 or 2
  vec2 piece[2];   // [x, y]: t0 <= x < y <= t1
};

// optics double_cone_roots (light.cpp): s where p + s·dir meets the double cone
// sin²α (v·a)² = cos²α |v⊥|² with its apex at the origin. The v⊥ form avoids
// the cancellation of (dir·a)² - cos²α, which in float would cost narrow cones
// most of their digits; the discriminant, expanded by hand, keeps the roots
// accurate when they are close (near 90°). No thresholds: a negative
// discriminant counts as 0 (keeping a double root at the apex), a missing
// root is s = 0; such spurious roots only add bounds. sn, cs: sin α, cos α.
vec2 double_cone_roots(vec3 p, vec3 dir, vec3 axis, float sn, float cs) {
  float s2 = sn * sn, c2 = cs * cs;
  float pa = dot(p, axis), da = dot(dir, axis);
  vec3 p_perp = p - pa * axis, d_perp = dir - da * axis;
  float A = s2 * da * da - c2 * dot(d_perp, d_perp);
  float B = s2 * pa * da - c2 * dot(p_perp, d_perp);
  float C = s2 * pa * pa - c2 * dot(p_perp, p_perp);
  vec3 e = da * p_perp - pa * d_perp, m = cross(p_perp, d_perp);
  float disc = c2 * (s2 * dot(e, e) - c2 * dot(m, m));  // B² - AC without its cancelling terms
  float q = -(B + (B < 0.0 ? -1.0 : 1.0) * sqrt(max(disc, 0.0)));  // stable quadratic roots
  return vec2(A != 0.0 ? q / A : 0.0, q != 0.0 ? C / q : 0.0);
}

// Whether the direction v from the apex lies inside the cone of half-angle α
// (sn, cs = sin α, cos α): |a×v|·cos α − (a·v)·sin α = |v|·sin(angle − α), both
// angles in [0, π], so it is <= 0 exactly where angle <= α — spot_cone's hard
// cut without its atan2 (docs/decisions.md, "Γ's cost"). x·|x| increases with
// x, so both sides are compared as signed squares, without the root of |a×v|.
bool inside_cone(vec3 axis, float sn, float cs, vec3 v) {
  vec3 across = cross(axis, v);
  float along = dot(axis, v);
  return dot(across, across) * cs * abs(cs) <= along * abs(along) * sn * sn;
}

// The cone given by sin and cos of its half-angle (sin_cos), for a caller that has them.
ConeIntervals cone_intervals(vec3 apex, vec3 axis, vec2 sin_cos, vec3 origin, vec3 dir, float t0, float t1) {
  ConeIntervals lit = ConeIntervals(0, vec2[2](vec2(0.0), vec2(0.0)));
  if (!(t1 > t0)) return lit;
  // Roots about the foot of the perpendicular from the apex: their rounding
  // scales with the line's distance from the apex, not the origin's.
  vec3 w = origin - apex;
  float foot = -dot(w, dir);
  float sn = sin_cos.x, cs = sin_cos.y;
  vec2 r = clamp(foot + double_cone_roots(w + foot * dir, dir, axis, sn, cs), t0, t1);
  float lo = min(r.x, r.y), hi = max(r.x, r.y);
  // Between consecutive bounds t0, lo, hi, t1 the angle never crosses α (the
  // boundary lies on the double cone): the midpoint classifies each piece,
  // picking the nappe. Lit pieces of positive length that meet join (across a
  // spurious bound or an empty piece); two pieces only around a dark middle
  // one (α > π/2). By selects, not the C++'s loop over the pieces: its writes
  // at lit.count are a per-lane indexed store on llvmpipe.
  bool lit0 = t0 < lo && inside_cone(axis, sn, cs, w + 0.5 * (t0 + lo) * dir);
  bool lit1 = lo < hi && inside_cone(axis, sn, cs, w + 0.5 * (lo + hi) * dir);
  bool lit2 = hi < t1 && inside_cone(axis, sn, cs, w + 0.5 * (hi + t1) * dir);
  bool gap = lit0 && lit2 && lo < hi && !lit1;
  lit.count = gap ? 2 : (lit0 || lit1 || lit2 ? 1 : 0);
  if (lit.count > 0) lit.piece[0] = vec2(lit0 ? t0 : (lit1 ? lo : hi), gap ? lo : (lit2 ? t1 : (lit1 ? hi : lo)));
  if (gap) lit.piece[1] = vec2(hi, t1);
  return lit;
}

ConeIntervals cone_intervals(vec3 apex, vec3 axis, float half_angle, vec3 origin, vec3 dir, float t0, float t1) {
  return cone_intervals(apex, axis, vec2(sin(half_angle), cos(half_angle)), origin, dir, t0, t1);
}

// optics::gobo_uv: u, v in [0, 1] over the square circumscribing the cone, v = 1
// toward `up`. right = normalize(axis × gobo_up), up = right × axis (C++ gobo_frame;
// the caller builds the frame once per light). tan_cone = tan(cone): pass 0 when
// cone >= 90° (no square; C++ maps every direction outside). Directions at or
// behind the light's plane map to (-1, -1), outside the gobo.
vec2 gobo_uv(vec3 axis, vec3 right, vec3 up, float tan_cone, vec3 dir) {
  float z = dot(dir, axis);
  if (!(tan_cone > 0.0) || z <= 0.0) return vec2(-1.0);
  float scale = 0.5 / (z * tan_cone);
  return vec2(0.5 + dot(dir, right) * scale, 0.5 + dot(dir, up) * scale);
}

// optics::sample_gobo times the "outside the unit square is black" rule of the
// C++ gobo colour: bilinear between pixel centres (i + 0.5)/W with indices
// clamped to the edge.
//
// Upload contract: layer `layer` holds the gobo Image, `size` texels from the
// layer's corner (a smaller gobo than the array's keeps its own texels, never
// resampled), with its rows flipped, so that texel row 0 (GL's t = 0) is the
// Image's bottom row and t = v (Image row 0 is the top, v = 1). Any filter and
// wrap mode may be set: texelFetch ignores
// them. The filtering is done here in float because GL_LINEAR hardware is
// allowed (and on most GPUs does) quantize the weights to 8 bits, ≈ 0.2% of
// the texel contrast, which would miss the C++ by far more than float precision.
vec3 sample_gobo(sampler2DArray gobos, float layer, ivec2 size, vec2 uv) {
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec3(0.0);
  vec2 p = uv * vec2(size) - 0.5;  // t = v, so this is C++'s (1 - v)·H - 0.5 mirrored
  vec2 f = floor(p);
  vec2 w = p - f;
  ivec2 i0 = clamp(ivec2(f), ivec2(0), size - 1);
  ivec2 i1 = clamp(ivec2(f) + 1, ivec2(0), size - 1);
  int l = int(layer + 0.5);
  vec3 c00 = texelFetch(gobos, ivec3(i0.x, i0.y, l), 0).rgb;
  vec3 c10 = texelFetch(gobos, ivec3(i1.x, i0.y, l), 0).rgb;
  vec3 c01 = texelFetch(gobos, ivec3(i0.x, i1.y, l), 0).rgb;
  vec3 c11 = texelFetch(gobos, ivec3(i1.x, i1.y, l), 0).rgb;
  return mix(mix(c00, c10, w.x), mix(c01, c11, w.x), w.y);
}

// A directional light's beam (scene.hpp Beam; the light.cpp beam functions):
// the box of the aperture rectangle `size` (along right, up: optics
// gobo_frame) centred at `origin`, perpendicular to the unit `axis` (the
// light's travel), extended `length` downstream.
struct Beam {
  vec3 origin, axis, right, up;
  vec2 size;
  float length;
};

// optics::beam_uv: u = 0.5 + (x − origin)·right / w, v = 0.5 + (x − origin)·up / h.
vec2 beam_uv(Beam b, vec3 x) {
  vec3 d = x - b.origin;
  return 0.5 + vec2(dot(d, b.right), dot(d, b.up)) / b.size;
}

// optics::beam_depth: s = (x − origin)·axis, downstream of the aperture's plane.
float beam_depth(Beam b, vec3 x) { return dot(x - b.origin, b.axis); }

// optics::inside_beam: the closed box, beam_uv in [0, 1]² and 0 <= s <= length.
bool inside_beam(Beam b, vec3 x) {
  vec2 uv = beam_uv(b, x);
  float s = beam_depth(b, x);
  return all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))) && s >= 0.0 && s <= b.length;
}

// optics::beam_interval: the part of [t0, t1] of origin + t·dir inside the
// beam's box, by slabs in the beam's frame (box_overlap, media.glsl); empty
// when !(x < y).
vec2 beam_interval(Beam b, vec3 origin, vec3 dir, float t0, float t1) {
  vec3 o = origin - b.origin;
  vec3 p = vec3(dot(o, b.right), dot(o, b.up), dot(o, b.axis));
  vec3 d = vec3(dot(dir, b.right), dot(dir, b.up), dot(dir, b.axis));
  vec3 half_size = vec3(0.5 * b.size, 0.0);
  return box_overlap(p, d, t0, t1, -half_size, half_size + vec3(0.0, 0.0, b.length));
}

// The distance falloff of optics::arrival for point and spot lights:
// 1/r² (physical) or 1/(a1 r² + a0) (simplified, Nilsson eq. 2.13), r clamped
// at MIN_LIGHT_DISTANCE. Directional lights have no falloff (factor 1).
float physical_falloff(float r) {
  float rc = max(r, MIN_LIGHT_DISTANCE);
  return 1.0 / (rc * rc);
}
float simplified_falloff(float r, float a1, float a0) {
  float rc = max(r, MIN_LIGHT_DISTANCE);
  return 1.0 / (a1 * rc * rc + a0);
}
float light_falloff(int model, float r, float a1, float a0) {
  return model == LIGHT_MODEL_SIMPLIFIED ? simplified_falloff(r, a1, a0) : physical_falloff(r);
}

// optics::arrival(...).irradiance for a point or spot light at distance r:
// I(ω) (intensity · spot_cone · gobo colour, composed by the caller) / falloff.
vec3 arrival_irradiance(vec3 intensity_toward_x, int model, float r, float a1, float a0) {
  return intensity_toward_x * light_falloff(model, r, a1, a0);
}
