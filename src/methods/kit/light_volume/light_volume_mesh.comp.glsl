// The light volume mesh (methods/kit/light_volume/light_volume_mesh.hpp; Kingston 2018
// §4.3.1, McCool 2000): one light's shadow map turned into a closed mesh
// around its lit region, in passes over one light at a time:
//   PASS_CELLS           each grid cell's [min, max] stored depth (shell only)
//   PASS_GRID_VERTICES   the (R+1)² grid vertices per map or cube face: texel, each corner's ray
//                        (origin and step per unit depth); shell, the displaced vertices
//   PASS_EXTRA_VERTICES  the apex (spot), or the far ring, skirt and cap corners (directional; texel only)
//   PASS_GRID_TRIANGLES  texel: six triangles per cell, its flat top and its walls to the next
//                        column's and row's cells; shell: two per cell and surface
//   PASS_EXTRA_TRIANGLES the side walls (spot, each cube face), or walls, skirt and cap
//                        (directional); shell: the strips between the two surfaces' borders
//   PASS_EYE             whether the frame's eye is inside: 0, else 1
//   PASS_SEAMS           shell cubes: each face's border vertices copied from the face that owns them
// Specialized by defines: VOLUME_KIND (the light's mesh), DEPTH_MODE (a
// vertex's depth), PASS, CELL_SPLIT (a cell's texels reduced by several
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
#define PASS_CELLS 0
#define PASS_GRID_VERTICES 1
#define PASS_EXTRA_VERTICES 2
#define PASS_GRID_TRIANGLES 3
#define PASS_EXTRA_TRIANGLES 4
#define PASS_EYE 5
#define PASS_SEAMS 6

layout(local_size_x = 64) in;

layout(std140, binding = BINDING_FRAME_BLOCK) uniform FrameBlock { FrameData frame; };
layout(std430, binding = BINDING_LIGHTS) readonly buffer SceneLights { SceneLight lights[]; };
layout(binding = BINDING_SHADOW_MAPS) uniform sampler2DArray shadow_maps;
layout(binding = BINDING_SHADOW_CUBES) uniform samplerCubeArray shadow_cubes;

// Grid vertex (i, j) of cube face `face` (layer 0 for 2D maps): xyz; a
// shell's outer surface in layers FACES to 2·FACES − 1. Texel: the corner's
// step per unit of depth in layer `face`, its ray's origin in face + FACES.
layout(rgba32f, binding = 0) uniform image2DArray vertices;
// A cell's [min, max] stored depth as order-preserving bits (order_bits).
layout(r32ui, binding = 1) uniform uimage2DArray cell_low;
layout(r32ui, binding = 2) uniform uimage2DArray cell_high;
// The vertices off the grid: apex; or far ring (4R), skirt corners (4), cap corners (4).
layout(std430, binding = BINDING_VOLUME_EXTRAS) buffer Extras { vec4 extras[]; };
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
// handedness of face `face`'s (or the map's) NDC → direction mapping.
float orientation(int face) {
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

// Grid vertex v of vertex layer `layer` (face + surface·FACES; on a cube's
// seams, the owner's copy).
vec3 grid_vertex(int layer, ivec2 v) { return imageLoad(vertices, ivec3(v, layer)).xyz; }

#if DEPTH_MODE == DEPTH_TEXEL
// The depth of cell c of face `face`: as far as the shadow test calls points
// lit (scene.glsl's shadow_visibility: up to the stored depth, no bias)
// through the texel under the cell's centre (texel c when R = S).
float cell_depth(int face, ivec2 c) {
  return clamp_depth(stored_depth(face, min((2 * c + 1) * map_size / (2 * grid), ivec2(map_size - 1))));
}

// Grid vertex v's ray at `depth`. `precise`: the cells and walls that share
// the point compute it apart, and a fused multiply–add in one of them would
// round it differently (the watertight test needs shared corners' bits equal).
vec3 corner_at(int face, ivec2 v, float depth) {
  precise vec3 point = imageLoad(vertices, ivec3(v, face + FACES)).xyz + depth * imageLoad(vertices, ivec3(v, face)).xyz;
  return point;
}
#endif

// Cell c's corners on vertex layer `layer` (texel: at the cell's depth, face `face`).
void cell_corners(int face, int layer, ivec2 c, out vec3 v00, out vec3 v10, out vec3 v01, out vec3 v11) {
#if DEPTH_MODE == DEPTH_TEXEL
  float d = cell_depth(face, c);
  v00 = corner_at(face, c, d);
  v10 = corner_at(face, c + ivec2(1, 0), d);
  v01 = corner_at(face, c + ivec2(0, 1), d);
  v11 = corner_at(face, c + ivec2(1), d);
#else
  v00 = grid_vertex(layer, c);
  v10 = grid_vertex(layer, c + ivec2(1, 0));
  v01 = grid_vertex(layer, c + ivec2(0, 1));
  v11 = grid_vertex(layer, c + ivec2(1));
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

// Oriented: (a, b, c) for o > 0, (a, c, b) otherwise.
void write_oriented(uint index, float o, vec3 a, vec3 b, vec3 c) {
  if (o > 0.0) write_triangle(index, a, b, c);
  else write_triangle(index, a, c, b);
}

#if DEPTH_MODE == DEPTH_TEXEL
// The wall between cell c (depth dc) and its neighbour n (dn) across their
// edge a → b (c's border counter-clockwise in (i, j)): the quad b_c a_c a_n
// b_n, c's pyramid side (b_c, a_c, light) plus n's (a_n, b_n, light) as the
// border's sides close the grid (extra_triangles); on a cube's edge,
// c and n lie on two faces, the corners' rays the same. Where the depths agree its
// corners coincide: no area, no crossing.
void wall(uint index, float o, int face, ivec2 a, ivec2 b, float dc, float dn) {
  vec3 ac = corner_at(face, a, dc), bc = corner_at(face, b, dc);
  vec3 an = corner_at(face, a, dn), bn = corner_at(face, b, dn);
  write_oriented(index, o, bc, ac, an);
  write_oriented(index + 1u, o, bc, an, bn);
}
#endif

#if PASS == PASS_CELLS
void cells(uint item) {
  int R = grid, S = map_size;
#ifdef CELL_SPLIT
  uint per_cell = uint(sub_blocks * sub_blocks);
  uint cell = item / per_cell, sub = item % per_cell;
#else
  uint cell = item;
#endif
  int face = int(cell / uint(R * R)), rest = int(cell % uint(R * R));
  ivec2 c = ivec2(rest % R, rest / R);
  ivec2 lo = c * S / R, hi = ((c + 1) * S + R - 1) / R;  // the texels the cell overlaps
#ifdef CELL_SPLIT
  lo += ivec2(int(sub) % sub_blocks, int(sub) / sub_blocks) * CELL_BLOCK;
  hi = min(hi, lo + CELL_BLOCK);
#endif
  float low = positive_infinity(), high = -positive_infinity();
  for (int y = lo.y; y < hi.y; ++y)
    for (int x = lo.x; x < hi.x; ++x) {
      float d = clamp_depth(stored_depth(face, ivec2(x, y)));
      low = min(low, d);
      high = max(high, d);
    }
  ivec3 at = ivec3(c, face);
#ifdef CELL_SPLIT
  if (lo.x < hi.x && lo.y < hi.y) {
    imageAtomicMin(cell_low, at, order_bits(low));
    imageAtomicMax(cell_high, at, order_bits(high));
  }
#else
  imageStore(cell_low, at, uvec4(order_bits(low)));
  imageStore(cell_high, at, uvec4(order_bits(high)));
#endif
}
#endif

#if PASS == PASS_GRID_VERTICES
#if DEPTH_MODE == DEPTH_SHELL
// The largest angle, seen from the light, between two corners of a grid cell:
// its diagonal at the map's (or face's) centre, where a rectilinear map's
// cells are widest.
float cos_widest_cell() {
#if VOLUME_KIND == KIND_CUBE
  return 1.0 / sqrt(1.0 + 8.0 / float(grid * grid));
#else
  return dot(normalize(map_ray(vec2(0.0))), normalize(map_ray(vec2(2.0 / float(grid)))));
#endif
}

// One texel past `stored`, a texel's size there being (k·r + c)/S: the shell's
// outer grid keeps that thickness where its cells' texels agree, so its
// surface stays a closed two-manifold (inner and outer would meet there); a
// shell that grows stays conservative.
float past_texel(float stored) {
  float b = 1.0 / frame.shadow_resolution;
#if VOLUME_KIND == KIND_DIRECTIONAL
  return stored + b * LIGHT.texel_constant;
#else
  return (stored + b * LIGHT.texel_constant) / max(1.0 - b * LIGHT.texel_per_distance, 1e-6);
#endif
}

// An outer vertex's distance, from the farthest stored depth of its cells
// (where the shadow test stops calling points lit): a texel past it, and for a
// light at a point past the chords between a cell's corners: a point of a
// triangle whose corners lie at distances ≥ D, at angles ≤ α apart as seen
// from the light, is at distance ≥ D·cos α (its projection on one corner's
// direction). An inner vertex needs neither: a triangle whose corners lie
// within distance D of the light lies within it (the ball is convex).
float beyond_lit(float stored) {
#if VOLUME_KIND == KIND_DIRECTIONAL
  return past_texel(stored);
#else
  return past_texel(stored) / cos_widest_cell();
#endif
}

// The extremes of the stored depths over the cells of `face` around vertex v.
void gather_cells(int face, ivec2 v, inout float low, inout float high) {
  ivec2 lo = max(v - 1, ivec2(0)), hi = min(v, ivec2(grid - 1));
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      low = min(low, from_order_bits(imageLoad(cell_low, ivec3(x, y, face)).r));
      high = max(high, from_order_bits(imageLoad(cell_high, ivec3(x, y, face)).r));
    }
}
#endif

void grid_vertices(uint item) {
  int n = grid + 1;
  int face = int(item / uint(n * n)), rest = int(item % uint(n * n));
  ivec2 v = ivec2(rest % n, rest / n);
  ivec3 p = lattice(face, v);
#if VOLUME_KIND == KIND_CUBE && DEPTH_MODE == DEPTH_SHELL
  if (owner(p) != face) return;  // another face computes this edge or corner vertex
#endif
#if DEPTH_MODE == DEPTH_TEXEL
  // grid_position as origin + depth · step.
  vec3 origin = LIGHT.position, step;
#if VOLUME_KIND == KIND_CUBE
  step = normalize(vec3(2 * p - grid) / float(grid));
#elif VOLUME_KIND == KIND_SPOT
  step = normalize(map_ray(grid_ndc(v)));
#else
  vec3 along = map_ray(grid_ndc(v));
  step = along / dot(along, LIGHT.direction);
  origin = map_point(grid_ndc(v), 0.0);
#endif
  imageStore(vertices, ivec3(v, face), vec4(step, 0.0));
  imageStore(vertices, ivec3(v, face + FACES), vec4(origin, 1.0));
#else
  float low = positive_infinity(), high = -positive_infinity();
#if VOLUME_KIND == KIND_CUBE
  // Every cell around the lattice point, on every face that holds it (constant faces: unrolled).
#define GATHER_FACE(f) if (on_face(f, p)) gather_cells(f, face_coords(f, p), low, high);
  GATHER_FACE(0) GATHER_FACE(1) GATHER_FACE(2) GATHER_FACE(3) GATHER_FACE(4) GATHER_FACE(5)
#undef GATHER_FACE
#else
  gather_cells(0, v, low, high);
#endif
  imageStore(vertices, ivec3(v, face), vec4(grid_position(v, p, low), 1.0));
  imageStore(vertices, ivec3(v, face + FACES), vec4(grid_position(v, p, beyond_lit(high)), 1.0));
#endif
}
#endif

#if PASS == PASS_EXTRA_VERTICES
void extra_vertices(uint item) {
#if VOLUME_KIND == KIND_SPOT
  extras[0] = vec4(LIGHT.position, 1.0);
#elif VOLUME_KIND == KIND_DIRECTIONAL
  int ring = 4 * grid, k = int(item);
  const vec2 corners[4] = vec2[](vec2(-1.0), vec2(1.0, -1.0), vec2(1.0), vec2(-1.0, 1.0));
  vec2 ndc;
  float depth = far_ring_depth;
  if (k < ring) ndc = grid_ndc(border(k));          // under the grid's border
  else if (k < ring + 4) ndc = corners[k - ring] * skirt_extent();  // the skirt's corners
  else {                                            // the cap's corners
    ndc = corners[k - ring - 4] * skirt_extent();
    depth = cap_depth;
  }
  extras[k] = vec4(map_point(ndc, depth), 1.0);
#endif
}
#endif

#if PASS == PASS_GRID_TRIANGLES
// Cell c's two triangles on vertex layer `layer`, from record `index`.
void cell_triangles(uint index, float o, int face, int layer, ivec2 c) {
  vec3 v00, v10, v01, v11;
  cell_corners(face, layer, c, v00, v10, v01, v11);
  write_oriented(index, o, v00, v10, v11);
  write_oriented(index + 1u, o, v00, v11, v01);
}


void grid_triangles(uint item, uint local) {
  int R = grid;
  int face = int(item / uint(R * R)), rest = int(item % uint(R * R));
  ivec2 c = ivec2(rest % R, rest / R);
  float o = orientation(face);
#if DEPTH_MODE == DEPTH_SHELL
  cell_triangles(4u * local, -o, face, face, c);  // the inner surface faces the light: out of the shell
  cell_triangles(4u * local + 2u, o, face, face + FACES, c);
#else
  // The shadow map's own steps: the texel's flat top, at its depth, over
  // exactly the directions that read it, and the walls to the next column's
  // and row's cells. The last column's and row's walls are the border's
  // sides (extra_triangles): here they get the cell's own depth, no area.
  cell_triangles(6u * local, o, face, face, c);
  float d = cell_depth(face, c);
  float right = c.x + 1 < R ? cell_depth(face, c + ivec2(1, 0)) : d;
  float up = c.y + 1 < R ? cell_depth(face, c + ivec2(0, 1)) : d;
  wall(6u * local + 2u, o, face, c + ivec2(1, 0), c + ivec2(1), d, right);
  wall(6u * local + 4u, o, face, c + ivec2(1), c + ivec2(0, 1), d, up);
#endif
}
#endif

#if PASS == PASS_EXTRA_TRIANGLES
#if DEPTH_MODE == DEPTH_SHELL
// A shell's side (spot: on the frustum's, directional: on the map column's):
// per border segment s the quad between the inner and the outer surface's
// border, two triangles whose edges run against the outer grid's (wound as the
// texel mesh's grid) and the inner grid's (wound the other way).
void extra_triangles(uint item, uint local) {
  int s = int(item);
  float o = orientation(0);
  vec3 i0 = grid_vertex(0, border(s)), i1 = grid_vertex(0, border(s + 1));
  vec3 u0 = grid_vertex(1, border(s)), u1 = grid_vertex(1, border(s + 1));
  write_oriented(2u * local, o, u1, u0, i0);
  write_oriented(2u * local + 1u, o, u1, i0, i1);
}
#else
#if VOLUME_KIND == KIND_CUBE
// Border segment s of face `face` (from border(s) to border(s + 1)) lies on a
// cube edge: the other face that holds both ends, and its cell there.
void across_seam(int face, int s, out int other, out ivec2 cell) {
  ivec3 p0 = lattice(face, border(s)), p1 = lattice(face, border(s + 1));
  other = 0;
  for (int g = 0; g < 6; ++g)
    if (g != face && on_face(g, p0) && on_face(g, p1)) other = g;
  cell = min(min(face_coords(other, p0), face_coords(other, p1)), ivec2(grid - 1));
}
#else
// On border vertex s, the depth where the two border segments that meet there
// (s − 1 and s) leave their cells' wall to a common side: the nearer cell's
// depth for a spot (its sides run to the apex), the farther for a
// directional map (to the far ring). One corner for both, so the border's
// sides share their edges exactly: overlapping edges of different lengths,
// met by every ray near a spot's apex, let the ray test hold a crossing twice
// or not at all.
float border_end(int s) {
  float before = cell_depth(0, border_cell(s + 4 * grid - 1)), after = cell_depth(0, border_cell(s));
#if VOLUME_KIND == KIND_SPOT
  return min(before, after);
#else
  return max(before, after);
#endif
}

// Part `part` (0, 1) of border segment s's side from the cell's depth d to
// the common ends (border_end): (b1·d, b0·d, b0·e0) and (b1·d, b0·e0, b1·e1),
// no area where an end is d. Returns the ends, b0·e0 and b1·e1, where the
// side goes on to the apex or the far ring.
void border_step(uint index, float o, int s, int part, out vec3 e0, out vec3 e1) {
  float d = cell_depth(0, border_cell(s));
  e0 = corner_at(0, border(s), border_end(s));
  e1 = corner_at(0, border(s + 1), border_end(s + 1));
  vec3 b0 = corner_at(0, border(s), d), b1 = corner_at(0, border(s + 1), d);
  if (part == 0) write_oriented(index, o, b1, b0, e0);
  else if (part == 1) write_oriented(index, o, b1, e0, e1);
}
#endif

// The grid runs along its border from border(s) to border(s + 1) when o > 0:
// what closes it runs back.
void extra_triangles(uint item, uint local) {
  int R = grid, ring = 4 * R, k = int(item);
#if VOLUME_KIND == KIND_CUBE
  // Per face and border segment: the wall to the cell across the cube's edge,
  // from the face of the lower index (the other's: no area).
  int face = k / ring, s = k % ring, other;
  ivec2 cell;
  across_seam(face, s, other, cell);
  float d = cell_depth(face, border_cell(s));
  wall(2u * local, orientation(face), face, border(s), border(s + 1), d, face < other ? cell_depth(other, cell) : d);
#elif VOLUME_KIND == KIND_SPOT
  // Per border segment: its step to the common ends, and from them to the apex.
  float o = orientation(0);
  vec3 e0, e1;
  border_step(local, o, k / 3, k % 3, e0, e1);
  if (k % 3 == 2) write_oriented(local, o, e1, e0, extras[0].xyz);
#elif VOLUME_KIND == KIND_DIRECTIONAL
  float o = orientation(0);
  // [0, 16R): per border segment its step to the common ends E, and walls down
  // from them to the far ring F; [16R, 20R + 4): the skirt at the far depth,
  // per side a fan from its outer corner O; then the outer walls up to the cap
  // corners Q (8), then the cap (2).
  if (k < 4 * ring) {
    int s = k / 4;
    vec3 e0, e1;
    border_step(local, o, s, k % 4, e0, e1);
    vec3 f0 = extras[s].xyz, f1 = extras[(s + 1) % ring].xyz;
    if (k % 4 == 2) write_oriented(local, o, e1, e0, f0);
    else if (k % 4 == 3) write_oriented(local, o, e1, f0, f1);
  } else if (k < 4 * ring + 4 * (R + 1)) {
    int side = (k - 4 * ring) / (R + 1), j = (k - 4 * ring) % (R + 1);
    vec3 outer = extras[ring + side].xyz;
    if (j < R) {
      int s = side * R + j;
      write_oriented(local, o, outer, extras[(s + 1) % ring].xyz, extras[s].xyz);
    } else {
      write_oriented(local, o, extras[((side + 1) * R) % ring].xyz, outer, extras[ring + (side + 1) % 4].xyz);
    }
  } else if (k < 4 * ring + 4 * (R + 1) + 8) {
    int side = (k - 4 * ring - 4 * (R + 1)) / 2;
    vec3 o0 = extras[ring + side].xyz, o1 = extras[ring + (side + 1) % 4].xyz;
    vec3 q0 = extras[ring + 4 + side].xyz, q1 = extras[ring + 4 + (side + 1) % 4].xyz;
    if (k % 2 == 0) write_oriented(local, o, o1, o0, q0);
    else write_oriented(local, o, o1, q0, q1);
  } else {
    vec3 q0 = extras[ring + 4].xyz, q1 = extras[ring + 5].xyz, q2 = extras[ring + 6].xyz, q3 = extras[ring + 7].xyz;
    if (k % 2 == 0) write_oriented(local, o, q0, q3, q2);
    else write_oriented(local, o, q0, q2, q1);
  }
#endif
}
#endif
#endif

#if PASS == PASS_EYE
// Whether x is on the lit side of the triangle of cell c (of face `face`, on
// vertex layer `layer`) that its NDC position (f: the position within the
// cell, [0, 1]²) falls in: the same split of the cell as grid_triangles, the
// plane of that triangle's corners.
bool below_cell(int face, int layer, ivec2 c, vec2 f, vec3 x) {
  vec3 v00, v10, v01, v11;
  cell_corners(face, layer, c, v00, v10, v01, v11);
  vec3 a = v00, b = f.y <= f.x ? v10 : v11, d = f.y <= f.x ? v11 : v01;  // (v00, v10, v11) or (v00, v11, v01)
  return orientation(face) * dot(cross(b - a, d - a), x - a) < 0.0;
}

// The cell holding NDC ndc ∈ [−1, 1]², and where in it.
ivec2 ndc_cell(vec2 ndc, out vec2 f) {
  vec2 g = (ndc + 1.0) * 0.5 * float(grid);
  ivec2 c = clamp(ivec2(floor(g)), ivec2(0), ivec2(grid - 1));
  f = g - vec2(c);
  return c;
}

// Whether x lies within the map's domain (a cube's: everywhere) on the
// light's side of grid surface `surface` (0: the only or the inner one, 1: a
// shell's outer).
bool below_surface(int surface, vec3 x) {
  vec2 f;
#if VOLUME_KIND == KIND_CUBE
  vec3 v = x - LIGHT.position, a = abs(v);
  if (v == vec3(0.0)) return true;  // at the light: every distance is > 0
  int face;
  vec2 st;
  if (a.x >= a.y && a.x >= a.z) {  // GL's face selection (the major axis)
    face = v.x >= 0.0 ? 0 : 1;
    st = vec2(v.x >= 0.0 ? -v.z : v.z, -v.y) / a.x;
  } else if (a.y >= a.z) {
    face = v.y >= 0.0 ? 2 : 3;
    st = vec2(v.x, v.y >= 0.0 ? v.z : -v.z) / a.y;
  } else {
    face = v.z >= 0.0 ? 4 : 5;
    st = vec2(v.z >= 0.0 ? v.x : -v.x, -v.y) / a.z;
  }
  return below_cell(face, face + surface * FACES, ndc_cell(st, f), f, x);
#else
  vec4 clip = LIGHT.shadow_matrix * vec4(x, 1.0);
  vec2 ndc = clip.xy / clip.w;
  bool domain = clip.w > 0.0 && all(lessThanEqual(abs(ndc), vec2(1.0)));
  return domain && below_cell(0, surface, ndc_cell(ndc, f), f, x);
#endif
}

void eye() {
  vec3 x = frame.eye;
#if DEPTH_MODE == DEPTH_SHELL
  bool inside = !below_surface(0, x) && below_surface(1, x);
#elif VOLUME_KIND == KIND_DIRECTIONAL
  // Inside the skirt's box, and under the grid where the map covers x.
  vec4 clip = LIGHT.shadow_matrix * vec4(x, 1.0);
  vec2 ndc = clip.xy / clip.w;
  float depth = dot(x, LIGHT.direction);
  bool inside = depth > cap_depth && depth < far_ring_depth && all(lessThan(abs(ndc), vec2(skirt_extent())));
  if (inside && all(lessThanEqual(abs(ndc), vec2(1.0)))) inside = below_surface(0, x);
#else
  bool inside = below_surface(0, x);
#endif
  eye_counts[light_index] = inside ? 0 : 1;
}
#endif

#if PASS == PASS_SEAMS
// Border slot k of face `face` (6·4R items): its owner's vertex, unless it is the owner.
void seams(uint item) {
  int ring = 4 * grid, face = int(item) / ring;
  ivec2 v = border(int(item) % ring);
  ivec3 p = lattice(face, v);
  int f = owner(p);
  if (f == face) return;
  for (int s = 0; s < SURFACES; ++s)
    imageStore(vertices, ivec3(v, face + s * FACES), imageLoad(vertices, ivec3(face_coords(f, p), f + s * FACES)));
}
#endif

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  uint item = uint(first_item) + local;
#if PASS == PASS_CELLS
  cells(item);
#elif PASS == PASS_GRID_VERTICES
  grid_vertices(item);
#elif PASS == PASS_EXTRA_VERTICES
  extra_vertices(item);
#elif PASS == PASS_GRID_TRIANGLES
  grid_triangles(item, local);
#elif PASS == PASS_EXTRA_TRIANGLES
  extra_triangles(item, local);
#elif PASS == PASS_EYE
  eye();
#else
  seams(item);
#endif
}
