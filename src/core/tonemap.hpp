#pragma once
// PNG tone mapping (docs/decisions.md "PNG tone mapping"): linear radiance in
// W/(m²·sr) × exposure, through a display curve, to sRGB-encoded values in [0, 1].
// Only PNG output goes through here; PFM, EXR and every metric stay linear.
#include <airlight/image.hpp>
#include <optional>
#include <string>

namespace airlight {

enum class ToneCurve {
  agx,    // Sobotka's AgX, Wrensch's polynomial fit: highlights roll off and desaturate
  aces,   // Hill's fit of the ACES RRT+ODT
  clamp,  // exposure, clip to [0, 1], sRGB: bright values clip to flat white
};

struct ToneMap {
  float exposure = 1.0f;  // linear radiance is multiplied by this before the curve
  ToneCurve curve = ToneCurve::agx;
};

// "agx", "aces", "clamp"; nullopt for any other name.
std::optional<ToneCurve> tone_curve(const std::string& name);
const char* tone_curve_name(ToneCurve curve);

// One pixel's sRGB-encoded display values in [0, 1]. NaN counts as 0 and
// negative radiance as 0, so the result is always finite.
glm::vec3 tone_map(glm::vec3 radiance, const ToneMap& tone);

// AgX's sigmoid on the normalised log2 value x in [0, 1]: the display value
// before the outset matrix (exposed for its tests).
float agx_contrast(float x);

// Rec. 709 luminance of linear RGB.
float luminance(glm::vec3 rgb);

// Reinhard et al. 2002, eq. 1-2: the exposure that maps the log-average luminance
// exp(mean(log(δ + Y))) to the key 0.18, δ = 1e-6 W/(m²·sr). Pixels with a
// non-finite or non-positive Y are left out (black sky carries no exposure
// information yet would dominate the log mean); with none left the exposure is 1.
float auto_exposure(const Image& image);

}  // namespace airlight
