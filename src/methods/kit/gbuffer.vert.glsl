// G-buffer pass: the scene's triangles through the camera of DESIGN §5.
#include "methods/kit/scene.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;  // per vertex; zero when the mesh has none
layout(location = 2) in vec3 albedo;

out vec3 world_position;
out vec3 vertex_normal;
out vec3 vertex_albedo;

void main() {
  world_position = position;
  vertex_normal = normal;
  vertex_albedo = albedo;
  gl_Position = frame_view_projection * vec4(position, 1.0);
}
