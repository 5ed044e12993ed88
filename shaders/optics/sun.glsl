// GLSL twin of the Sun et al. 2005 airlight in src/optics/closed_form.cpp
// (Kingston eqs. 36-40): the unoccluded single scattering of one isotropic
// point light along a view segment in a homogeneous medium, isotropic phase.
// Evaluated in the shader by Gauss–Legendre quadrature (the table variant is
// separate). Tested against the C++ by src/methods/kit/testing/twins/optics_twin_test.cpp.
#include "optics/numerics.glsl"
#include "optics/light.glsl"

// Beyond u·(tan ξ - tan ξ_lo) = 16 the integrand is below e^-16 of its start:
// the dropped tail is below e^(1-16) ≈ 3e-7 of the integral (it is bounded by
// e^-16/(u sec² ξ_cut) and the first e-fold holds at least e^-1/(u sec² ξ_cut)).
const float SUN_CUTOFF = 16.0;

// J = ∫_{ξlo}^{ξhi} exp(-u (tan ξ - w_lo)) dξ with w_lo = tan ξlo >= 0,
// dw = tan ξhi - w_lo >= 0 (+∞ allowed), u >= 0.
// In w = tan ξ it is ∫ exp(-u (w - w_lo)) dw/(1 + w²). Plain Gauss–Legendre
// in ξ converges only as 1/N² when the range nears π/2 (exp(-u/η), η = π/2 - ξ,
// has structure at every scale from u to 1), so the range is split where w = 1:
//   A: up to w = 1, in w itself: 1/(1 + w²) has its poles ±i far from [0, 1];
//   B: beyond, in s = ln(w / w_b): dw/(1 + w²) = ds/(w + 1/w), whose poles stay
//      π/2 off the real axis at every scale, and exp(-u(w - w_lo)) is entire.
// 8 nodes on A, 12 on B, whose range in s reaches ln(16/u); their error is
// measured in docs/decisions.md (Numerics, "Γ's cost") and on the GPU by the twin test.
// The nodes come in pairs at the middle ∓ h: exp of the middle ∓ h is exp of
// the middle times e^{∓h}, so a pair takes one exp for what both share and
// one division for the sum of both terms (docs/decisions.md, "Γ's cost").
// Returns e^{-depth}·J: the caller's exponential factor joins the one A's and
// B's terms share (e^{-u·a_len/2}) in one exp.
float sun_angular(float u, float w_lo, float dw, float depth) {
  if (!(u > 1e-20)) {  // J = atan(w_lo + dw) - atan(w_lo) - O(u·ln(1/u)), as one atan2 (π/2 - atan(w_lo) for dw = ∞)
    bool open = dw > 1e30;
    return exp(-depth) * atan2_accurate(open ? 1.0 : dw, open ? w_lo : 1.0 + w_lo * (w_lo + dw));
  }
  float dw_cut = min(dw, SUN_CUTOFF / u);
  float a_len = w_lo < 1.0 ? min(dw_cut, 1.0 - w_lo) : 0.0;  // part A's range in w
  float w_b = max(w_lo + a_len, 1.0);                        // part B starts here
  float len_b = dw_cut > a_len ? log1p_nonneg((dw_cut - a_len) / w_b) : 0.0;
  // A: exp(-u·t·a_len) at t = (1 ∓ x)/2 is e^{-u·a_len/2}·e^{±y}, y = u·a_len·x/2 <= 8 (a_len <= 16/u).
  float half_a = 0.5 * a_len, w_mid = w_lo + half_a;
  float sum_a = 0.0;
  for (int i = 0; i < 4; ++i) {
    float h = half_a * GAUSS8_X[i], e = exp(u * h);
    float below = 1.0 + (w_mid - h) * (w_mid - h), above = 1.0 + (w_mid + h) * (w_mid + h);
    sum_a += GAUSS8_W[i] * (e * e * above + below) / (e * below * above);
  }
  // B: e^s at s = len_b·(1 ± x)/2 is (1 + c)·e^{±h}; e^s - 1 from expm1s, without cancellation.
  // Its terms f/(w + 1/w) are summed per pair as f·e/p with p = e·(w + 1/w)/W, W = w_b(1 + c):
  // one division gives both 1/e (for the lower node's e^s) and 1/(p_hi·p_lo). No overflow:
  // 1 <= e < W, so p_hi <= 2e², p_lo < 2 and e·p_hi·p_lo < 4e³ < 4e^{1.5·len_b}, where
  // len_b <= ln(1 + 16/u) < 49 (u > 1e-20).
  float c = expm1_nonneg(0.5 * len_b), W = w_b * (1.0 + c), iW = 1.0 / W, iW2 = iW * iW;
  float sum_b = 0.0;
  for (int i = 0; i < 6; ++i) {
    float m = expm1_nonneg(0.5 * len_b * GAUSS12_X[i]), e = 1.0 + m, e2 = e * e;
    float p_hi = e2 + iW2, p_lo = 1.0 + iW2 * e2, inv = 1.0 / (e * p_hi * p_lo);
    float f_hi = exp(-u * (half_a + w_b * (c + m * (1.0 + c))));
    float f_lo = exp(-u * (half_a + w_b * (c - m) * p_hi * p_lo * inv));
    sum_b += GAUSS12_W[i] * e2 * inv * (f_hi * p_lo + f_lo * p_hi);
  }
  return exp(-(depth + u * half_a)) * (half_a * sum_a + 0.5 * len_b * iW * sum_b);
}

// Sun et al.'s F(u, v) = ∫_0^v exp(-u tan ξ) dξ (Kingston eq. 40), u >= 0,
// 0 <= v <= π/2 (v at or past π/2 in float integrates to the cutoff).
float sun_F(float u, float v) {
  float c = cos(v);
  return sun_angular(u, 0.0, c > 0.0 ? sin(v) / c : positive_infinity(), 0.0);
}

// tan ξ at a point whose offset along the ray from the foot of the perpendicular
// is e, at distance r from the light: (e + r)/r0, written as r0/(r - e) for
// e < 0 where e + r cancels. As (numerator, denominator), both positive, so that
// sun_segment takes its quotients with one division.
vec2 sun_tan_xi_terms(float e, float r0, float r) {
  bool ahead = e >= 0.0;  // selected terms: llvmpipe runs both sides of a branch
  return vec2(ahead ? e + r : r0, ahead ? r0 : r - e);
}
float sun_tan_xi(float e, float r0, float r) {
  vec2 q = sun_tan_xi_terms(e, r0, r);
  return q.x / q.y;
}

// The segment x in [0, d] with the foot of the perpendicular from the light at
// x = xs, at distance r0: Kingston eqs. 36-39 with x - xs = r0 tan(2ξ - π/2),
// as ONE integral A0·e^{-σt d_lv}·∫ exp(-σt r0 (tan ξ - tan ξ0)) dξ (the
// difference F(A1, A2) - F(A1, γ/2) cancels catastrophically at large σt d_lv,
// docs/decisions.md, Numerics). The range starts at ξ0 = γ/2, and its length is
// taken in w = tan ξ (dw below), not as half the angle the segment subtends (the C++).
// r0 is clamped at MIN_LIGHT_DISTANCE, so a light on the ray stays finite (the
// C++ clamps r instead: the two differ only when the light is within 1 µm of the ray).
// depth: an optical depth before the segment (the eye's leg to its start), whose
// transmittance joins the light leg's in one exp.
float sun_segment(float sigma_s, float sigma_t, float I0, float xs, float r0, float d, float depth) {
  if (!(d > 0.0)) return 0.0;
  r0 = max(r0, MIN_LIGHT_DISTANCE);
  float d_lv = length(vec2(xs, r0)), r_d = length(vec2(d - xs, r0));
  vec2 lo = sun_tan_xi_terms(-xs, r0, d_lv), hi = sun_tan_xi_terms(d - xs, r0, r_d);
  // r0·(w_hi - w_lo) = d + r_d - d_lv, and r_d - d_lv = (r_d² - d_lv²)/(r_d + d_lv)
  // = d·(e_hi + e_lo)/(r_d + d_lv) for the ends' offsets e: so dw = d·(w_lo + w_hi)/(d_lv + r_d),
  // a sum of positive terms, with no cancellation for short segments or ends behind the foot.
  // w_lo and dw share one division (the terms are at most a few times the scene's size, at least r0).
  float sum = d_lv + r_d, inv = 1.0 / (lo.y * hi.y * sum);
  float w_lo = lo.x * hi.y * sum * inv, dw = d * (lo.x * hi.y + hi.x * lo.y) * inv;
  float A0 = sigma_s * I0 / (2.0 * PI * r0);  // Kingston's A0, e^{-σt d_lv cos γ} moved inside
  return A0 * sun_angular(sigma_t * r0, w_lo, dw, sigma_t * d_lv + depth);
}

// optics::sun_airlight(σs, σt, I0, d_lv, γ, d_vp): d_lv the eye–light distance,
// gamma the angle between the view ray and the direction to the light, d_vp the
// length of the view segment.
float sun_airlight(float sigma_s, float sigma_t, float I0, float d_lv, float gamma, float d_vp) {
  return sun_segment(sigma_s, sigma_t, I0, d_lv * cos(gamma), d_lv * abs(sin(gamma)), d_vp, 0.0);
}

// The same for a ray (origin, unit dir), a light position and the segment [0, d]
// (optics::sun_airlight's vector form), times e^{-depth}: r0 = |Δ - xs·dir| (no
// cancellation, unlike sqrt(|Δ|² - xs²) of Nilsson eq. 2.16).
float sun_airlight_ray(float sigma_s, float sigma_t, float I0, vec3 origin, vec3 dir, vec3 light, float d,
                       float depth) {
  vec3 delta = light - origin;
  float xs = dot(delta, dir);
  return sun_segment(sigma_s, sigma_t, I0, xs, length(delta - xs * dir), d, depth);
}
