#pragma once
// Per-pixel sample offsets for jittered ray marching (Kingston §5.1.1: a noise
// texture varies the start of the samples per pixel so that the steps' bands
// become noise). Both textures are tiles of values in (0, 1), row-major.
#include <string>
#include <vector>

namespace airlight::kit {

inline constexpr int noise_size = 64;  // texels per side of a tile

// The `jitter` setting of marching methods; jitter_choices names it in order.
enum class Jitter { none, white, blue };
inline const std::vector<std::string> jitter_choices{"none", "white", "blue"};

// White noise: a 32-bit integer hash of the texel index, uniform in [0, 1).
std::vector<float> white_noise(int size = noise_size);

// Blue noise by void-and-cluster (Ulichney 1993): a toroidal Gaussian energy
// (σ = 1.5 texels) ranks every texel; value = (rank + 0.5) / size². Each value
// occurs once (a stratified uniform set) and neighbours differ more than white
// noise's, so the marching error becomes high-frequency noise.
std::vector<float> blue_noise(int size = noise_size);

}  // namespace airlight::kit
