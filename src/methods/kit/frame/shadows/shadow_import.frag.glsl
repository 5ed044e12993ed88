// A light's shadow map as an engine drew it, converted texel by texel into the
// layer of airlight's map that scene.glsl's lookups read
// (kit::SceneFrame::import_shadow_layer): the engine's stored value is turned
// back into the occluder's position (2D: through the inverse of the engine's
// light matrix, which the light's record then uses for its lookups; cube: along
// the texel's direction), and stored as shadow_distance — the distance from the
// light, or the depth along a directional light's travel. Texels at the
// engine's clear value hold no occluder: FLT_MAX, as airlight's own maps.
#include "methods/kit/frame/scene.glsl"

#ifdef ENGINE_CUBE
layout(binding = BINDING_ENGINE_INPUT) uniform samplerCube engine_map;
#elif defined(ENGINE_ARRAY)
layout(binding = BINDING_ENGINE_INPUT) uniform sampler2DArray engine_map;
#else
layout(binding = BINDING_ENGINE_INPUT) uniform sampler2D engine_map;
#endif

uniform int light_index;
uniform int face;            // cube: the face being written, GL's order +x −x +y −y +z −z
uniform int engine_layer;    // 2D array: the layer of the engine's map
uniform bool engine_distance;  // the engine stores linear distance from the light (cubes)
uniform mat4 engine_inverse_view_projection;  // 2D: of its light matrix; cube: of a face's projection
uniform bool engine_zero_to_one;
uniform float engine_far_depth;

layout(location = 0) out float out_distance;

const float FLT_MAX = 3.402823466e38;

float ndc_z(float z) { return engine_zero_to_one ? z : 2.0 * z - 1.0; }

#include "methods/kit/frame/shadows/cube_faces.glsl"

void main() {
  vec2 st = 2.0 * gl_FragCoord.xy / vec2(frame.shadow_resolution) - 1.0;
#ifdef ENGINE_CUBE
  vec3 dir = cube_face_direction(face, st);
  float z = texture(engine_map, dir).r;
  if (engine_distance) {
    out_distance = z;
    return;
  }
  // A face's view depth along its axis, then the distance along the texel's direction.
  vec4 view = engine_inverse_view_projection * vec4(0.0, 0.0, ndc_z(z), 1.0);
  bool none = z == engine_far_depth || !(view.w > 0.0);
  out_distance = none ? FLT_MAX : (-view.z / view.w) * length(dir) / max(abs(dir.x), max(abs(dir.y), abs(dir.z)));
#else
  vec2 uv = 0.5 * st + 0.5;
#ifdef ENGINE_ARRAY
  float z = texture(engine_map, vec3(uv, float(engine_layer))).r;
#else
  float z = texture(engine_map, uv).r;
#endif
  vec4 world = engine_inverse_view_projection * vec4(st, ndc_z(z), 1.0);
  bool none = z == engine_far_depth || !(world.w > 0.0);
  out_distance = none ? FLT_MAX : shadow_distance(light_index, world.xyz / world.w);
#endif
}
