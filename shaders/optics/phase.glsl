// GLSL twin of src/optics/phase.cpp (docs/design.md §1): phase functions normalized to
// 1 over the sphere. cos_theta is the cosine between the light's direction of
// travel and the direction toward the eye, so g > 0 scatters forward.
// Tested against the C++ by src/methods/kit/testing/twins/optics_twin_test.cpp.
#include "optics/constants.glsl"

// Lobe type codes: the integer values of airlight::PhaseType (include/airlight/scene.hpp).
const int PHASE_ISOTROPIC = 0;
const int PHASE_RAYLEIGH = 1;
const int PHASE_HENYEY_GREENSTEIN = 2;
const int PHASE_SCHLICK = 3;
const int PHASE_HAZY = 4;
const int PHASE_MURKY = 5;

// Schlick's k for a Henyey–Greenstein g (Kingston eq. 16), clamped to |k| <= 0.999
// exactly as optics::schlick_k: beyond |g| ≈ 0.938 eq. 16 gives |k| > 1 and a pole.
float schlick_k(float g) {
  return clamp(1.55 * g - 0.55 * g * g * g, -0.999, 0.999);
}

// 1 - k·c for |k| < 1, c in [-1, 1], written as a sum of non-negative terms:
// the direct form cancels for k·c → 1 (forward peak at g → 1, backward at
// g → -1) and loses all float digits there. 1 ∓ c and 1 ∓ k are exact (Sterbenz).
float one_minus_kc(float k, float c) {
  return k >= 0.0 ? (1.0 - k) + k * (1.0 - c) : (1.0 + k) - k * (1.0 + c);
}

// Henyey–Greenstein (Kingston eq. 14): (1 - g²) / (4π (1 + g² - 2g cos θ)^1.5).
// 1 + g² - 2gc = (1 - g)² + 2g(1 - c) = (1 + g)² - 2g(1 + c): no cancellation.
float henyey_greenstein(float g, float c) {
  float a = g >= 0.0 ? 1.0 - g : 1.0 + g;
  float denom = a * a + 2.0 * abs(g) * (g >= 0.0 ? 1.0 - c : 1.0 + c);
  return (1.0 - g) * (1.0 + g) * INV_4PI / (denom * sqrt(denom));
}

// Schlick (Kingston eq. 15 with the sign of eq. 14: k > 0 scatters forward, docs/decisions.md).
float schlick_lobe(float k, float c) {
  float denom = one_minus_kc(k, c);
  return (1.0 - k) * (1.0 + k) * INV_4PI / (denom * denom);
}

// ((1 + c)/2)^(2^n) by n squarings: pow() is exp2(log2) in GLSL and loses
// about 32·ε·|log2 x| of relative precision; squaring loses at most 2^n·ε/2.
float half_one_plus_c_pow2n(float c, int n) {
  float x = max(0.0, 0.5 * (1.0 + c));
  for (int i = 0; i < n; ++i) x *= x;
  return x;
}

// Nishita's hazy (1 + 9cos¹⁶(θ/2)) and murky (1 + 50cos⁶⁴(θ/2)) lobes normalized
// over the sphere: ∫ = 8π and 332π/33 (docs/decisions.md: Nilsson Appendix A's K is wrong).
// cos^16(θ/2) = ((1+c)/2)^8, cos^64(θ/2) = ((1+c)/2)^32.
float hazy_lobe(float c) { return (1.0 + 9.0 * half_one_plus_c_pow2n(c, 3)) / (8.0 * PI); }
float murky_lobe(float c) { return 33.0 * (1.0 + 50.0 * half_one_plus_c_pow2n(c, 5)) / (332.0 * PI); }

// optics::phase(PhaseLobe, cos θ); `type` is a PHASE_* code, g is used by HG and Schlick.
float phase_lobe(int type, float g, float cos_theta) {
  switch (type) {
    case PHASE_ISOTROPIC: return INV_4PI;
    case PHASE_RAYLEIGH: return 3.0 / (16.0 * PI) * (1.0 + cos_theta * cos_theta);
    case PHASE_HENYEY_GREENSTEIN: return henyey_greenstein(g, cos_theta);
    case PHASE_SCHLICK: return schlick_lobe(schlick_k(g), cos_theta);
    case PHASE_HAZY: return hazy_lobe(cos_theta);
    case PHASE_MURKY: return murky_lobe(cos_theta);
  }
  return 0.0;
}
