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
  uint loop_limited;   // pixels whose sum llvmpipe's loop limit cut short (lit_intervals.comp.glsl)
  uint unfinished;     // pixels that go on in another pass of it
};

uint pack_crossing(int light, int change) { return (uint(light) << 16) | uint(change + 32768); }
int crossing_light(uint bits) { return int(bits >> 16); }
int crossing_change(uint bits) { return int(bits & 0xffffu) - 32768; }

// An edge's function (a 2×2 determinant of its corners p, q in the sheared
// frame below), or where that is 0 — the ray on the edge's line — its sign
// with the ray moved by (1, η), η → 0+ (simulation of simplicity): the two
// triangles that share an edge get opposite values, so that exactly one
// holds the ray, and at a shared corner exactly one of those around it. Taking
// 0 as inside counted a ray along an edge twice. `precise`: a fused
// multiply–add would round the two orders differently.
float edge_function(vec2 p, vec2 q) {
  precise float e = p.x * q.y - p.y * q.x;
  return e != 0.0 ? e : (p.y != q.y ? p.y - q.y : q.x - p.x);
}

// Whether the ray from `origin` along `dir` passes through triangle (a, b, c):
// the watertight test of Woop, Benthin & Wald 2013, in a frame sheared so the
// ray runs along an axis. An edge's function is a 2×2 determinant of its two
// corners, so the two triangles that share an edge get exactly opposite
// values: no ray passes between them, and none is counted by both. A triangle
// seen edge-on holds no ray: its functions are not all of one sign.
bool ray_crosses(vec3 origin, vec3 dir, vec3 a, vec3 b, vec3 c) {
  vec3 d = abs(dir);
  int kz = d.x > d.y ? (d.x > d.z ? 0 : 2) : (d.y > d.z ? 1 : 2);
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (dir[kz] < 0.0) {
    int swap = kx;
    kx = ky;
    ky = swap;
  }
  vec2 shear = vec2(dir[kx], dir[ky]) / dir[kz];
  vec3 pa = a - origin, pb = b - origin, pc = c - origin;
  vec2 A = vec2(pa[kx], pa[ky]) - shear * pa[kz];
  vec2 B = vec2(pb[kx], pb[ky]) - shear * pb[kz];
  vec2 C = vec2(pc[kx], pc[ky]) - shear * pc[kz];
  float u = edge_function(C, B), v = edge_function(A, C), w = edge_function(B, A);
  return (u > 0.0 && v > 0.0 && w > 0.0) || (u < 0.0 && v < 0.0 && w < 0.0);
}

// Whether a fragment of counted triangle c (crossings.vert.glsl: `exact` when
// its corners are finite) stands for a crossing of the pixel's ray along `dir`.
bool covers(int exact, CountedTriangle c, vec3 dir) {
  return exact == 0 || ray_crosses(frame.eye, dir, c.corners[0].xyz / c.corners[0].w,
                                   c.corners[1].xyz / c.corners[1].w, c.corners[2].xyz / c.corners[2].w);
}
