// The counted triangles (lit_intervals.glsl), three vertices each fetched from
// their buffer by gl_VertexID; no vertex attributes. Corners at infinity
// (w = 0, as robust shadow volumes extrude) are projected as they are, so no
// far plane cuts a shadow plane.
//
// A triangle whose corners are all finite and in front of the eye is drawn
// grown by COVER_MARGIN pixels on every side (each corner moved to where its
// two edges, pushed out, meet; a sliver's sharp corners at most MITER_LIMIT
// margins), and its fragments decide whether their ray crosses it by an exact
// test (crossings.frag.glsl): the rasterizer snaps corners to 1/256 pixel,
// and where two slivers of a light volume's shadow side meet a pixel's centre
// within that, it covered neither and lost the crossing. 1/16 pixel clears
// the snapping many times over; a whole pixel made every small triangle of a
// light volume mesh cover its neighbours' pixels too (docs/decisions.md).
#include "methods/kit/scene.glsl"
#include "methods/kit/lit_intervals.glsl"

flat out int triangle;
flat out int exact;  // 1: the fragment tests its ray against the triangle

const float COVER_MARGIN = 1.0 / 16.0;
const float MITER_LIMIT = 64.0;

float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

void main() {
  triangle = gl_VertexID / 3;
  int k = gl_VertexID % 3;
  vec4 clip[3];
  bool finite = true;
  for (int i = 0; i < 3; ++i) {
    vec4 corner = counted[triangle].corners[i];
    clip[i] = frame.view_projection * corner;
    finite = finite && corner.w != 0.0 && clip[i].w > 0.0;
  }
  exact = 0;
  gl_Position = clip[k];
  if (!finite) return;
  vec2 s[3];
  for (int i = 0; i < 3; ++i) s[i] = 0.5 * frame.size * clip[i].xy / clip[i].w;
  float area = cross2(s[1] - s[0], s[2] - s[0]);
  if (!(abs(area) > 0.0)) return;  // edge-on: no pixel's ray crosses it
  exact = 1;
  float side = sign(area);  // counter-clockwise: the interior on the left of each edge
  vec2 before = s[k] - s[(k + 2) % 3], after = s[(k + 1) % 3] - s[k];
  vec2 n0 = normalize(side * vec2(before.y, -before.x)), n1 = normalize(side * vec2(after.y, -after.x));
  vec2 miter = (n0 + n1) / max(1.0 + dot(n0, n1), 1e-6);
  float length_miter = length(miter);
  if (length_miter > MITER_LIMIT) miter *= MITER_LIMIT / length_miter;
  vec2 moved = s[k] + COVER_MARGIN * miter;
  gl_Position = vec4(moved / (0.5 * frame.size) * clip[k].w, clip[k].z, clip[k].w);
}
