// An engine's depth buffer as airlight's G-buffer (kit::SceneFrame::import_depth):
// each pixel's window depth unprojected through the engine's camera to an eye
// distance along airlight's pixel ray, capped at the far plane; gl_FragDepth is
// that point's depth in airlight's own projection, for methods that depth-test.
// No normals or albedo: the engine shades its own surfaces.
#include "methods/kit/frame/view_ray.glsl"

layout(binding = BINDING_ENGINE_INPUT) uniform sampler2D engine_depth;
uniform mat4 engine_inverse_view_projection;
uniform bool engine_zero_to_one;  // DepthRange::zero_to_one: NDC z = window depth
uniform float engine_far_depth;   // the window depth of the engine's far plane (its clear value)

layout(location = 0) out float out_distance;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_geometric_normal;
layout(location = 3) out vec4 out_albedo;

void main() {
  vec3 dir = pixel_ray(gl_FragCoord.xy);
  float far = far_plane_distance(dir);
  float z = texelFetch(engine_depth, ivec2(gl_FragCoord.xy), 0).r;
  vec4 ndc = vec4(pixel_ndc(gl_FragCoord.xy), engine_zero_to_one ? z : 2.0 * z - 1.0, 1.0);
  vec4 world = engine_inverse_view_projection * ndc;
  // The clear value, a point at infinity (reversed-Z with an infinite far
  // plane) or one behind the eye: no surface on this ray.
  float d = far;
  if (z != engine_far_depth && world.w > 0.0) d = min(length(world.xyz / world.w - frame.eye), far);
  bool surface = d < far;
  out_distance = d;
  out_normal = vec4(0.0);
  out_geometric_normal = vec4(0.0);
  out_albedo = vec4(0.0);
  vec4 clip = frame.view_projection * vec4(frame.eye + d * dir, 1.0);
  gl_FragDepth = surface ? clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0) : 1.0;
}
