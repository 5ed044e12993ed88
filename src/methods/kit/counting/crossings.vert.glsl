// The counted triangles (lit_intervals.glsl), three vertices each fetched from
// their buffer by gl_VertexID; no vertex attributes. Corners at infinity
// (w = 0, as robust shadow volumes extrude) are projected as they are, so no
// far plane cuts a shadow plane, and the rasterizer decides their pixels.
//
// A triangle whose corners are all finite and in front of the eye is drawn
// grown by COVER_MARGIN pixels on every side (each corner moved to where its
// two edges, pushed out, meet), and its fragments decide whether their ray
// crosses it by an exact test (crossings.frag.glsl): the rasterizer snaps
// corners to 1/256 pixel, and where two slivers of a light volume's shadow
// side meet a pixel's centre within that, it covered neither and lost the
// crossing. 1/16 pixel clears the snapping many times over; a whole pixel made
// every small triangle of a light volume mesh cover its neighbours' pixels too
// (docs/decisions.md). A sliver's sharp corner moves margin / sin(half its
// angle), far past the corner but within a strip the margin wide: capped at 64
// margins, as it was, the grown sides near the corner stayed within the
// snapping of the sliver's, and pixel centres inside it were lost. MITER_LIMIT
// still keeps the corner finite: at its 10⁵ margins, slivers down to 10⁻⁶
// radians keep a margin above the snapping. A finite triangle reaching behind
// the eye, or beyond REACH pixels where the rasterizer's fixed point ends, is
// clipped to the view's frustum (widened by GUARD pixels) in clip space, and
// the triangle around the rectangle around that part drawn instead, tested
// exactly all the same: left to the rasterizer, as it was, its edges leaked
// against the exactly tested triangles beside it.
#include "methods/kit/frame/scene.glsl"
#include "methods/kit/counting/lit_intervals.glsl"

#ifdef KEPT_TRIANGLES
// The triangles CountedDraw kept (cull_counted.comp.glsl), by index.
layout(std430, binding = BINDING_KEPT) readonly buffer KeptBlock { uint kept[]; };
#endif

flat out int triangle;
flat out int exact;  // 1: the fragment tests its ray against the triangle

const float COVER_MARGIN = 1.0 / 16.0;
const float MITER_LIMIT = 1e5;
const float REACH = 1e6;
const float GUARD = 4.0;
const int MAX_PART = 7;  // a triangle clipped by four planes

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

// Corner k of triangle s (counter-clockwise when side is 1) moved to where its edges, pushed
// out by the margin, meet: along the outward bisector, by margin / sin(half the angle) =
// 2 margin / |n0 + n1|. The bisector from the sum of the edges' normals, which cancels at a
// sharp corner, or there from the difference of their directions.
vec2 grown_corner(vec2 s[3], float side, int k) {
  vec2 before = normalize(s[k] - s[(k + 2) % 3]), after = normalize(s[(k + 1) % 3] - s[k]);
  vec2 normals = side * vec2(before.y + after.y, -before.x - after.x);  // the edges' outward unit normals, summed
  vec2 tip = before - after;  // along the bisector, outward
  vec2 bisector = normalize(dot(normals, normals) > dot(tip, tip) ? normals : tip);
  return s[k] + COVER_MARGIN * min(2.0 / length(normals), MITER_LIMIT) * bisector;
}

// How far clip-space point p lies inside plane k of the frustum widened by GUARD pixels
// (|x| ≤ reach.x·w, |y| ≤ reach.y·w), in clip units: negative outside.
float inside(vec4 p, int k) {
  vec2 reach = 1.0 + 2.0 * GUARD / frame.size;
  float c = k < 2 ? p.x : p.y;
  return (k < 2 ? reach.x : reach.y) * p.w - (k % 2 == 0 ? c : -c);
}

// The triangle's part in the widened frustum, in pixels from the image's centre: n corners,
// fewer than 3 where it lies outside. Each corner and its side of a plane are carried to the
// next edge rather than read again: an array read at a data index is a gather per lane on
// llvmpipe, and reading each corner twice made this fallback most of the program's compile
// (docs/decisions.md "The first frame (issue 28)").
int visible_part(vec4 clip[3], out vec2 part[MAX_PART]) {
  vec4 polygon[MAX_PART], clipped[MAX_PART];
  for (int i = 0; i < 3; ++i) polygon[i] = clip[i];
  int n = 3;
  for (int k = 0; k < 4; ++k) {
    int m = 0;
    vec4 first = polygon[0], p = first;
    float d_first = inside(first, k), dp = d_first;
    for (int i = 0; i < n; ++i) {
      vec4 q = i + 1 < n ? polygon[i + 1] : first;
      float dq = i + 1 < n ? inside(q, k) : d_first;
      if (dp >= 0.0) clipped[m++] = p;
      if ((dp >= 0.0) != (dq >= 0.0)) clipped[m++] = mix(p, q, dp / (dp - dq));
      p = q;
      dp = dq;
    }
    polygon = clipped;
    n = m;
  }
  for (int i = 0; i < n; ++i) part[i] = 0.5 * frame.size * polygon[i].xy / polygon[i].w;
  return n;
}

// Corner k of the triangle around polygon part[0 … n), grown by the margin: twice the
// rectangle around it along its longest edge (the longest kept, not read again).
vec2 enclosing_corner(vec2 part[MAX_PART], int n, int k) {
  vec2 start = part[0], end = part[1];
  float longest = distance(end, start);
  for (int i = 1; i < n; ++i) {
    vec2 next = i + 1 < n ? part[i + 1] : part[0];
    float length_i = distance(next, part[i]);
    if (length_i > longest) {
      start = part[i];
      end = next;
      longest = length_i;
    }
  }
  vec2 along = normalize(end - start), across = vec2(-along.y, along.x);
  vec2 lo = vec2(0.0), hi = vec2(0.0);
  for (int i = 0; i < n; ++i) {
    vec2 p = vec2(dot(part[i] - start, along), dot(part[i] - start, across));
    lo = min(lo, p);
    hi = max(hi, p);
  }
  lo -= COVER_MARGIN;
  hi += COVER_MARGIN;
  vec2 corner = lo + vec2(k == 1 ? 2.0 : 0.0, k == 2 ? 2.0 : 0.0) * (hi - lo);
  return start + corner.x * along + corner.y * across;
}

void main() {
#ifdef KEPT_TRIANGLES
  triangle = int(kept[gl_VertexID / 3]);
#else
  triangle = gl_VertexID / 3;  // every triangle drawn (beam_volumes' signed sum: blending adds in draw order)
#endif
  int k = gl_VertexID % 3;
  vec4 clip[3];
  bool at_infinity = false, in_front = true;
  for (int i = 0; i < 3; ++i) {
    vec4 corner = counted[triangle].corners[i];
    clip[i] = frame.view_projection * corner;
    at_infinity = at_infinity || corner.w == 0.0;
    in_front = in_front && clip[i].w > 0.0;
  }
  exact = 0;
  gl_Position = clip[k];
  if (at_infinity) return;
  exact = 1;
  if (in_front) {
    vec2 s[3];
    for (int i = 0; i < 3; ++i) s[i] = 0.5 * frame.size * clip[i].xy / clip[i].w;
    float area = cross2(s[1] - s[0], s[2] - s[0]);
    if (!(abs(area) > 0.0)) return;  // edge-on: no pixel's ray crosses it
    vec2 extent = max(max(abs(s[0]), abs(s[1])), abs(s[2]));
    if (max(extent.x, extent.y) <= REACH) {
      vec2 moved = grown_corner(s, sign(area), k);
      gl_Position = vec4(moved / (0.5 * frame.size) * clip[k].w, clip[k].z, clip[k].w);
      return;
    }
  }
  vec2 part[MAX_PART];
  int n = visible_part(clip, part);
  vec2 corner = n >= 3 ? enclosing_corner(part, n, k) : vec2(0.0);
  gl_Position = vec4(corner / (0.5 * frame.size), 0.0, 1.0);
}
