// Shadow-map pass: the scene's triangles from light `light_index`.
#include "methods/kit/scene.glsl"

layout(location = 0) in vec3 position;

uniform mat4 light_view_projection;  // the 2D map's matrix or one cube face's

out vec3 world_position;

void main() {
  world_position = position;
  gl_Position = light_view_projection * vec4(position, 1.0);
}
