#include "methods/kit/sampling/noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

namespace airlight::kit {
namespace {

// A 32-bit integer hash with good avalanche (Wellons' "lowbias32").
uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// Σ over set texels q of exp(−|p − q|²/2σ²) on the torus, kept up to date as
// texels are set and cleared.
class EnergyField {
public:
  explicit EnergyField(int size) : size_(size), kernel_(size * size), energy_(size * size, 0.0), bits_(size * size, 0) {
    constexpr double sigma = 1.5;
    for (int dy = 0; dy < size; ++dy)
      for (int dx = 0; dx < size; ++dx) {
        const int x = std::min(dx, size - dx), y = std::min(dy, size - dy);
        kernel_[dy * size + dx] = std::exp(-(x * x + y * y) / (2.0 * sigma * sigma));
      }
  }
  int count() const { return static_cast<int>(bits_.size()); }
  bool is_set(int p) const { return bits_[p] != 0; }
  void set(int p, bool on) {
    bits_[p] = on;
    const double sign = on ? 1.0 : -1.0;
    const int px = p % size_, py = p / size_;
    for (int qy = 0; qy < size_; ++qy) {
      const double* row = &kernel_[((qy - py + size_) % size_) * size_];
      double* energy = &energy_[qy * size_];
      for (int qx = 0; qx < size_; ++qx) energy[qx] += sign * row[qx >= px ? qx - px : qx - px + size_];
    }
  }
  // The set texel of highest energy, or the clear texel of lowest.
  int tightest_cluster() const { return extreme(true); }
  int largest_void() const { return extreme(false); }

private:
  int extreme(bool set) const {
    int best = -1;
    for (int p = 0; p < count(); ++p) {
      if (is_set(p) != set) continue;
      if (best < 0 || (set ? energy_[p] > energy_[best] : energy_[p] < energy_[best])) best = p;
    }
    return best;
  }
  int size_;
  std::vector<double> kernel_, energy_;
  std::vector<char> bits_;
};

// Ulichney's initial binary pattern: random 10% of the texels, then moving the
// tightest cluster into the largest void until that changes nothing.
EnergyField initial_pattern(int size) {
  EnergyField field(size);
  std::mt19937 random(1993);
  std::uniform_int_distribution<int> texel(0, size * size - 1);
  for (int placed = 0; placed < size * size / 10;) {
    const int p = texel(random);
    if (!field.is_set(p)) {
      field.set(p, true);
      ++placed;
    }
  }
  for (;;) {
    const int cluster = field.tightest_cluster();
    field.set(cluster, false);
    const int hole = field.largest_void();
    field.set(hole, true);
    if (hole == cluster) return field;
  }
}

}  // namespace

std::vector<float> white_noise(int size) {
  std::vector<float> values(static_cast<size_t>(size) * size);
  for (size_t i = 0; i < values.size(); ++i)
    values[i] = static_cast<float>(hash32(static_cast<uint32_t>(i)) >> 8) * 0x1p-24f;
  return values;
}

std::vector<float> blue_noise(int size) {
  const int n = size * size;
  const EnergyField prototype = initial_pattern(size);
  std::vector<int> rank(n, 0);
  int ones = 0;
  for (int p = 0; p < n; ++p) ones += prototype.is_set(p);
  // Phase 1: clear the tightest clusters, ranking them downward from ones − 1.
  EnergyField field = prototype;
  for (int r = ones - 1; r >= 0; --r) {
    const int p = field.tightest_cluster();
    field.set(p, false);
    rank[p] = r;
  }
  // Phases 2 and 3: fill the largest voids upward. (Ulichney's phase 3 takes the
  // tightest cluster of the clear texels; with the full toroidal kernel their
  // energy is a constant minus this one, so it is the same texel.)
  field = prototype;
  for (int r = ones; r < n; ++r) {
    const int p = field.largest_void();
    field.set(p, true);
    rank[p] = r;
  }
  std::vector<float> values(n);
  for (int p = 0; p < n; ++p) values[p] = (static_cast<float>(rank[p]) + 0.5f) / static_cast<float>(n);
  return values;
}

}  // namespace airlight::kit
