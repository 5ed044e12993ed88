// The floor of `airlight bench --floor` (app/floor.hpp): the least a march can
// cost per sample on this machine, fixed once and never tuned to a method. One
// spot light; per pixel a ray through a fixed frustum, `steps` uniform steps to
// 20 m sampled at their midpoints; per sample one texelFetch from a 1024² R32F
// shadow map, a Henyey–Greenstein phase, exp extinction on both legs and 1/r².
// With FULLSCREEN the pass only writes each pixel: the cost of a dispatch.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D floor_out;
layout(binding = 0) uniform sampler2D shadow_map;

uniform int steps;
uniform mat4 light_matrix;  // world → clip of the spot's map

const vec3 eye = vec3(0.0);
const vec3 light_position = vec3(0.0, 3.0, -6.0);
const vec3 light_axis = vec3(0.0, -1.0, 0.0);
const float cos_cone = 0.866;  // 30°
const float sigma_s = 0.05, sigma_t = 0.06, g = 0.3, intensity = 100.0, far = 20.0;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(floor_out);
  if (any(greaterThanEqual(pixel, size))) return;
#ifdef FULLSCREEN
  imageStore(floor_out, pixel, vec4(0.0));
#else
  vec2 ndc = 2.0 * (vec2(pixel) + 0.5) / vec2(size) - 1.0;
  vec3 dir = normalize(vec3(ndc.x * float(size.x) / float(size.y), ndc.y, -2.4));
  float dt = far / float(steps), sum = 0.0;
  for (int k = 0; k < steps; ++k) {
    float t = (float(k) + 0.5) * dt;
    vec3 x = eye + t * dir, to_x = x - light_position;
    float r2 = dot(to_x, to_x), r = sqrt(r2);
    vec3 travel = to_x / r;
    vec4 clip = light_matrix * vec4(x, 1.0);
    ivec2 texel = ivec2(clamp(0.5 * clip.xy / clip.w + 0.5, 0.0, 1.0) * 1023.0);
    float lit = (r <= texelFetch(shadow_map, texel, 0).r && dot(travel, light_axis) >= cos_cone) ? 1.0 : 0.0;
    float cos_theta = dot(travel, -dir), denom = 1.0 + g * g - 2.0 * g * cos_theta;
    float phase = (1.0 - g * g) / (12.566370614359172 * denom * sqrt(denom));
    sum += sigma_s * phase * lit * intensity * exp(-sigma_t * (t + r)) / r2 * dt;
  }
  imageStore(floor_out, pixel, vec4(vec3(sum), 1.0));
#endif
}
