// G-buffer pass: the scene's triangles, moved by their objects' transforms,
// through the camera of docs/design.md §5.
#include "methods/kit/frame/objects.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;  // per vertex; zero when the mesh has none
layout(location = 2) in vec3 albedo;
layout(location = 3) in int object;

out vec3 world_position;
out vec3 vertex_normal;
out vec3 vertex_albedo;
flat out int vertex_object;

void main() {
  world_position = (objects[object].model * vec4(position, 1.0)).xyz;
  vertex_normal = mat3(objects[object].normal) * normal;
  vertex_albedo = albedo;
  vertex_object = object;
  gl_Position = frame.view_projection * vec4(world_position, 1.0);
}
