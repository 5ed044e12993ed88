// Surface pass: L_surf·T(d) per pixel, exactly as reference.cpp's trace():
// Lambertian with ambient, each light's arrival (cone, beam, gobo, falloff), shadow-map
// visibility, a light behind the triangle's plane blocked, extinction on the
// light's leg and on the eye's (docs/design.md §1); 0 where the ray reaches the far plane.
#include "methods/kit/frame/pixel.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2D surface_out;

struct SurfacePoint {
  vec3 position;
  vec3 geometric_normal;
  vec3 shading_normal;
  vec3 albedo;
};

// reference.cpp irradiance(): E·cos θ_i·V·exp(−τ_light) from light i.
vec3 irradiance(int i, SurfacePoint s) {
  Arrival a = light_arrival(i, s.position);
  float cos_i = dot(s.shading_normal, a.to_light);
  bool lit = cos_i > 0.0 && dot(s.geometric_normal, a.to_light) > 0.0 && a.irradiance != vec3(0.0);
  if (!lit || surface_visibility(i, s.position, s.geometric_normal) == 0.0) return vec3(0.0);
  return a.irradiance * cos_i * exp(-light_leg_depth(i, s.position));
}

// L_surf = albedo·ambient + Σ_lights albedo/π · irradiance.
vec3 surface_radiance(SurfacePoint s) {
  vec3 e = vec3(0.0);
  for (int i = 0; i < LIGHT_COUNT; ++i) e += irradiance(i, s);
  return s.albedo * (frame.ambient + e / PI);
}

void main() {
  FRAME_PIXEL_OR_RETURN(pixel);
  vec4 albedo = texelFetch(gbuffer_albedo, pixel, 0);
  vec3 radiance = vec3(0.0);
  if (albedo.a > 0.0) {
    PixelRay ray = load_pixel_ray(pixel);
    SurfacePoint s = SurfacePoint(frame.eye + ray.d * ray.dir, texelFetch(gbuffer_geometric_normal, pixel, 0).xyz,
                                  texelFetch(gbuffer_normal, pixel, 0).xyz, albedo.rgb);
    radiance = surface_radiance(s) * eye_transmittance(ray.dir, ray.d);
  }
  imageStore(surface_out, pixel, vec4(radiance, 1.0));
}
