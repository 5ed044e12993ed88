// Shadow-map pass: the scene's triangles, moved by their objects' transforms,
// from light `light_index`.
#include "methods/kit/frame/objects.glsl"

layout(location = 0) in vec3 position;
layout(location = 3) in int object;
uniform mat4 light_view_projection;  // the 2D map's matrix or one cube face's
out vec3 world_position;

void main() {
  world_position = (objects[object].model * vec4(position, 1.0)).xyz;
  gl_Position = light_view_projection * vec4(world_position, 1.0);
}
