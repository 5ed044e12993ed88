// Lit intervals by counting crossings (docs/design.md §3, "lit intervals"):
// the surfaces that bound each light's lit region — shadow planes extruded
// from casters' silhouettes (shadow_planes), the faces of lit pyramids
// (beam_volumes) — drawn as triangles (crossings.vert/.frag.glsl); each
// pixel's crossings with them go to a list that lit_intervals.comp.glsl walks.
//
// A triangle carries its plane (unit normal n, n·x) and a weight w: crossing it
// along a view ray changes its light's count by +w where dot(n, dir) > 0 and
// by −w otherwise; the ray is lit by the light where the count, started at
// the eye's, is 0. A node of a pixel's list holds one crossing: its distance t
// along the pixel's ray, the light, the change of the count, and the next node.

struct CountedTriangle {
  vec4 corners[3];  // homogeneous world positions (w = 0: a point at infinity)
  vec4 plane;       // xyz: the unit normal n (computed in double on the CPU), w: n·x for x on the plane
  ivec4 light_weight;  // x: the light's index, y: the weight w
};

layout(std430, binding = BINDING_COUNTED) readonly buffer CountedBlock { CountedTriangle counted[]; };

const uint END_OF_LIST = 0xffffffffu;

// A node is three words: t's bits, (light << 16) | (change + 32768), next.
layout(std430, binding = BINDING_NODES) coherent buffer NodeBlock { uint nodes[]; };
layout(std430, binding = BINDING_NODE_COUNT) coherent buffer CountBlock {
  uint node_count;     // nodes the crossing pass asked for (more than capacity: it must run again)
  uint node_capacity;  // nodes the pool holds
};

uint pack_crossing(int light, int change) { return (uint(light) << 16) | uint(change + 32768); }
int crossing_light(uint bits) { return int(bits >> 16); }
int crossing_change(uint bits) { return int(bits & 0xffffu) - 32768; }
