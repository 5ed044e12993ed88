// A fragment of virtual plane k at a pixel: its sample of the light's
// in-scattering, Dobashi eq. 5's I(θ,φ)·ξ·V, added into the float target by
// additive blending (no 8-bit quantization floor, unlike the paper's frame
// buffer). I(θ,φ) is the light map (light_map: spot cone and gobo, or the
// beam and its gobo), V the shadow-map test (Dobashi §5.2 in its modern form).
//
// The slab [k·dz, (k+1)·dz] is cut at the visible surface: only its part in
// front counts, sampled at its middle (or at the pixel's jitter offset), so a
// surface inside a slab gets no step of up to dz in its fog.
#include "methods/planes/view_ray.glsl"

layout(binding = BINDING_JITTER) uniform sampler2D jitter_offsets;  // R32F tile of values in [0, 1)

uniform int light;
uniform bool lattice_xi;
uniform float dz;
uniform bool jitter;  // per-pixel offset of the samples within their slabs (Dobashi §7's jittering)

flat in int plane;
in vec3 xi;
layout(location = 0) out vec4 airlight;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 dir = pixel_ray(gl_FragCoord.xy);
  float cos_axis = dot(dir, frame_forward.xyz);
  float z0 = float(plane) * dz;
  float z1 = min(z0 + dz, surface_distance(pixel) * cos_axis);
  if (!(z1 > z0)) discard;  // the depth test's rounding let a slab behind the surface through
  float offset = jitter ? texelFetch(jitter_offsets, pixel % textureSize(jitter_offsets, 0), 0).r : 0.5;
  vec3 eye = frame_eye.xyz;
  vec3 x = eye + mix(z0, z1, offset) / cos_axis * dir;
  vec3 map = light_map(light, x);
  if (map == vec3(0.0)) discard;
  float visible = shadow_visibility(light, x);
  if (visible == 0.0) discard;
  vec3 scatter = lattice_xi ? xi * (z1 - z0)
                            : inscatter_unmapped(light, x, dir, eye_leg_depth(eye, x)) * ((z1 - z0) / cos_axis);
  airlight = vec4(map * visible * scatter, 0.0);
}
