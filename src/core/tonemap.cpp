#include "core/tonemap.hpp"

#include "core/image_io.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace airlight {

namespace {

// Every curve is flat above ~20 (exposed), so this bound loses nothing and keeps
// the ACES fit's products finite for huge or infinite radiance.
constexpr float brightest = 1e6f;

// The matrix whose rows are r, g, b, applied to v.
glm::vec3 rows(const glm::vec3& r, const glm::vec3& g, const glm::vec3& b, glm::vec3 v) {
  return {glm::dot(r, v), glm::dot(g, v), glm::dot(b, v)};
}

// AgX (Troy Sobotka, github.com/sobotka/AgX) in Benjamin Wrensch's "Minimal AgX
// Implementation" (iolite-engine.com/blog_posts/minimal_agx_implementation, 2023),
// the form three.js and Filament started from: inset matrix on linear Rec. 709,
// log2 encoding over [-12.47393, 4.026069] EV (log2 of 0.18·2^-10 and 0.18·2^6.5),
// the 6th-order polynomial fit of the sigmoid, outset matrix. The result is a
// display value for a 2.2 power display (Wrensch's agxEotf), so we decode it with
// the 2.2 power to linear and encode that with the sRGB curve the PNG declares:
// mid grey 0.18 becomes display 0.497, linear 0.215, sRGB 0.50 (8-bit code 128).
constexpr float agx_min_ev = -12.47393f, agx_max_ev = 4.026069f;

glm::vec3 agx(glm::vec3 v) {
  // The inset and outset matrices' rows (Wrensch's agx_mat and agx_mat_inv, transposed
  // from GLSL's column order); each row sums to 1 within 2e-4, so grey stays grey.
  v = rows({0.842479062253094f, 0.0784335999999992f, 0.0792237451477643f},
           {0.0423282422610123f, 0.878468636469772f, 0.0791661274605434f},
           {0.0423756549057051f, 0.0784336f, 0.879142973793104f}, v);
  glm::vec3 display;
  for (int c = 0; c < 3; ++c) {
    const float ev = std::log2(std::max(v[c], 1e-10f));  // black to the bottom of the range
    display[c] = agx_contrast(std::clamp((ev - agx_min_ev) / (agx_max_ev - agx_min_ev), 0.0f, 1.0f));
  }
  display = rows({1.19687900512017f, -0.0980208811401368f, -0.0990297440797205f},
                 {-0.0528968517574562f, 1.15190312990417f, -0.0989611768448433f},
                 {-0.0529716355144438f, -0.0980434501171241f, 1.15107367264116f}, display);
  glm::vec3 linear;
  for (int c = 0; c < 3; ++c) linear[c] = std::pow(std::max(display[c], 0.0f), 2.2f);
  return linear;
}

// Stephen Hill's fit of the ACES RRT+ODT (github.com/TheRealMJP/BakingLab,
// ACES.hlsl, 2016): sRGB to the RRT's working space, the rational fit, back to
// linear sRGB. Input scaled by 1/0.6 as three.js does (ACESFilmicToneMapping),
// so that mid grey 0.18 lands near where the clamp curve puts it (sRGB 0.50
// rather than 0.36). The fit reaches 1 at ~15 (exposed) and clips there.
glm::vec3 aces(glm::vec3 v) {
  v = rows({0.59719f, 0.35458f, 0.04823f}, {0.07600f, 0.90834f, 0.01566f}, {0.02840f, 0.13383f, 0.83777f},
           v / 0.6f);
  const glm::vec3 a = v * (v + 0.0245786f) - 0.000090537f;
  const glm::vec3 b = v * (0.983729f * v + 0.4329510f) + 0.238081f;
  return rows({1.60475f, -0.53108f, -0.07367f}, {-0.10208f, 1.10813f, -0.00605f}, {-0.00327f, -0.07276f, 1.07602f},
              a / b);
}

}  // namespace

std::optional<ToneCurve> tone_curve(const std::string& name) {
  if (name == "agx") return ToneCurve::agx;
  if (name == "aces") return ToneCurve::aces;
  if (name == "clamp") return ToneCurve::clamp;
  return std::nullopt;
}

const char* tone_curve_name(ToneCurve curve) {
  switch (curve) {
    case ToneCurve::agx: return "agx";
    case ToneCurve::aces: return "aces";
    case ToneCurve::clamp: return "clamp";
  }
  return "?";
}

float agx_contrast(float x) {
  // Wrensch's 6th-order fit (mean squared error 3.7e-6), in Horner form.
  return ((((((15.5f * x - 40.14f) * x + 31.96f) * x - 6.868f) * x + 0.4298f) * x + 0.1191f) * x) - 0.00232f;
}

float luminance(glm::vec3 rgb) { return 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b; }

glm::vec3 tone_map(glm::vec3 radiance, const ToneMap& tone) {
  glm::vec3 v;
  for (int c = 0; c < 3; ++c)
    v[c] = std::isnan(radiance[c]) ? 0.0f : std::clamp(radiance[c] * tone.exposure, 0.0f, brightest);
  const glm::vec3 linear = tone.curve == ToneCurve::agx ? agx(v) : tone.curve == ToneCurve::aces ? aces(v) : v;
  return {linear_to_srgb(linear.r), linear_to_srgb(linear.g), linear_to_srgb(linear.b)};  // clamps to [0, 1]
}

float auto_exposure(const Image& image) {
  constexpr double delta = 1e-6, key = 0.18;
  double sum = 0.0;
  long count = 0;
  for (const auto& p : image.pixels) {
    const double y = luminance(p);
    if (!std::isfinite(y) || y <= 0.0) continue;
    sum += std::log(delta + y);
    ++count;
  }
  return count ? static_cast<float>(key / std::exp(sum / static_cast<double>(count))) : 1.0f;
}

}  // namespace airlight
