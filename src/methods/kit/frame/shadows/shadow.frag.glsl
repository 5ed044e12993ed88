// Shadow-map pass: the linear distance the lookups compare with (shadow_distance).
#include "methods/kit/frame/scene.glsl"

uniform int light_index;

in vec3 world_position;
layout(location = 0) out float out_distance;

void main() { out_distance = shadow_distance(light_index, world_position); }
