// The per-pixel lists of shadow-plane crossings shared by the crossing pass
// (crossings.vert/.frag.glsl) and the resolve (resolve.comp.glsl).
//
// A plane is the quad of one caster edge (a, b) extruded away from its light to
// infinity (geometry/shadow_edges.hpp): its weight w is the signed number of
// triangle shadow volumes the edge bounds, so crossing it along a view ray
// changes that light's shadow count by +w where dot(n, dir) > 0 and by −w
// otherwise. A node of a pixel's list holds one crossing: its distance t along
// the pixel's ray, the light, the change of the count, and the next node.

struct ShadowPlane {
  vec4 a;      // xyz: an end of the edge (world), w: the weight
  vec4 b;      // xyz: the other end, w: the light's index
  vec4 plane;  // xyz: the unit normal n (computed in double on the CPU), w: n·x for x on the plane
};

layout(std430, binding = BINDING_PLANES) readonly buffer PlaneBlock { ShadowPlane planes[]; };

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
