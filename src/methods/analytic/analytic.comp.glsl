// analytic (Kingston 4.2.3, Sun et al. 2005): per pixel, L_air = Σ_lights
// Γ_i(0 → d), the unoccluded closed-form airlight of each light along the view
// ray from the eye to the G-buffer distance d (the visible surface or the far
// plane). No samples along the ray, hence no shadow-map lookups: the method has
// no volumetric shadows (Kingston §5.2.3). With SUN_F_TABLE, Γ reads Sun et
// al.'s F(u, v) from the table at BINDING_SUN_TABLE instead of integrating it.
#define SCENE_IN_REGISTERS
#include "methods/kit/frame/pixel.glsl"
#include "methods/kit/gamma/closed_form.glsl"

layout(rgba32f, binding = 0) writeonly uniform image2D airlight_out;

void main() {
  FRAME_PIXEL_OR_RETURN(pixel);
  PixelRay ray = load_pixel_ray(pixel);
  vec3 sum = vec3(0.0);
  // One copy of Γ per light, not per structure (FOR_EACH_LIGHT_SHARED): on
  // llvmpipe the copies overlap and a loop over stage's spots ran slower,
  // while Γ alone compiles fast (docs/decisions.md, "The first frame").
#define ADD_GAMMA(i) sum += closed_form_airlight(i, frame.eye, ray.dir, 0.0, ray.d);
  FOR_EACH_LIGHT(ADD_GAMMA)
#undef ADD_GAMMA
  imageStore(airlight_out, pixel, vec4(sum, 1.0));
}
