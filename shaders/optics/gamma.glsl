// GLSL twin of the per-light closed forms of src/optics/gamma.cpp and
// closed_form.cpp: the Sun et al. F(u, v) table lookup (SunTable), Nilsson's
// simplified model (eq. 2.17), the exact exponential form of directional
// lights, and the Gauss–Legendre nodes of Biri's angular integral. The
// scene-level Γ is methods/kit/gamma/closed_form.glsl.
#include "optics/sun.glsl"

// optics::sun_asymptote: B(u, v) = v·(1 - e^{-uv})/(uv), the table's divisor.
float sun_asymptote(float u, float v) {
  float z = u * v;
  float q = z < 1e-2 ? 1.0 - z * (0.5 - z * (1.0 / 6.0 - z / 24.0)) : (1.0 - exp(-z)) / z;
  return v * q;
}

// atan(w) for any w >= 0 (+∞ allowed) with atan_unit's precision.
float atan_unit_any(float w) { return w <= 1.0 ? atan_unit(w) : HALF_PI - atan_unit(1.0 / w); }

#ifdef SUN_F_TABLE
// gamma.hpp sun_table_*: the grid in (ln u, ln tan v).
const float SUN_TABLE_LOG_U_MIN = -12.0, SUN_TABLE_LOG_U_STEP = 18.0 / 255.0;
const float SUN_TABLE_LOG_TAN_MIN = -6.0, SUN_TABLE_LOG_TAN_STEP = 15.0 / 255.0;
const float SUN_TABLE_MAX_CONDITION = 8.0, SUN_TABLE_MAX_GAIN = 30.0;

// optics::SunTable::F_tan: R bilinear from four texelFetch reads (GL_LINEAR may
// quantize weights to 8 bits, as light.glsl's sample_gobo explains), times B.
float sun_table_F(sampler2D table, float u, float tan_v, float v) {
  if (!(v > 0.0)) return 0.0;
  ivec2 size = textureSize(table, 0);
  vec2 p = clamp(vec2((log(u) - SUN_TABLE_LOG_U_MIN) / SUN_TABLE_LOG_U_STEP,
                      (log(tan_v) - SUN_TABLE_LOG_TAN_MIN) / SUN_TABLE_LOG_TAN_STEP),
                 vec2(0.0), vec2(size - 1));
  ivec2 i = min(ivec2(p), size - 2);
  vec2 f = p - vec2(i);
  float r = mix(mix(texelFetch(table, i, 0).r, texelFetch(table, i + ivec2(1, 0), 0).r, f.x),
                mix(texelFetch(table, i + ivec2(0, 1), 0).r, texelFetch(table, i + ivec2(1, 1), 0).r, f.x), f.y);
  return r * sun_asymptote(u, v);
}

// optics::sun_airlight_table: Kingston eq. 38 with F from the table where the
// difference is well-conditioned, else sun.glsl's in-shader integral; times
// e^{-depth} as sun_airlight_ray.
float sun_airlight_table(sampler2D table, float sigma_s, float sigma_t, float I0, vec3 origin, vec3 dir,
                         vec3 light, float d, float depth) {
  vec3 delta = light - origin;
  float xs = dot(delta, dir);
  float r0 = max(length(delta - xs * dir), MIN_LIGHT_DISTANCE);
  float w0 = sun_tan_xi(-xs, r0, length(vec2(xs, r0))), w1 = sun_tan_xi(d - xs, r0, length(vec2(d - xs, r0)));
  float u = sigma_t * r0;
  float F0 = sun_table_F(table, u, w0, atan_unit_any(w0)), F1 = sun_table_F(table, u, w1, atan_unit_any(w1));
  if (!(d > 0.0) || -sigma_t * xs > SUN_TABLE_MAX_GAIN || !(F1 + F0 <= SUN_TABLE_MAX_CONDITION * (F1 - F0)))
    return sun_segment(sigma_s, sigma_t, I0, xs, r0, d, depth);
  return sigma_s * I0 / (2.0 * PI * r0) * exp(-(sigma_t * xs + depth)) * (F1 - F0);
}
#endif

// ∫_{s0}^{s1} ds / (a1 s² + B), B >= 0 (closed_form.cpp inverse_quadratic_integral,
// Nilsson eq. 2.17 before σs/(4π)): one atan2 for the difference of atans, and
// the limits a1 → 0 and B → 0.
float inverse_quadratic_integral(float a1, float B, float s0, float s1) {
  if (!(s1 > s0)) return 0.0;
  float q = sqrt(a1 / B);
  float s_min = (s0 > 0.0 || s1 < 0.0) ? min(abs(s0), abs(s1)) : 0.0;
  float s_max = max(abs(s0), abs(s1));
  if (q * s_max < 1e-30) return (s1 - s0) / B;
  if (q * s_min > 1e30) return (s1 - s0) / (a1 * s0 * s1);
  return atan2_accurate(q * (s1 - s0), 1.0 + q * q * s0 * s1) / (q * B);
}

// optics::nilsson_airlight: σs·I/(4π)·∫ dz/(a1 r² + a0) over [z0, z1], r
// clamped at MIN_LIGHT_DISTANCE (constant inside |z - zs| < h).
float nilsson_airlight(float sigma_s, float I, float a0, float a1, vec3 origin, vec3 dir, vec3 light,
                       float z0, float z1) {
  if (!(z1 > z0)) return 0.0;
  vec3 delta = light - origin;
  float zs = dot(delta, dir), r0 = length(delta - zs * dir);  // Nilsson eq. 2.16 as |Δ - zs·Ω|
  float s0 = z0 - zs, s1 = z1 - zs, B = a1 * r0 * r0 + a0;
  float eps = MIN_LIGHT_DISTANCE, h = r0 < eps ? sqrt(eps * eps - r0 * r0) : 0.0;
  float in0 = clamp(-h, s0, s1), in1 = clamp(h, s0, s1);
  float sum = inverse_quadratic_integral(a1, B, s0, in0) + (in1 - in0) / (a1 * eps * eps + a0) +
              inverse_quadratic_integral(a1, B, in1, s1);
  return sigma_s * I * INV_4PI * sum;
}

// ∫_0^L exp(-k t) dt per channel, exact as k → 0 (gamma.cpp exponential_length).
vec3 exponential_length(vec3 k, float L) {
  vec3 len;
  for (int c = 0; c < 3; ++c) {
    float x = k[c] * L;
    len[c] = x == 0.0 ? L : (x < 1e-2 ? L * (1.0 - x * (0.5 - x / 6.0)) : (1.0 - exp(-x)) / k[c]);
  }
  return len;
}

// asinh without cancellation for negative arguments (gamma.cpp stable_asinh).
float stable_asinh(float z) {
  float a = abs(z);
  return sign(z) * log1p_nonneg(a + a * a / (1.0 + sqrt(1.0 + a * a)));
}


// Biri's angular integral in s = asinh((x - xs)/h) (gamma.cpp): 8-point
// Gauss–Legendre per panel (GAUSS8), panels <= 2 in s and <= 4 in the growth of σt(x + r).
const float BIRI_MAX_PANEL = 2.0, BIRI_PANEL_GROWTH = 4.0, BIRI_TAIL_GROWTH = 32.0;
const int BIRI_MAX_PANELS = 64;  // gamma.cpp max_panels
