// The light volume mesh (methods/kit/light_volume/light_volume_mesh.hpp; Kingston 2018
// §4.3.1, McCool 2000): one light's shadow map turned into a closed mesh
// around its lit region by compute programs over one light at a time, each
// including this file, in the order LightVolumeMesh::build_light runs them:
//   cell_depths.comp.glsl      each grid cell's [min, max] stored depth (shell only)
//   grid_vertices.comp.glsl    the (R+1)² grid vertices per map or cube face: texel, each corner's ray
//                              (origin and step per unit depth) and its cell's depth; shell, the
//                              displaced vertices
//   seam_vertices.comp.glsl    shell cubes: each face's border vertices copied from the face that owns them
//   eye_count.comp.glsl        whether the frame's eye is inside: 0, else 1; and the light's orientation
//   grid_triangles.comp.glsl   texel: six triangles per cell, its flat top and its walls to the next
//                              column's and row's cells; shell: two per cell and surface
//   extra_vertices.comp.glsl   the apex (spot), or the far ring, skirt and cap corners (directional; texel only)
//   extra_triangles.comp.glsl  the side walls (spot, each cube face), or walls, skirt and cap
//                              (directional); shell: the strips between the two surfaces' borders
// Specialized by defines: VOLUME_KIND (the light's mesh), DEPTH_MODE (a
// vertex's depth), CELL_SPLIT (a cell's texels reduced by several
// invocations). No runtime branch on the light's kind.
//
// Vertices are computed once and read by every triangle that uses them (the
// grid's in an image, the rest in a buffer), or (texel) computed from a
// corner's ray and a stored depth by one `precise` expression, so corners
// shared by triangles are the same bits; a shell cube's edge and corner
// vertices are computed by the face that owns them and copied to the others'
// slots, a texel cube's rays come from the lattice point, the same on every face.
#include "methods/kit/frame/frame_data.glsl"
#include "optics/constants.glsl"

#define KIND_SPOT 1
#define KIND_CUBE 2
#define KIND_DIRECTIONAL 3
#define DEPTH_TEXEL 0  // LightVolumeMesh::Depth
#define DEPTH_SHELL 1

layout(local_size_x = 64) in;

layout(std140, binding = BINDING_FRAME_BLOCK) uniform FrameBlock { FrameData frame; };
layout(std430, binding = BINDING_LIGHTS) readonly buffer SceneLights { SceneLight lights[]; };
layout(binding = BINDING_SHADOW_MAPS) uniform sampler2DArray shadow_maps;
layout(binding = BINDING_SHADOW_CUBES) uniform samplerCubeArray shadow_cubes;

// Grid vertex (i, j) of cube face `face` (layer 0 for 2D maps): xyz; a
// shell's outer surface in layers FACES to 2·FACES − 1. Texel: the corner's
// step per unit of depth in layer `face` (w: the depth of the cell whose
// corner v00 it is), its ray's origin in face + FACES (directional; a point
// light's rays start at the light).
layout(rgba32f, binding = 0) uniform image2DArray vertices;
// A cell's [min, max] stored depth as order-preserving bits (order_bits).
layout(r32ui, binding = 1) uniform uimage2DArray cell_low;
layout(r32ui, binding = 2) uniform uimage2DArray cell_high;
// The vertices off the grid: apex; or far ring (4R), skirt corners (4), cap
// corners (4). At ORIENTATION_SLOT, the light's map_orientation (eye_count).
layout(std430, binding = BINDING_VOLUME_EXTRAS) buffer Extras { vec4 extras[]; };
#define ORIENTATION_SLOT (4 * grid + 8)
// CountedTriangle records (lit_intervals.glsl) as five uvec4 words each: the
// three corners, the plane, ivec4(light, weight, 0, 0); this dispatch's first
// record at word_offset of the bound range.
layout(std430, binding = BINDING_VOLUME_RECORDS) writeonly buffer Records { uvec4 records[]; };
layout(std430, binding = BINDING_VOLUME_EYE) writeonly buffer EyeCounts { int eye_counts[]; };

uniform int light_index;
uniform int grid;              // R: cells per side
uniform int map_size;          // S: texels per side of the map (or cube face)
uniform float far_depth;       // depths are clamped to it: beyond every visible point ("no occluder")
uniform float far_ring_depth;  // directional: the skirt's depth, a little beyond far_depth
uniform float cap_depth;       // directional: the cap's depth, before every visible point
uniform float visible_range;   // directional: no visible point is farther than this from the eye
uniform int item_count;        // items of this dispatch
uniform int first_item;        // the dispatch's first item
uniform int word_offset;       // where its first record starts in the bound range, in uvec4 words
uniform int sub_blocks;        // CELL_SPLIT: sub-blocks per cell side

const int CELL_BLOCK = 64;  // texels per side that one invocation reduces

#define LIGHT lights[light_index]

#if VOLUME_KIND == KIND_CUBE
const int FACES = 6;
#else
const int FACES = 1;
#endif
#if DEPTH_MODE == DEPTH_SHELL
const int SURFACES = 2;  // the inner surface (layer face), the outer (face + FACES)
#else
const int SURFACES = 1;
#endif

// ---- depths ---------------------------------------------------------------------

// Non-negative and negative floats as uints in the same order (atomicMin / Max).
uint order_bits(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}
float from_order_bits(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? (u & 0x7fffffffu) : ~u); }

// A stored value as the mesh's depth: +∞, the clear value and anything past
// the backplate become far_depth; a directional light's depth is also kept
// from before the cap.
float clamp_depth(float stored) {
#if VOLUME_KIND == KIND_DIRECTIONAL
  return min(max(stored, cap_depth), far_depth);
#else
  return min(max(stored, 0.0), far_depth);
#endif
}

#if VOLUME_KIND == KIND_CUBE
#include "methods/kit/frame/shadows/cube_faces.glsl"
// Texel `texel` of a face, sampled at its centre (nearest: exactly that texel).
float stored_depth(int face, ivec2 texel) {
  vec2 st = (2.0 * vec2(texel) + 1.0) / float(map_size) - 1.0;
  return textureLod(shadow_cubes, vec4(cube_face_direction(face, st), float(LIGHT.shadow_layer)), 0.0).r;
}
#else
float stored_depth(int face, ivec2 texel) { return texelFetch(shadow_maps, ivec3(texel, LIGHT.shadow_layer), 0).r; }
#endif

// ---- the cube's surface lattice -------------------------------------------------
// Grid vertex (i, j) of face f is lattice point P ∈ [0, R]³ on the cube's
// surface, P = R·(cube_face_direction(f, s, t) + 1)/2 with s = 2i/R − 1, t = 2j/R − 1.

ivec3 lattice(int face, ivec2 v) {
  int R = grid;
  if (face == 0) return ivec3(R, R - v.y, R - v.x);
  if (face == 1) return ivec3(0, R - v.y, v.x);
  if (face == 2) return ivec3(v.x, R, v.y);
  if (face == 3) return ivec3(v.x, 0, R - v.y);
  if (face == 4) return ivec3(v.x, R - v.y, R);
  return ivec3(R - v.x, R - v.y, 0);
}
bool on_face(int face, ivec3 p) {
  int R = grid;
  if (face == 0) return p.x == R;
  if (face == 1) return p.x == 0;
  if (face == 2) return p.y == R;
  if (face == 3) return p.y == 0;
  if (face == 4) return p.z == R;
  return p.z == 0;
}
ivec2 face_coords(int face, ivec3 p) {  // lattice's inverse on a face that holds p
  int R = grid;
  if (face == 0) return ivec2(R - p.z, R - p.y);
  if (face == 1) return ivec2(p.z, R - p.y);
  if (face == 2) return ivec2(p.x, p.z);
  if (face == 3) return ivec2(p.x, R - p.z);
  if (face == 4) return ivec2(p.x, R - p.y);
  return ivec2(R - p.x, R - p.y);
}
// The face that computes (owns) a lattice point: the first that holds it.
int owner(ivec3 p) {
  for (int f = 0; f < 5; ++f)
    if (on_face(f, p)) return f;
  return 5;
}

// ---- the map's rays -------------------------------------------------------------

vec4 matrix_row(mat4 m, int r) { return vec4(m[0][r], m[1][r], m[2][r], m[3][r]); }

// The direction of the points whose shadow_matrix image has NDC xy = ndc: the
// line where the planes (row0 − x·row3)·X = 0 and (row1 − y·row3)·X = 0 meet
// (no inverse, no near plane: exact in float at any field of view), pointing
// away from the light (clip w growing for a perspective map, the light's travel
// for an orthographic one). Not normalized.
vec3 map_ray(vec2 ndc) {
  mat4 m = LIGHT.shadow_matrix;
  vec4 w = matrix_row(m, 3);
  vec3 d = cross((matrix_row(m, 0) - ndc.x * w).xyz, (matrix_row(m, 1) - ndc.y * w).xyz);
#if VOLUME_KIND == KIND_DIRECTIONAL
  return dot(d, LIGHT.direction) < 0.0 ? -d : d;
#else
  return dot(d, w.xyz) < 0.0 ? -d : d;
#endif
}

#if VOLUME_KIND == KIND_DIRECTIONAL
// An orthographic map: the point at depth `depth` (along the light's travel)
// on the line of NDC xy = ndc.
vec3 map_point(vec2 ndc, float depth) {
  mat4 m = LIGHT.shadow_matrix;
  vec4 r0 = matrix_row(m, 0) - ndc.x * matrix_row(m, 3), r1 = matrix_row(m, 1) - ndc.y * matrix_row(m, 3);
  vec3 n0 = r0.xyz, n1 = r1.xyz;  // n·X = −r.w on the line
  float a = dot(n0, n0), b = dot(n0, n1), c = dot(n1, n1);
  vec3 x = ((-r0.w * c + r1.w * b) * n0 + (-r1.w * a + r0.w * b) * n1) / (a * c - b * b);
  vec3 along = map_ray(ndc);
  return x + ((depth - dot(x, LIGHT.direction)) / dot(along, LIGHT.direction)) * along;
}

// How far the skirt reaches in NDC: past every point within visible_range of the eye.
float skirt_extent() {
  mat4 m = LIGHT.shadow_matrix;
  vec4 clip = m * vec4(frame.eye, 1.0);
  vec2 eye = clip.xy / clip.w;
  float e = max(abs(eye.x) + length(matrix_row(m, 0).xyz) * visible_range,
                abs(eye.y) + length(matrix_row(m, 1).xyz) * visible_range);
  return 1.01 * max(e, 1.0);
}
#endif

vec2 grid_ndc(ivec2 v) { return vec2(2 * v - grid) / float(grid); }

// The vertex at depth `depth` on grid vertex v's ray (for cubes, lattice point p's).
vec3 grid_position(ivec2 v, ivec3 p, float depth) {
#if VOLUME_KIND == KIND_CUBE
  return LIGHT.position + depth * normalize(vec3(2 * p - grid) / float(grid));
#elif VOLUME_KIND == KIND_SPOT
  return LIGHT.position + depth * normalize(map_ray(grid_ndc(v)));
#else
  return map_point(grid_ndc(v), depth);
#endif
}

// +1 when the grid's triangles (v00, v10, v11), (v00, v11, v01) face away from
// the light (out of the lit volume), −1 when they must be reversed: the
// handedness of the map's (every cube face's) NDC → direction mapping.
float map_orientation() {
#if VOLUME_KIND == KIND_CUBE
  // det(cube_face_direction(f, (−1, −1)), (1, −1), (1, 1)) = −4 on every face: GL's
  // faces, seen from the cube's centre, all map (s, t) the same way round.
  return -1.0;
#elif VOLUME_KIND == KIND_SPOT
  vec3 a = map_ray(vec2(-1.0)), b = map_ray(vec2(1.0, -1.0)), c = map_ray(vec2(1.0));
  return dot(a, cross(b, c)) > 0.0 ? 1.0 : -1.0;
#else
  vec3 a = map_point(vec2(-1.0), 0.0), b = map_point(vec2(1.0, -1.0), 0.0), c = map_point(vec2(1.0), 0.0);
  return dot(cross(b - a, c - a), LIGHT.direction) > 0.0 ? 1.0 : -1.0;
#endif
}

// The same, a constant of the light: eye_count, run straight after the
// grid's vertices, stores it in the extras' last slot, and the triangles read
// it there. Computed per triangle, a map's three rays were a third of the
// grid triangles' time per frame.
float orientation() {
#if VOLUME_KIND == KIND_CUBE
  return -1.0;
#else
  return extras[ORIENTATION_SLOT].x;
#endif
}

// Grid vertex v of vertex layer `layer` (face + surface·FACES; on a cube's
// seams, the owner's copy).
vec3 grid_vertex(int layer, ivec2 v) { return imageLoad(vertices, ivec3(v, layer)).xyz; }

#if DEPTH_MODE == DEPTH_TEXEL
// The depth of cell c of face `face`: as far as the shadow test calls points
// lit (scene.glsl's shadow_visibility: up to the stored depth, no bias)
// through the texel under the cell's centre (texel c when R = S).
float map_cell_depth(int face, ivec2 c) {
  return clamp_depth(stored_depth(face, min((2 * c + 1) * map_size / (2 * grid), ivec2(map_size - 1))));
}

// The same, as grid_vertices stored it beside the step of the cell's corner
// v00: read once per cell from the map, where a cube's is a sampled direction.
float cell_depth(int face, ivec2 c) { return imageLoad(vertices, ivec3(c, face)).w; }

// Grid vertex v's ray at `depth`. `precise`: the cells and walls that share
// the point compute it apart, and a fused multiply–add in one of them would
// round it differently (the watertight test needs shared corners' bits equal).
// A light at a point is every ray's origin: only a directional map's are stored.
vec3 corner_at(int face, ivec2 v, float depth) {
#if VOLUME_KIND == KIND_DIRECTIONAL
  vec3 origin = imageLoad(vertices, ivec3(v, face + FACES)).xyz;
#else
  vec3 origin = LIGHT.position;
#endif
  precise vec3 point = origin + depth * imageLoad(vertices, ivec3(v, face)).xyz;
  return point;
}
#endif

// Half h (0, 1) of cell c, counter-clockwise in (i, j): grid vertices
// (v00, v10, v11) or (v00, v11, v01).
void half_vertices(int h, ivec2 c, out ivec2 u0, out ivec2 u1, out ivec2 u2) {
  u0 = c;
  u1 = c + (h == 0 ? ivec2(1, 0) : ivec2(1));
  u2 = c + (h == 0 ? ivec2(1) : ivec2(0, 1));
}

// Half h of cell c on vertex layer `layer` (texel: at the cell's depth, face `face`).
void cell_triangle(int face, int layer, ivec2 c, int h, out vec3 a, out vec3 b, out vec3 d) {
  ivec2 u0, u1, u2;
  half_vertices(h, c, u0, u1, u2);
#if DEPTH_MODE == DEPTH_TEXEL
  float depth = cell_depth(face, c);
  a = corner_at(face, u0, depth);
  b = corner_at(face, u1, depth);
  d = corner_at(face, u2, depth);
#else
  a = grid_vertex(layer, u0);
  b = grid_vertex(layer, u1);
  d = grid_vertex(layer, u2);
#endif
}

// Vertex s of the grid's border, counter-clockwise in (i, j): bottom, right, top, left.
ivec2 border(int s) {
  int R = grid;
  s = s % (4 * R);
  int side = s / R, k = s % R;
  if (side == 0) return ivec2(k, 0);
  if (side == 1) return ivec2(R, k);
  if (side == 2) return ivec2(R - k, R);
  return ivec2(0, R - k);
}

// The cell inside border segment s (from border(s) to border(s + 1)).
ivec2 border_cell(int s) { return min(min(border(s), border(s + 1)), ivec2(grid - 1)); }

// This dispatch's item (a 2D dispatch of 64-wide groups, as long as it must be).
uint local_item() { return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u; }

// ---- the passes ------------------------------------------------------------------

void write_triangle(uint index, vec3 a, vec3 b, vec3 c) {
  // The plane from the corner opposite the longest edge (the same orientation
  // as cross(b − a, c − a)): a shadow's side is a sliver a texel wide and the
  // backplate's distance long, and the cross product of its two long edges,
  // nearly parallel, loses the normal's direction in float, the crossing's t
  // with it (lost crossings were single wrong pixels).
  vec3 ab = b - a, bc = c - b, ca = a - c;
  float lab = dot(ab, ab), lbc = dot(bc, bc), lca = dot(ca, ca);
  vec3 apex = a, n = cross(ab, -ca);
  if (lab >= lbc && lab >= lca) {
    apex = c;
    n = cross(ca, -bc);
  } else if (lca >= lab && lca >= lbc) {
    apex = b;
    n = cross(bc, -ab);
  }
  float length_n = length(n);
  n = length_n > 0.0 ? n / length_n : vec3(0.0);  // degenerate: no crossing (t is not finite)
  uint w = uint(word_offset) + 5u * index;
  records[w] = floatBitsToUint(vec4(a, 1.0));
  records[w + 1u] = floatBitsToUint(vec4(b, 1.0));
  records[w + 2u] = floatBitsToUint(vec4(c, 1.0));
  records[w + 3u] = floatBitsToUint(vec4(n, dot(n, apex)));
  records[w + 4u] = uvec4(uint(light_index), 1u, 0u, 0u);
}

// Oriented: (a, b, c) for o > 0, (a, c, b) otherwise. Every pass that writes
// triangles writes one per invocation, by one call with its corners chosen,
// not one per case: GLSL inlines each call, each copy is compiled, and its
// five stores are a loop over the lanes each on llvmpipe (docs/decisions.md
// "The first frame (issue 28)").
void write_oriented(uint index, float o, vec3 a, vec3 b, vec3 c) {
  write_triangle(index, a, o > 0.0 ? b : c, o > 0.0 ? c : b);
}

#if DEPTH_MODE == DEPTH_TEXEL
// Part `part` (0, 1) of the wall between cell c (depth dc) and its neighbour n
// (dn) across their edge a → b (c's border counter-clockwise in (i, j)): the
// quad b_c a_c a_n b_n, c's pyramid side (b_c, a_c, light) plus n's (a_n, b_n,
// light) as the border's sides close the grid (extra_triangles), is
// (b_c, a_c, a_n) and (b_c, a_n, b_n): its corners' grid vertices u and
// depths d. On a cube's edge, c and n lie on two faces, the corners' rays the
// same. Where the depths agree its corners coincide: no area, no crossing.
void wall_triangle(ivec2 a, ivec2 b, float dc, float dn, int part, out ivec2 u0, out float d0, out ivec2 u1,
                   out float d1, out ivec2 u2, out float d2) {
  u0 = b;
  d0 = dc;
  u1 = a;
  d1 = part == 0 ? dc : dn;
  u2 = part == 0 ? a : b;
  d2 = dn;
}
#endif
