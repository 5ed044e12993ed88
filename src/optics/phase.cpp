#include "optics/phase.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace airlight::optics {
namespace {

constexpr double pi = std::numbers::pi;

// cos^n(θ/2) = ((1 + cos θ)/2)^(n/2), without computing θ.
double cos_half_pow(double cos_theta, double n) {
  return std::pow(std::max(0.0, 0.5 * (1.0 + cos_theta)), 0.5 * n);
}

// Henyey–Greenstein (Kingston eq. 14): (1 - g²) / (4π (1 + g² - 2g cos θ)^1.5).
double henyey_greenstein(double g, double cos_theta) {
  const double denom = 1.0 + g * g - 2.0 * g * cos_theta;
  return (1.0 - g * g) / (4.0 * pi * denom * std::sqrt(denom));
}

// Schlick (Kingston eq. 15, with the sign of eq. 14 so that k > 0 scatters
// forward like g > 0; his eq. 15 has the opposite convention, docs/decisions.md, Model).
double schlick(double k, double cos_theta) {
  const double denom = 1.0 - k * cos_theta;
  return (1.0 - k * k) / (4.0 * pi * denom * denom);
}

}  // namespace

double schlick_k(double g) {
  // Kingston eq. 16. It exceeds 1 in magnitude for 0.938 < |g| < 1, which puts a
  // pole at cos θ = 1/k inside [-1, 1] and makes 1 - k² negative; |k| <= 0.999
  // keeps the lobe finite, positive and normalized (peak (1+k)/(4π(1-k)) ≈ 159).
  const double k = 1.55 * g - 0.55 * g * g * g;
  return std::clamp(k, -0.999, 0.999);
}

double phase(const PhaseLobe& lobe, double cos_theta) {
  const double g = lobe.g;
  switch (lobe.type) {
    case PhaseType::isotropic: return 1.0 / (4.0 * pi);
    case PhaseType::rayleigh: return 3.0 / (16.0 * pi) * (1.0 + cos_theta * cos_theta);
    case PhaseType::henyey_greenstein: return henyey_greenstein(g, cos_theta);
    case PhaseType::schlick: return schlick(schlick_k(g), cos_theta);
    // Nishita's hazy and murky lobes, normalized over the sphere (dΩ = 2π d cos θ):
    // ∫(1 + 9cos¹⁶(θ/2)) dΩ = 8π, ∫(1 + 50cos⁶⁴(θ/2)) dΩ = 332π/33 (docs/decisions.md,
    // Model: Nilsson Appendix A's K is wrong).
    case PhaseType::hazy: return (1.0 + 9.0 * cos_half_pow(cos_theta, 16)) / (8.0 * pi);
    case PhaseType::murky: return 33.0 * (1.0 + 50.0 * cos_half_pow(cos_theta, 64)) / (332.0 * pi);
  }
  return 0.0;
}

double phase(const Phase& phase_function, double cos_theta) {
  double sum = 0.0;
  for (const PhaseLobe& lobe : phase_function.lobes) sum += lobe.weight * phase(lobe, cos_theta);
  return sum;
}

}  // namespace airlight::optics
