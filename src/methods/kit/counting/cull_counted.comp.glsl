// Which counted triangles a pixel's ray can cross (CountedDraw, before
// crossings.vert.glsl draws them): a light volume mesh has millions of
// triangles, most of them smaller than a pixel and between pixel centres, and
// llvmpipe spent nearly all of light_volume's frame running the vertex stage
// for them (docs/decisions.md). A triangle with finite corners, all in front
// of the eye, is dropped when no pixel centre lies within COVER_MARGIN of the
// box around its projection: a ray crosses a triangle only through its
// projection, and the vertex stage grows triangles by that margin, no more,
// for the rasterizer's sake. Edge-on triangles are dropped too (the vertex
// stage covers nothing for them). Any triangle, its corners at infinity or
// not, is dropped when all its corners lie on the outer side of one plane of
// the view's frustum in clip space — behind the eye (w ≤ 0: a ray meets
// nothing at t ≤ 0) or beyond a side, which every pixel centre is inside —
// since the triangle is their positive combinations. Other corners at
// infinity, behind the eye or beyond SAFE pixels (where float positions are
// coarser than a thousandth of a pixel) keep their triangle. The kept ones' indices are appended, and the
// draw's vertex count with them (an indirect draw: no wait for the count).
#include "methods/kit/frame/scene.glsl"
#include "methods/kit/counting/lit_intervals.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = BINDING_KEPT) writeonly buffer KeptBlock { uint kept[]; };
layout(std430, binding = BINDING_KEPT_DRAW) coherent buffer DrawBlock {
  uint vertex_count;  // DrawArraysIndirectCommand: 3 per kept triangle
  uint instance_count, first, base_instance;
};

uniform int item_count;

const float COVER_MARGIN = 1.0 / 16.0;  // crossings.vert.glsl's
const float SAFE = 1e4;

// Whether some pixel centre (i + 0.5 in pixels from the image's corner) lies in [lo, hi] along one axis.
bool holds_centre(float lo, float hi, float size) {
  float first = max(ceil(lo + 0.5 * size - 0.5), 0.0), last = min(floor(hi + 0.5 * size - 0.5), size - 1.0);
  return first <= last;
}

bool may_cross_a_ray(CountedTriangle c) {
  vec4 clip[3];
  bvec4 beyond = bvec4(true);  // all corners beyond the side x = w, x = −w, y = w, y = −w
  bool behind = true, projected = true;
  for (int i = 0; i < 3; ++i) {
    clip[i] = frame.view_projection * c.corners[i];
    beyond = bvec4(ivec4(beyond) & ivec4(greaterThan(vec4(clip[i].x, -clip[i].x, clip[i].y, -clip[i].y), vec4(clip[i].w))));
    behind = behind && !(clip[i].w > 0.0);
    projected = projected && c.corners[i].w != 0.0 && clip[i].w > 0.0;
  }
  if (behind || any(beyond)) return false;
  if (!projected) return true;
  vec2 s[3];
  for (int i = 0; i < 3; ++i) s[i] = 0.5 * frame.size * clip[i].xy / clip[i].w;
  vec2 lo = min(min(s[0], s[1]), s[2]), hi = max(max(s[0], s[1]), s[2]);
  if (!(max(max(abs(lo.x), abs(lo.y)), max(abs(hi.x), abs(hi.y))) <= SAFE)) return true;
  vec2 e1 = s[1] - s[0], e2 = s[2] - s[0];
  if (!(abs(e1.x * e2.y - e1.y * e2.x) > 0.0)) return false;
  return holds_centre(lo.x - COVER_MARGIN, hi.x + COVER_MARGIN, frame.size.x) &&
         holds_centre(lo.y - COVER_MARGIN, hi.y + COVER_MARGIN, frame.size.y);
}

void main() {
  uint item = gl_WorkGroupID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x + gl_GlobalInvocationID.x;
  if (item >= uint(item_count) || !may_cross_a_ray(counted[item])) return;
  kept[atomicAdd(vertex_count, 3u) / 3u] = item;
}
