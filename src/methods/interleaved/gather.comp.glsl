// One direction of interleaved sampling's separable sum (Tóth 2009 §4.1): each
// pixel adds the partial sums of M consecutive pixels of its row (or column) —
// the window around it, shifted inside the image at its borders. M consecutive
// pixels hold every residue x mod M once, so after a horizontal and a vertical
// pass each pixel covers all M² residues q, i.e. all N sample indices.
//
// Depth-aware: a neighbour whose G-buffer distance differs from this pixel's by
// more than depth_threshold (relative) lies across a silhouette, where its ray
// marches another interval. The window first moves, among the M windows of M
// pixels that contain the pixel, to the one with the most neighbours on the
// pixel's own surface, so that beside a silhouette it keeps all M residues
// when that side is M pixels wide; neighbours still across are left out and
// the accepted partial sums scaled by M / accepted (the missing residues'
// samples replaced by the mean of the others'), so shafts do not bleed across
// silhouettes. Pixels outside a too-small image count as left out. (teapot_spot,
// N = 64, sum gather, rRMSE in the teapot's silhouette band: uniform steps
// 0.27 plain, 0.21 by exclusion alone, 0.17 with the moving window; equiangular
// 0.22, 0.036, 0.035.)
//
// Normalized (gather=normalized, not in Tóth): the partial sums come divided by
// each pixel's light guide G (march.glsl: the unshadowed ∫I/r² of its ray), the
// vertical pass multiplies the sum by the pixel's own G. Interleaving assumes
// the pixels of a window see nearly the same ray (Tóth §4.1); next to a light's
// image, L_air ∝ 1/h changes by large factors from pixel to pixel and a plain
// sum blurs the peak and spreads it over the cone's edge, whatever N. G carries
// that change exactly, so what the window shares is only the smooth remainder
// (σs·p, V, extinction). Neighbours whose rays no light reaches (G = 0, w = PARTIAL_EMPTY)
// are left out like those across silhouettes. Volume-aware (normalized, in
// scenes with bounded volumes; not in Tóth): the guide carries the volumes'
// σs but not V, so a neighbour whose volume key (march.glsl: the share of its
// guide the lights reach) differs from this pixel's is left out too — at a
// volume's outline, or a shadow plane seen edge-on inside it, the G-buffer
// distance is the same on both sides.
// Guarded (GUARD = k > 0, not in Tóth): a pixel beside a light's image
// marched all N samples itself (march.comp.glsl, w = PARTIAL_OWN); it is left out of
// every window and keeps its own estimate. For the others the vertical pass clamps the gathered
// value, per channel, to P ± k·SE, where P = M²·(own partial sum) is the
// pixel's own estimate of L_air from its N/M² samples and SE its standard
// error by systematic sampling's successive-difference estimator,
// SE² = M⁴·n/(2(n − 1))·Σ(y_k − y_{k−1})² (march.glsl). Where the window's rays
// differ by more than the pixel's own uncertainty — a lamp's image, a shadow
// edge — the pixel keeps its own march; elsewhere the gather's smoothing
// stands. SE falls as N grows, so the result converges to the pixel's own
// march, i.e. to raymarch, whatever the gather's bias.
// Specialized by GatherPass: BLOCK (M), VERTICAL, DEPTH_AWARE, NORMALIZED and
// GUARD, so that each pass's loops have constant trip counts and only the
// vertical pass multiplies by the light guide.
#include "methods/kit/frame/pixel.glsl"
#include "methods/kit/march/march.glsl"

#ifdef VERTICAL
layout(rgba32f, binding = 0) uniform image2D gathered;  // holds this pixel's own partial sum until written
#else
layout(rgba32f, binding = 0) uniform writeonly image2D gathered;
#endif
layout(binding = BINDING_PARTIAL) uniform sampler2D partial_sums;
layout(binding = BINDING_GUIDE) uniform sampler2D guides;  // the march's light guide per pixel (normalized)
layout(binding = BINDING_SPREAD) uniform sampler2D spreads;  // the march's Σ(y_k − y_{k−1})² and n (guard)

uniform float depth_threshold;  // relative to this pixel's distance
// Volume-aware (normalized, scenes with bounded volumes): a neighbour whose
// volume key (march.glsl: the lit share of its guide) differs from this
// pixel's by more than this is left out like one across a silhouette (0.05
// and 0.1 leave out the same pixels on biri_media; 0.2 lets more of the
// volumes' edges blur at 32×24, docs/decisions.md).
const float VOLUME_KEY_STEP = 0.1;

#ifdef VERTICAL
const ivec2 axis = ivec2(0, 1);  // along columns
#else
const ivec2 axis = ivec2(1, 0);  // along rows
#endif

// The 2M − 1 pixels around this one along the axis, s = along − M + 1 + j for
// j = 0 … 2M − 2, each fetched once: every window containing the pixel lies
// among them.
const int SPAN = 2 * BLOCK - 1;
vec3 partial[SPAN];
bool joined[SPAN];  // inside the image, reached by some light (normalized), on this pixel's surface and key

void fetch_neighbourhood(ivec2 pixel, int along, int size, float distance, float key) {
  for (int j = 0; j < SPAN; ++j) {
    int s = along - BLOCK + 1 + j;
    ivec2 neighbour = pixel + (clamp(s, 0, size - 1) - along) * axis;
    vec4 p = texelFetch(partial_sums, neighbour, 0);
    partial[j] = p.rgb;
    joined[j] = s >= 0 && s < size && p.w == PARTIAL_SHARED;
#ifdef DEPTH_AWARE
    joined[j] = joined[j] && (j == BLOCK - 1 ||
                              abs(surface_distance(neighbour) - distance) <= depth_threshold * distance);
#endif
#if defined(NORMALIZED) && VOLUME_COUNT > 0
    joined[j] = joined[j] && (j == BLOCK - 1 || abs(texelFetch(guides, neighbour, 0).w - key) <= VOLUME_KEY_STEP);
#endif
  }
}

// The first pixel (along the axis) of this pixel's window of M: of the M
// windows that contain it and fit in the image, the one with the most joining
// pixels, the centred one on ties. Next to a silhouette the window thus lies on
// the pixel's side when that side is M pixels wide, and keeps every residue.
int window_start(int along, int size) {
  int centred = clamp(along - (BLOCK - 1) / 2, 0, max(size - BLOCK, 0));
#ifdef DEPTH_AWARE
  if (size <= BLOCK) return centred;
  int lo = max(along - BLOCK + 1, 0), hi = min(along, size - BLOCK);
  int best = centred, most = -1;
  for (int j = 0; j < BLOCK; ++j) {  // window s = along − M + 1 + j covers neighbourhood j … j + M − 1
    int s = along - BLOCK + 1 + j;
    if (s < lo || s > hi) continue;
    int count = 0;
    for (int k = 0; k < BLOCK; ++k) count += joined[j + k] ? 1 : 0;
    if (count > most || (count == most && abs(s - centred) < abs(best - centred))) {
      best = s;
      most = count;
    }
  }
  return best;
#else
  return centred;
#endif
}

#if defined(VERTICAL) && defined(GUARD)
// The gathered value clamped to the pixel's own estimate ± GUARD standard
// errors (see the top). Below 8 own samples the spread is not trusted and the
// gather stands: with 4, a pixel whose samples all fall on a gobo's dark cells
// has a spread of 0 and would be clamped to black (docs/decisions.md).
const float MIN_N = 8.0;
vec3 guarded(vec3 value, ivec2 pixel, vec3 guide) {
  const float blocks = float(BLOCK * BLOCK);
  vec4 partial = imageLoad(gathered, pixel);
  vec3 own = blocks * partial.rgb * guide;
  if (partial.w == PARTIAL_OWN) return own;  // beside a light's image (march.comp.glsl)
  vec4 spread = texelFetch(spreads, pixel, 0);
  float n = spread.w;
  if (n < MIN_N) return value;
  vec3 error = blocks * sqrt(spread.rgb * (n / (2.0 * (n - 1.0))));
  return clamp(value, own - GUARD * error, own + GUARD * error);
}
#endif

void main() {
  FRAME_PIXEL_OR_RETURN(pixel);
  int along = pixel.x * axis.x + pixel.y * axis.y;
  int size = frame_size().x * axis.x + frame_size().y * axis.y;
  float distance = surface_distance(pixel);
#ifdef NORMALIZED
  float key = texelFetch(guides, pixel, 0).w;  // the march's volume key (march.glsl)
#else
  float key = 0.0;
#endif
  fetch_neighbourhood(pixel, along, size, distance, key);
  int first = window_start(along, size) - (along - BLOCK + 1);  // in the neighbourhood: 0 … M − 1
  vec3 sum = vec3(0.0);
  int count = 0;
  for (int j = 0; j < SPAN; ++j) {  // constant trip count: the window's M of the 2M − 1
    bool in_window = j >= first && j < first + BLOCK && joined[j];
    sum += in_window ? partial[j] : vec3(0.0);
    count += in_window ? 1 : 0;
  }
  if (count > 0) sum *= float(BLOCK) / float(count);
#ifdef VERTICAL
#ifdef NORMALIZED
  vec3 guide = texelFetch(guides, pixel, 0).rgb;
#else
  vec3 guide = vec3(1.0);
#endif
  sum *= guide;
#ifdef GUARD
  sum = guarded(sum, pixel, guide);
#endif
#endif
  imageStore(gathered, pixel, vec4(sum, count > 0 ? PARTIAL_SHARED : PARTIAL_EMPTY));
}
