// The shared frame as every GPU method sees it (methods/kit/frame/scene_frame.hpp):
// the frame block, the scene's lights, volumes and phase lobes, the G-buffer
// and shadow maps, and the scene-level helpers built on the optics twins — the
// GLSL side of optics::arrival, light_leg_depth, eye_leg_depth, scattering and
// inscatter (src/optics/), so that GPU passes match src/reference/reference.cpp.
//
// Specialized to the scene: binding points and the scene's structure come as
// macros from kit::SceneFrame::defines() — LIGHT_COUNT, LIGHT_TYPES,
// LIGHT_SHADOWS, LIGHT_GOBOS, LIGHT_BEAMS, LIGHT_EDGES, LIGHT_NARROW,
// VOLUME_COUNT, LIGHT_MODEL_TYPE, GREY_MEDIA, MEDIUM_PHASE(c),
// VOLUME_PHASE(v, c), FOR_EACH_LIGHT(F), FOR_EACH_LIGHT_SHARED(F) … — so that
// with a constant light index every test of a light's kind folds away: a
// generic shader pays for every branch it holds (docs/design.md §2). What
// holds for the whole scene (SIMPLIFIED_MODEL, ISOTROPIC_COMPONENTS) is also
// for #if: a branch that folds is still inlined, at every call, before it does.
// A program that defines SCENE_IN_REGISTERS before including this file and
// calls load_scene() first reads each light, volume and lobe from its buffer
// once per invocation instead of at every use.
#include "methods/kit/frame/frame_data.glsl"
#include "optics/phase.glsl"
#include "optics/light.glsl"
#include "optics/media.glsl"

// airlight::LightType values.
const int LIGHT_POINT = 0;
const int LIGHT_SPOT = 1;
const int LIGHT_DIRECTIONAL = 2;
// Shadow map kinds (SceneLight.shadow_kind).
const int SHADOW_NONE = 0;  // no occluders in the scene: always visible
const int SHADOW_MAP = 1;   // 2D: perspective over a spot's cone, or orthographic for directional
const int SHADOW_CUBE = 2;  // cube: point lights and spots of cone >= kit::wide_spot_deg (Tóth §4)

layout(std140, binding = BINDING_FRAME_BLOCK) uniform FrameBlock { FrameData frame; };

layout(std430, binding = BINDING_LIGHTS) readonly buffer SceneLights { SceneLight lights[]; };
layout(std430, binding = BINDING_VOLUMES) readonly buffer SceneVolumes { SceneVolume volumes[]; };
layout(std430, binding = BINDING_LOBES) readonly buffer SceneLobes { SceneLobe lobes[]; };

layout(binding = BINDING_DISTANCE) uniform sampler2D gbuffer_distance;
layout(binding = BINDING_NORMAL) uniform sampler2D gbuffer_normal;
layout(binding = BINDING_GEOMETRIC_NORMAL) uniform sampler2D gbuffer_geometric_normal;
layout(binding = BINDING_ALBEDO) uniform sampler2D gbuffer_albedo;
layout(binding = BINDING_GOBOS) uniform sampler2DArray gobo_maps;
layout(binding = BINDING_SHADOW_MAPS) uniform sampler2DArray shadow_maps;
layout(binding = BINDING_SHADOW_CUBES) uniform samplerCubeArray shadow_cubes;

const int light_types[] = LIGHT_TYPES;      // LIGHT_* per light
const int light_shadows[] = LIGHT_SHADOWS;  // SHADOW_* per light
const bool light_gobos[] = LIGHT_GOBOS;     // whether a light samples a gobo
const bool light_beams[] = LIGHT_BEAMS;     // a directional light bounded to its beam
const bool light_edges[] = LIGHT_EDGES;     // a spot with a smooth edge (edge_deg > 0)
const bool light_narrow[] = LIGHT_NARROW;   // a spot narrower than 90°: its lit set is its cone, convex

// Code compiled for one light may serve every light of its structure
// (kit::SceneFrame::representative): LIGHT_DATA(i) is the light whose data
// light i's code reads (its index into the buffers and images the method
// keeps per light).
//  - A program that draws one light at a time, compiled for its structure's
//    first light SHARED_LIGHT, reads light `shared_light` there.
//  - FOR_EACH_LIGHT_SHARED(F) takes F(i) once per structure, i its first
//    light, in a loop over the structure's lights, which swap_lights() turns
//    through slot i: a scene of five spots of two kinds compiles two copies
//    of F, not five.
int light_data_index[] = LIGHT_IDENTITY;
#ifdef SHARED_LIGHT
uniform int shared_light;
#define LIGHT_DATA(i) ((i) == SHARED_LIGHT ? shared_light : (i))
#else
#define LIGHT_DATA(i) light_data_index[i]
#endif

#ifdef SCENE_IN_REGISTERS
SceneLight scene_lights[LIGHT_COUNT > 0 ? LIGHT_COUNT : 1];
SceneVolume scene_volumes[VOLUME_COUNT > 0 ? VOLUME_COUNT : 1];
SceneLobe scene_lobes[LOBE_COUNT > 0 ? LOBE_COUNT : 1];
#define LOAD_LIGHT(i) scene_lights[i] = lights[LIGHT_DATA(i)];
#define LOAD_VOLUME(v) scene_volumes[v] = volumes[v];
#define LOAD_LOBE(k) scene_lobes[k] = lobes[k];
void load_scene() { FOR_EACH_LIGHT(LOAD_LIGHT) FOR_EACH_VOLUME(LOAD_VOLUME) FOR_EACH_LOBE(LOAD_LOBE) }
#if LIGHT_COUNT > 0
#define LIGHT(i) scene_lights[i]
#else
// No light: nothing reads one, but the helpers that would still compile, and
// reading the never-written register copy is a compiler warning that the GL
// debug output reports as an error (docs/decisions.md "No lights").
#define LIGHT(i) lights[LIGHT_DATA(i)]
#endif
#define VOLUME(v) scene_volumes[v]
#define LOBE(k) scene_lobes[k]
#else
void load_scene() {}
#define LIGHT(i) lights[LIGHT_DATA(i)]
#define VOLUME(v) volumes[v]
#define LOBE(k) lobes[k]
#endif

// Swaps what lights a and b's code reads: FOR_EACH_LIGHT_SHARED turns its
// lights through their structure's slot by swaps of constant indices, which
// in registers are moves (a read of a light's buffer at an index that varies
// is a load per SIMD lane on llvmpipe).
void swap_lights(int a, int b) {
  int index = light_data_index[a];
  light_data_index[a] = light_data_index[b];
  light_data_index[b] = index;
#if defined(SCENE_IN_REGISTERS) && LIGHT_COUNT > 0
  SceneLight light = scene_lights[a];
  scene_lights[a] = scene_lights[b];
  scene_lights[b] = light;
#endif
}
LIGHT_GROUPS

bool simplified_model() { return LIGHT_MODEL_TYPE == LIGHT_MODEL_SIMPLIFIED; }
ivec2 frame_size() { return ivec2(frame.size); }

// ---- G-buffer -----------------------------------------------------------------

// Eye distance along the pixel's ray to the visible surface, or to the far plane.
float surface_distance(ivec2 pixel) { return texelFetch(gbuffer_distance, pixel, 0).r; }

// ---- media (optics/media.hpp) -------------------------------------------------

// The medium's phase function at cos θ: its lobes, each of a constant type.
float medium_phase(float c) { return MEDIUM_PHASE(c); }

// optics::scattering: Σ over media containing x of σs·p(cos θ); σs/4π under the
// simplified model (Nilsson eq. 2.14).
vec3 scattering(vec3 x, float c) {
  if (simplified_model()) return frame.medium_sigma_s * INV_4PI;
  vec3 sum = frame.medium_sigma_s * medium_phase(c);
#define ADD_VOLUME_SCATTERING(v) \
  if (box_contains(x, VOLUME(v).lo, VOLUME(v).hi)) sum += VOLUME(v).sigma_s * VOLUME_PHASE(v, c);
  FOR_EACH_VOLUME(ADD_VOLUME_SCATTERING)
#undef ADD_VOLUME_SCATTERING
  return sum;
}

// σs and σt of everything that fills x: the medium and the volumes that hold
// it; under the simplified model the filling medium alone scatters.
vec3 sigma_s_at(vec3 x) {
  vec3 sigma = frame.medium_sigma_s;
  if (simplified_model()) return sigma;
#define ADD_VOLUME_SIGMA_S(v) if (box_contains(x, VOLUME(v).lo, VOLUME(v).hi)) sigma += VOLUME(v).sigma_s;
  FOR_EACH_VOLUME(ADD_VOLUME_SIGMA_S)
#undef ADD_VOLUME_SIGMA_S
  return sigma;
}
vec3 sigma_t_at(vec3 x) {
  vec3 sigma = frame.medium_sigma_t;
#define ADD_VOLUME_SIGMA_T(v) if (box_contains(x, VOLUME(v).lo, VOLUME(v).hi)) sigma += VOLUME(v).sigma_t;
  FOR_EACH_VOLUME(ADD_VOLUME_SIGMA_T)
#undef ADD_VOLUME_SIGMA_T
  return sigma;
}

// optics::optical_depth: ∫σt along the segment a → b, medium and volumes.
vec3 optical_depth(vec3 a, vec3 b) {
  vec3 depth = frame.medium_sigma_t * length(b - a);
#define ADD_VOLUME_CHORD(v) depth += VOLUME(v).sigma_t * box_chord(a, b, VOLUME(v).lo, VOLUME(v).hi);
  FOR_EACH_VOLUME(ADD_VOLUME_CHORD)
#undef ADD_VOLUME_CHORD
  return depth;
}

// optics::eye_leg_depth: zero under the simplified model (T = 1, Nilsson eq. 2.15).
vec3 eye_leg_depth(vec3 a, vec3 b) { return simplified_model() ? vec3(0.0) : optical_depth(a, b); }

// T(d) = exp(−τ(eye → eye + d·dir)) per channel: the eye leg's transmittance
// to distance d along unit `dir`.
vec3 eye_transmittance(vec3 dir, float d) { return exp(-eye_leg_depth(frame.eye, frame.eye + d * dir)); }

// A directional light with a beam (beam_length > 0), and the beam.
bool has_beam(int i) { return light_beams[i]; }
Beam light_beam(int i) {
  return Beam(LIGHT(i).position, LIGHT(i).direction, LIGHT(i).gobo_right, LIGHT(i).gobo_up,
              vec2(LIGHT(i).beam_width, LIGHT(i).beam_height), LIGHT(i).beam_length);
}

// optics::light_leg_depth: to the light's position; a beam, emitted at its
// aperture, back to the aperture's plane (0 upstream of it); other directional
// lights only through bounded volumes (docs/design.md §1).
vec3 light_leg_depth(int i, vec3 x) {
  if (simplified_model()) return vec3(0.0);
  if (light_types[i] != LIGHT_DIRECTIONAL) return optical_depth(x, LIGHT(i).position);
  if (has_beam(i)) return optical_depth(x, x - max(beam_depth(light_beam(i), x), 0.0) * LIGHT(i).direction);
  vec3 depth = vec3(0.0);
#define ADD_VOLUME_RAY_CHORD(v) depth += VOLUME(v).sigma_t * box_ray_chord(x, -LIGHT(i).direction, VOLUME(v).lo, VOLUME(v).hi);
  FOR_EACH_VOLUME(ADD_VOLUME_RAY_CHORD)
#undef ADD_VOLUME_RAY_CHORD
  return depth;
}

// ---- lights (optics/light.hpp) ------------------------------------------------

struct Arrival {
  vec3 irradiance;  // I(ω)/r² (or the model's falloff), or a directional irradiance
  vec3 to_light;    // unit, from x toward the light
  float distance;   // +∞ for directional lights
};

// ---- the light map (Dobashi 2000 §4: I(θ, φ) as a texture) -------------------
// light_arrival = light_arrival_unmapped × light_map, so that a method that
// projects the light map itself (planes) can evaluate the two apart.

// Light i's gobo in texels (frame_data.glsl: its width · 65536 + height).
ivec2 gobo_size(int i) { return ivec2(LIGHT(i).gobo_size >> 16, LIGHT(i).gobo_size & 0xffff); }

// The gobo colour of light i at uv (1 without a gobo; black outside [0, 1]²).
vec3 gobo_color(int i, vec2 uv) {
  return light_gobos[i] ? sample_gobo(gobo_maps, float(LIGHT(i).gobo_layer), gobo_size(i), uv) : vec3(1.0);
}

// optics::light_map: the unitless per-channel factor of what light i sends to
// x: spot → spot_cone · gobo colour toward x; directional with a beam → (x
// inside the beam) · gobo colour at beam_uv(x); point and unbounded directional → 1.
// `in_cone` (a constant): x is known to lie in a hard-edged spot's cone, whose
// factor is then 1 without the test.
vec3 light_map(int i, vec3 x, bool in_cone) {
  if (light_types[i] == LIGHT_SPOT) {
    vec3 axis = LIGHT(i).direction, delta = x - LIGHT(i).position;
    float r = length(delta);
    vec3 dir = r > 0.0 ? delta / r : axis;  // at the apex: the axis, as light_arrival_unmapped
    float cone = in_cone && !light_edges[i]
                     ? 1.0
                     : spot_cone(axis, LIGHT(i).cone, light_edges[i] ? LIGHT(i).edge : 0.0, dir);  // a constant 0: the hard cut alone
    if (cone == 0.0) return vec3(0.0);
    vec2 uv = gobo_uv(axis, LIGHT(i).gobo_right, LIGHT(i).gobo_up, LIGHT(i).tan_cone, dir);
    return cone * gobo_color(i, uv);
  }
  if (!has_beam(i)) return vec3(1.0);
  Beam b = light_beam(i);
  return inside_beam(b, x) ? gobo_color(i, beam_uv(b, x)) : vec3(0.0);
}
vec3 light_map(int i, vec3 x) { return light_map(i, x, false); }

// optics::arrival without the light map: intensity/falloff toward x (point,
// spot), or the irradiance (directional).
Arrival light_arrival_unmapped(int i, vec3 x) {
  if (light_types[i] == LIGHT_DIRECTIONAL)
    return Arrival(LIGHT(i).color, -LIGHT(i).direction, positive_infinity());
  vec3 delta = LIGHT(i).position - x;
  float r = length(delta);
  vec3 to_light = r > 0.0 ? delta / r : -LIGHT(i).direction;
  vec3 irradiance =
      arrival_irradiance(LIGHT(i).color, LIGHT_MODEL_TYPE, r, frame.light_model_a1, frame.light_model_a0);
  return Arrival(irradiance, to_light, r);
}

// optics::arrival: what reaches x from light i before visibility and extinction.
Arrival light_arrival(int i, vec3 x) {
  Arrival a = light_arrival_unmapped(i, x);
  a.irradiance *= light_map(i, x);
  return a;
}

// The part of [t0, t1] along eye + t·dir (unit) where light i can arrive: for
// a spot the hull of its cone's pieces (cone_intervals: the cone itself below
// 90°, where it is convex; a wider cone's lit set may be two pieces around the
// dark backward cone, and the gap between them has a cone factor of 0); for a
// beam its box (beam_interval); else all of it. Empty: !(x < y).
vec2 lit_interval(int i, vec3 eye, vec3 dir, float t0, float t1) {
  if (has_beam(i)) return beam_interval(light_beam(i), eye, dir, t0, t1);
  if (light_types[i] != LIGHT_SPOT) return vec2(t0, t1);
  ConeIntervals lit = cone_intervals(LIGHT(i).position, LIGHT(i).direction, LIGHT(i).cone,
                                     eye, dir, t0, t1);
  return lit.count > 0 ? vec2(lit.piece[0].x, lit.piece[lit.count - 1].y) : vec2(t1, t0);
}

// Whether light i's lit interval lies in its cone: for a spot narrower than
// 90° it is the cone's one piece, up to the rounding of its ends. A sample
// there needs no angle test (light_map's `in_cone`: an atan2 a sample).
bool lit_interval_in_cone(int i) { return light_types[i] == LIGHT_SPOT && light_narrow[i]; }

// ---- shadow maps (Tóth §4: 2D for spots, cubes for point lights) ---------------

// What a shadow map stores (R32F, linear): the distance from a point light or
// spot to x, or x's depth along a directional light's travel.
float shadow_distance(int i, vec3 x) {
  if (light_types[i] == LIGHT_DIRECTIONAL) return dot(x, LIGHT(i).direction);
  return length(LIGHT(i).position - x);  // light_arrival_unmapped's length, to the bit: computed once
}

// World size of one shadow-map texel at x (at the map's centre, where texels are largest).
float shadow_texel(int i, vec3 x) {
  float along = light_types[i] == LIGHT_DIRECTIONAL ? 0.0 : length(x - LIGHT(i).position);
  return (LIGHT(i).texel_per_distance * along + LIGHT(i).texel_constant) / frame.shadow_resolution;
}

// The stored distance of the nearest occluder toward x; +∞ where x lies outside
// the map (nothing in the scene's bounds can occlude it there).
float shadow_occluder(int i, vec3 x) {
  float layer = float(LIGHT(i).shadow_layer);
  if (light_shadows[i] == SHADOW_CUBE) {
    vec3 dir = x - LIGHT(i).position;
    return dir == vec3(0.0) ? positive_infinity() : texture(shadow_cubes, vec4(dir, layer)).r;
  }
  vec4 clip = LIGHT(i).shadow_matrix * vec4(x, 1.0);
  if (!(clip.w > 0.0)) return positive_infinity();  // behind a spot
  vec2 ndc = clip.xy / clip.w;
  if (any(greaterThan(abs(ndc), vec2(1.0)))) return positive_infinity();
  return texture(shadow_maps, vec3(0.5 * ndc + 0.5, layer)).r;
}

// V(x) for a point in the medium from light i's shadow map: lit when its
// distance does not exceed the stored one. No depth bias: a point in the
// medium cannot shadow itself, and a bias lights the medium that far behind
// every lit surface. Points a fraction of a texel in front of a lit, sloped
// surface are all it kept lit, at the ends of the rays that reach it; the
// medium inside a caster the near plane cuts, or behind a quad, is what view
// rays cross (random scene 851, a sphere across the near plane: rRMSE 0.86 at
// 1 texel, 0.094 at 0).
float shadow_visibility(int i, vec3 x) {
  if (light_shadows[i] == SHADOW_NONE) return 1.0;
  return shadow_distance(i, x) <= shadow_occluder(i, x) ? 1.0 : 0.0;
}

// V at a surface point with (eye-facing) geometric normal n: the point moves off
// the surface by shadow_bias texels along n (normal offset). With nearest lookup
// the stored surface is at most √2/2 texel away sideways, i.e. at most
// 0.71·tan θ texels nearer the light along the ray, while the offset gains
// b/cos θ: b = 1 clears it at every incidence angle θ.
float surface_visibility(int i, vec3 x, vec3 n) {
  return shadow_visibility(i, x + n * (frame.shadow_bias * shadow_texel(i, x)));
}

// ---- single scattering (optics::inscatter, docs/design.md §1) -------------------------

// inscatter without the light map: σs·p(cos θ)·I/r²·exp(−τ_light)·exp(−τ_eye)
// with I the light's unmapped intensity (or irradiance), at x on a view ray
// along unit view_dir, without visibility; eye_depth is τ from the eye to x
// (shared by all lights at one sample).
vec3 inscatter_unmapped(int i, vec3 x, vec3 view_dir, vec3 eye_depth) {
  Arrival a = light_arrival_unmapped(i, x);
  float cos_theta = dot(a.to_light, view_dir);  // light's travel vs. toward the eye
  vec3 depth = light_leg_depth(i, x) + eye_depth;
#if GREY_MEDIA
  return scattering(x, cos_theta) * a.irradiance * exp(-depth.r);  // one exp: σ is the same in R, G and B
#else
  return scattering(x, cos_theta) * a.irradiance * exp(-depth);
#endif
}

// optics::inscatter: light_map × inscatter_unmapped. Outside a cone or a beam
// the map is 0 and the rest (media, extinction) is skipped: marches stay cheap.
// `in_cone` as light_map's.
vec3 inscatter(int i, vec3 x, vec3 view_dir, vec3 eye_depth, bool in_cone) {
  vec3 map = light_map(i, x, in_cone);
  return map == vec3(0.0) ? vec3(0.0) : map * inscatter_unmapped(i, x, view_dir, eye_depth);
}
vec3 inscatter(int i, vec3 x, vec3 view_dir, vec3 eye_depth) { return inscatter(i, x, view_dir, eye_depth, false); }

// ---- pieces of a view ray ------------------------------------------------------
// Bounded media (Biri 2006 §5.2): the pixel's ray [0, d] cut at the ends of its
// chords through the volumes into pieces, each inside a fixed set of media:
// breaks[0] = 0 < … < breaks[PIECES] = d (empty pieces where chords miss); one
// piece without volumes.
const int PIECES = 2 * VOLUME_COUNT + 1;
float breaks[PIECES + 1];

void cut_into_pieces(vec3 dir, float d) {
  breaks[0] = 0.0;
  breaks[PIECES] = d;
#if VOLUME_COUNT > 0
#define ADD_CHORD_ENDS(v)                                                          \
  {                                                                                \
    vec2 chord = box_overlap(frame.eye, dir, 0.0, d, VOLUME(v).lo, VOLUME(v).hi); \
    bool hit = chord.x < chord.y;                                                  \
    breaks[2 * v + 1] = hit ? chord.x : d;                                         \
    breaks[2 * v + 2] = hit ? chord.y : d;                                         \
  }
  FOR_EACH_VOLUME(ADD_CHORD_ENDS)
#undef ADD_CHORD_ENDS
  // The 2·VOLUME_COUNT chord ends sorted by a bubble sort of constant trip
  // counts (min and max, no data-dependent loop), in registers.
  for (int pass = 1; pass < PIECES - 1; ++pass)
    for (int j = 1; j < PIECES - 1; ++j) {
      float lo = min(breaks[j], breaks[j + 1]), hi = max(breaks[j], breaks[j + 1]);
      breaks[j] = lo;
      breaks[j + 1] = hi;
    }
#endif
}
