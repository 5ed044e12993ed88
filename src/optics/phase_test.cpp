#include "optics/phase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "optics/gauss_kronrod.hpp"

namespace airlight::optics {
namespace {

constexpr double pi = std::numbers::pi;

// ∫ f(cos θ) dΩ = 2π ∫_{-1}^{1} f(c) dc (adaptive G7K15, relative 1e-12: its
// error is negligible against every tolerance below).
template <class F>
double sphere_integral(F&& f) {
  gk::Settings s;
  s.rel_tol = 1e-12;
  return 2.0 * pi * gk::integrate<double>(f, {-1.0, 0.0, 1.0}, s);
}

double norm(const Phase& p) {
  return sphere_integral([&](double c) { return phase(p, c); });
}
double mean_cosine(const Phase& p) {
  return sphere_integral([&](double c) { return c * phase(p, c); });
}
Phase lobe(PhaseType type, float g = 0.0f) { return Phase{{PhaseLobe{type, g, 1.0f}}}; }

const float kGs[] = {-0.99f, -0.9f, -0.5f, 0.0f, 0.3f, 0.7f, 0.9f, 0.95f, 0.99f};

TEST(Phase, EveryLobeIntegratesToOne) {
  // 1e-4 (the brief): the functions are normalized analytically, so the
  // residual is the quadrature's (~1e-12).
  for (PhaseType t : {PhaseType::isotropic, PhaseType::rayleigh, PhaseType::hazy, PhaseType::murky})
    EXPECT_NEAR(norm(lobe(t)), 1.0, 1e-4) << int(t);
  for (float g : kGs) {
    EXPECT_NEAR(norm(lobe(PhaseType::henyey_greenstein, g)), 1.0, 1e-4) << "HG g=" << g;
    EXPECT_NEAR(norm(lobe(PhaseType::schlick, g)), 1.0, 1e-4) << "Schlick g=" << g;
  }
}

TEST(Phase, WeightedSumIntegratesToOne) {
  const Phase sum{{PhaseLobe{PhaseType::rayleigh, 0.0f, 0.3f},
                   PhaseLobe{PhaseType::henyey_greenstein, 0.7f, 0.5f},
                   PhaseLobe{PhaseType::murky, 0.0f, 0.2f}}};
  EXPECT_NEAR(norm(sum), 1.0, 1e-4);  // 1e-4: as for single lobes
}

TEST(Phase, HenyeyGreensteinMeanCosineIsG) {
  // 1e-9: HG's mean cosine is g exactly; only the quadrature's error remains.
  for (float g : kGs) EXPECT_NEAR(mean_cosine(lobe(PhaseType::henyey_greenstein, g)), g, 1e-9) << g;
}

TEST(Phase, GreaterThanZeroScattersForward) {
  // docs/design.md §1: cos θ = +1 is forward (toward a viewer facing the light); Kingston
  // eq. 15 has the opposite sign, so this catches a copied Schlick.
  for (PhaseType t : {PhaseType::henyey_greenstein, PhaseType::schlick}) {
    EXPECT_GT(phase(lobe(t, 0.5f), 1.0), phase(lobe(t, 0.5f), -1.0));
    EXPECT_LT(phase(lobe(t, -0.5f), 1.0), phase(lobe(t, -0.5f), -1.0));
  }
  EXPECT_GT(phase(lobe(PhaseType::hazy), 1.0), phase(lobe(PhaseType::hazy), -1.0));
}

TEST(Phase, SchlickKStaysInsideTheUnitInterval) {
  EXPECT_DOUBLE_EQ(schlick_k(0.0), 0.0);
  EXPECT_NEAR(schlick_k(0.5), 1.55 * 0.5 - 0.55 * 0.125, 1e-15);  // Kingston eq. 16
  EXPECT_DOUBLE_EQ(schlick_k(0.95), 0.999);  // 1.55g - 0.55g³ = 1.0009 > 1 here
  EXPECT_DOUBLE_EQ(schlick_k(-1.0), -0.999);
  EXPECT_TRUE(std::isfinite(phase(lobe(PhaseType::schlick, 0.95f), 1.0)));
}

TEST(Phase, SchlickApproximatesHenyeyGreenstein) {
  // Schlick's k(g) is a fit, not an identity: its mean cosine overshoots g, and
  // the L1 distance ∫|p_S - p_HG| dΩ grows with |g| (the forward peaks differ
  // most). The bounds 0.08 and 0.45 just cover the gap measured over |g| <= 0.9
  // (docs/decisions.md, Model).
  double worst_mean = 0.0, worst_l1 = 0.0;
  for (int i = -18; i <= 18; ++i) {
    const float g = 0.05f * float(i);
    const Phase hg = lobe(PhaseType::henyey_greenstein, g), s = lobe(PhaseType::schlick, g);
    worst_mean = std::max(worst_mean, std::abs(mean_cosine(s) - g));
    worst_l1 = std::max(worst_l1, sphere_integral([&](double c) {
                          return std::abs(phase(s, c) - phase(hg, c));
                        }));
  }
  std::printf("Schlick vs HG, |g| <= 0.9: worst |mean cos - g| = %.4f, worst L1 = %.4f\n",
              worst_mean, worst_l1);
  EXPECT_LT(worst_mean, 0.08);
  EXPECT_LT(worst_l1, 0.45);
}

TEST(Phase, ClosedFormValues) {
  // Spot values from the formulas of docs/design.md §1 (1e-15 relative: rounding).
  EXPECT_NEAR(phase(lobe(PhaseType::isotropic), 0.3), 1.0 / (4 * pi), 1e-17);
  EXPECT_NEAR(phase(lobe(PhaseType::rayleigh), 1.0), 6.0 / (16 * pi), 1e-16);
  EXPECT_NEAR(phase(lobe(PhaseType::hazy), 1.0), 10.0 / (8 * pi), 1e-15);
  EXPECT_NEAR(phase(lobe(PhaseType::hazy), -1.0), 1.0 / (8 * pi), 1e-16);
  EXPECT_NEAR(phase(lobe(PhaseType::murky), 1.0), 51.0 * 33.0 / (332 * pi), 1e-14);
  EXPECT_NEAR(phase(lobe(PhaseType::henyey_greenstein, 0.5f), 1.0), 0.75 / (4 * pi * 0.125), 1e-14);
}

}  // namespace
}  // namespace airlight::optics
