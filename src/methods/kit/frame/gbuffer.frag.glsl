// G-buffer pass: eye distance along the pixel ray, normals facing the eye and
// albedo, as reference.cpp's surface_point builds them from a ray hit.
#include "methods/kit/frame/objects.glsl"
#include "methods/kit/frame/view_ray.glsl"

layout(std430, binding = BINDING_FACE_NORMALS) readonly buffer FaceNormals { vec4 face_normals[]; };

in vec3 world_position;
in vec3 vertex_normal;
in vec3 vertex_albedo;
flat in int vertex_object;

layout(location = 0) out float out_distance;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_geometric_normal;
layout(location = 3) out vec4 out_albedo;

// reference.cpp facing(): a normal turned toward the viewer.
vec3 facing(vec3 n, vec3 view_dir) { return dot(n, view_dir) > 0.0 ? -n : n; }

void main() {
  vec3 dir = pixel_ray(gl_FragCoord.xy);
  vec3 geometric = mat3(objects[vertex_object].normal) * face_normals[gl_PrimitiveID].xyz;
  if (geometric != vec3(0.0)) geometric = normalize(geometric);
  float length_n = length(vertex_normal);
  // reference.cpp interpolated_normal: the geometric normal when the mesh has no
  // normals or they cancel (perspective-correct interpolation = the hit's barycentrics).
  vec3 shading = length_n > 0.0 ? vertex_normal / length_n : geometric;
  if (geometric == vec3(0.0)) geometric = shading;  // a degenerate triangle (Embree never hits one)
  out_distance = length(world_position - frame.eye);
  out_normal = vec4(facing(shading, dir), 0.0);
  out_geometric_normal = vec4(facing(geometric, dir), 0.0);
  out_albedo = vec4(vertex_albedo, 1.0);  // a = 1: a surface was hit
}
