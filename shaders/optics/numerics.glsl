// Numerical helpers shared by the optics twins.
#include "optics/constants.glsl"

// Gauss–Legendre on [-1, 1], 8 and 12 points: the positive abscissae and their weights.
const float GAUSS8_X[4] = float[](0.960289856497536, 0.796666477413627, 0.525532409916329, 0.183434642495650);
const float GAUSS8_W[4] = float[](0.101228536290376, 0.222381034453374, 0.313706645877887, 0.362683783378362);
const float GAUSS12_X[6] = float[](0.981560634247, 0.904117256370, 0.769902674194,
                                   0.587317954287, 0.367831498998, 0.125233408511);
const float GAUSS12_W[6] = float[](0.047175336387, 0.106939325995, 0.160078328543,
                                   0.203167426723, 0.233492536538, 0.249147045813);

// atan(t) for t in [0, 1] to ~2 ulp (Cephes atanf: reduction at tan(π/8),
// odd minimax polynomial, peak relative error 1.9e-7). GLSL's atan may be off
// by 4096 ulp (Mesa's llvmpipe is off by hundreds), which shifts a spot's smooth
// edge by ~1e-4 of its width and the Sun et al. ξ range by as much.
float atan_unit(float t) {
  float base = 0.0;
  if (t > 0.41421356) {  // tan(π/8)
    base = 0.25 * PI;
    t = (t - 1.0) / (t + 1.0);
  }
  float z = t * t;
  return base + ((((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z
                  - 3.33329491539e-1) * z * t + t);
}

// atan2(y, x) in [-π, π] with full float relative precision: the argument of
// atan_unit is min/max of |x| and |y|, so no quotient overflows.
float atan2_accurate(float y, float x) {
  float ax = abs(x), ay = abs(y);
  if (ax == 0.0 && ay == 0.0) return 0.0;
  float a = atan_unit(min(ax, ay) / max(ax, ay));  // one quotient and polynomial: llvmpipe runs both sides of a branch
  if (ay > ax) a = 0.5 * PI - a;
  if (x < 0.0) a = PI - a;
  return y < 0.0 ? -a : a;
}

// Angle in [0, π] between two vectors of any length: atan2(|a×b|, a·b) keeps
// full relative precision at every angle, unlike acos(a·b) near 0 and π.
float angle_between(vec3 a, vec3 b) {
  return atan2_accurate(length(cross(a, b)), dot(a, b));
}

// log(1 + x) and exp(x) - 1 for x >= 0: a Taylor polynomial below 1e-2 (error
// < x⁵/5 relative, below ε) where the direct forms cancel; GLSL has neither.
float log1p_nonneg(float x) {
  return x < 1e-2 ? x * (1.0 - x * (0.5 - x * (1.0 / 3.0 - 0.25 * x))) : log(1.0 + x);
}
float expm1_nonneg(float x) {
  return x < 1e-2 ? x * (1.0 + x * (0.5 + x * (1.0 / 6.0 + x / 24.0))) : exp(x) - 1.0;
}
