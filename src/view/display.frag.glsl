// The viewer's image on the window: the chosen pass of L_air and L_surf·T(d),
// × exposure, through the PNG tone curve of core/tonemap.cpp — this is its
// GLSL twin, held to it by display_test — and sRGB-encoded, because the window's
// 8-bit framebuffer takes encoded values. The images may be smaller than the
// viewport (progressive rendering while the camera moves): they are sampled by
// normalized position, through the nearest or bilinear sampler Display binds.
layout(binding = 0) uniform sampler2D airlight_image;
layout(binding = 1) uniform sampler2D surface_image;
uniform int pass;        // 0 composite, 1 airlight, 2 surface (airlight::Pass); 3: airlight_image
                         // holds display values (a heat map), shown as they are
uniform float exposure;
uniform int curve;       // 0 agx, 1 aces, 2 clamp (airlight::ToneCurve)
uniform vec4 viewport;  // x, y, width, height in window pixels
out vec4 color;

const float brightest = 1e6;  // every curve is flat long before; keeps ACES finite
const float agx_min_ev = -12.47393, agx_max_ev = 4.026069;

float agx_contrast(float x) {
  return ((((((15.5 * x - 40.14) * x + 31.96) * x - 6.868) * x + 0.4298) * x + 0.1191) * x) - 0.00232;
}

// v * mat3(r, g, b) = (dot(v, r), dot(v, g), dot(v, b)): tonemap.cpp's rows().
vec3 agx(vec3 v) {
  v = v * mat3(vec3(0.842479062253094, 0.0784335999999992, 0.0792237451477643),
               vec3(0.0423282422610123, 0.878468636469772, 0.0791661274605434),
               vec3(0.0423756549057051, 0.0784336, 0.879142973793104));
  vec3 x = clamp((log2(max(v, vec3(1e-10))) - agx_min_ev) / (agx_max_ev - agx_min_ev), 0.0, 1.0);
  vec3 display = vec3(agx_contrast(x.r), agx_contrast(x.g), agx_contrast(x.b));
  display = display * mat3(vec3(1.19687900512017, -0.0980208811401368, -0.0990297440797205),
                           vec3(-0.0528968517574562, 1.15190312990417, -0.0989611768448433),
                           vec3(-0.0529716355144438, -0.0980434501171241, 1.15107367264116));
  return pow(max(display, vec3(0.0)), vec3(2.2));
}

vec3 aces(vec3 v) {
  v = (v / 0.6) * mat3(vec3(0.59719, 0.35458, 0.04823), vec3(0.07600, 0.90834, 0.01566),
                       vec3(0.02840, 0.13383, 0.83777));
  vec3 a = v * (v + 0.0245786) - 0.000090537;
  vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
  return (a / b) * mat3(vec3(1.60475, -0.53108, -0.07367), vec3(-0.10208, 1.10813, -0.00605),
                        vec3(-0.00327, -0.07276, 1.07602));
}

vec3 linear_to_srgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, 12.92 * c, lessThanEqual(c, vec3(0.0031308)));
}

vec3 tone_map(vec3 radiance) {
  vec3 v = clamp(radiance * exposure, 0.0, brightest);
  v = mix(v, vec3(0.0), isnan(radiance));
  vec3 linear = curve == 0 ? agx(v) : curve == 1 ? aces(v) : v;
  return linear_to_srgb(linear);
}

void main() {
  vec2 uv = (gl_FragCoord.xy - viewport.xy) / viewport.zw;
  vec3 l_air = texture(airlight_image, uv).rgb, l_surf = texture(surface_image, uv).rgb;
  if (pass == 3) {
    color = vec4(l_air, 1.0);
    return;
  }
  vec3 radiance = pass == 1 ? l_air : pass == 2 ? l_surf : l_air + l_surf;
  color = vec4(tone_map(radiance), 1.0);
}
