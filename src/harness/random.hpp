#pragma once
// A portable random generator for the harness's seeded scenes: PCG32 (O'Neill
// 2014, pcg32_random_r of the reference C code) seeded through splitmix64, with
// its own distributions. The std:: distributions are implementation-defined, so
// the same seed would draw other scenes under GCC and Clang; these are not. The
// floating-point ones use +, −, ×, ÷ and sqrt, correctly rounded everywhere,
// and std::exp and std::log, which come from the same libm whichever compiler
// built the caller; x86-64's baseline has no FMA for a compiler to contract
// into. So a seed gives the same bits under both. Not sin and cos of one angle:
// GCC fuses them into one sincos call, whose last bit can differ from theirs.
// Callers draw one value per statement: the order in which a call's arguments
// (or a + b's operands) are evaluated is unspecified, and GCC and Clang differ.
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>

namespace airlight::harness {

// The k-th output (from 1) of splitmix64 (Steele, Lea, Flood 2014) started at
// `seed`: spreads a small seed over all 64 bits, so that seeds 0, 1, 2 start
// PCG32 in unrelated states.
inline std::uint64_t splitmix64(std::uint64_t seed, std::uint64_t k) {
  std::uint64_t z = seed + k * 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

class Random {
public:
  // pcg32_srandom_r(initstate, initseq): the reference code's own seeding, so its
  // published outputs check this one.
  Random(std::uint64_t initstate, std::uint64_t initseq) : inc_((initseq << 1u) | 1u) {
    next();
    state_ += initstate;
    next();
  }
  // The harness's seeding: state and stream both from splitmix64 of the seed.
  explicit Random(std::uint64_t seed) : Random(splitmix64(seed, 1), splitmix64(seed, 2)) {}

  // pcg32_random_r: XSH RR output of a 64-bit LCG.
  std::uint32_t next() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1) with 53 random bits: every double that step can hold.
  double uniform() {
    const std::uint64_t high = next();
    const std::uint64_t bits = (high << 32) | next();
    return static_cast<double>(bits >> 11) * 0x1p-53;
  }
  // Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform on the integers lo..hi, both included, without modulo bias
  // (pcg32_boundedrand_r: reject the few values below 2³² mod the range).
  int integer(int lo, int hi) {
    const std::uint32_t bound = static_cast<std::uint32_t>(hi - lo) + 1u;
    const std::uint32_t threshold = (0u - bound) % bound;
    for (;;) {
      const std::uint32_t r = next();
      if (r >= threshold) return lo + static_cast<int>(r % bound);
    }
  }
  // Log-uniform in [lo, hi) (both > 0): every decade equally likely.
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  // Uniform over the unit sphere: a point uniform in the unit ball, by rejection
  // from the cube (π/6 of draws kept), scaled to length 1.
  glm::dvec3 unit_vector() {
    for (;;) {
      const double x = uniform(-1.0, 1.0);
      const double y = uniform(-1.0, 1.0);
      const double z = uniform(-1.0, 1.0);
      const double r2 = x * x + y * y + z * z;
      if (r2 > 1e-12 && r2 <= 1.0) return glm::dvec3(x, y, z) / std::sqrt(r2);
    }
  }
  bool bernoulli(double p) { return uniform() < p; }
  template <class T>
  const T& pick(std::span<const T> items) {
    return items[static_cast<size_t>(integer(0, static_cast<int>(items.size()) - 1))];
  }

private:
  std::uint64_t state_ = 0, inc_;
};

}  // namespace airlight::harness
