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
// grown by the same margin in homogeneous coordinates and left to GL's
// clipping, tested exactly all the same: drawn ungrown, as it once was, its
// edges leaked against the exactly tested triangles beside it.
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

// Corner k of the triangle grown by the margin in the view's homogeneous 2D coordinates, where
// no corner needs to be in front of the eye (Olano & Greer 1997's edge functions): each corner
// (x, y, w) in pixels, the line through two corners their cross product, pushed out by the
// margin, and each corner again where its two lines meet, signed so that it is the same point
// at a margin of 0. Returned in clip space: GL's clipping then cuts the grown triangle to the
// view. Clipping the triangle here and drawing the triangle around its part, as before, wrote
// arrays at data indices, a scatter per lane on llvmpipe: most of the program's compile, and
// run masked by every vertex (docs/decisions.md "The first frame (issue 28)"). In double: a
// line through two corners far apart on the image (or far off it) is their nearly parallel
// vectors' cross product, and in float its error passed the margin (three_lights lost pixels).
vec4 grown_homogeneous_corner(vec4 clip[3], int k) {
  vec2 half_size = 0.5 * frame.size;
  dvec3 v[3];
  for (int i = 0; i < 3; ++i) v[i] = normalize(dvec3(clip[i].xy * half_size, clip[i].w));
  double orientation = sign(dot(v[0], cross(v[1], v[2])));  // 0: edge-on, no pixel's ray crosses it
  // Line i runs through the corners other than i; pixel p = (x, y, 1) is inside where line_i · p
  // has the orientation's sign, and |line_i · p| / |line_i.xy| pixels from it.
  dvec3 line[3];
  for (int i = 0; i < 3; ++i) {
    dvec3 l = cross(v[(i + 1) % 3], v[(i + 2) % 3]);
    line[i] = l + dvec3(0.0, 0.0, orientation * COVER_MARGIN * length(l.xy));
  }
  // The grown triangle is the intersection of the grown half-planes: the points x where each
  // line_i · x has the orientation's sign. The corners' cone is that set when they are signed
  // by the lines' determinant too: volume² at a margin of 0, it changes sign where the triangle
  // reaches behind the eye and the lines, pushed out, pass the projected corner opposite one of
  // them (its part in view is unbounded, and that corner's triangle shrinks). Taken as +1 there,
  // the cone was the complement, and three_lights lost pixels. Three lines through one point
  // bound no triangle: then the whole view is drawn, the exact test deciding.
  double turn = sign(dot(line[0], cross(line[1], line[2])));
  if (orientation == 0.0) return vec4(0.0, 0.0, 0.0, 1.0);
  if (turn == 0.0) return vec4(k == 1 ? 3.0 : -1.0, k == 2 ? 3.0 : -1.0, 0.0, 1.0);
  dvec3 corner = orientation * turn * cross(line[(k + 1) % 3], line[(k + 2) % 3]);
  corner /= length(corner);  // within float's range; the point is the same
  return vec4(vec2(corner.xy) / half_size, 0.0, float(corner.z));
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
  gl_Position = grown_homogeneous_corner(clip, k);
}
