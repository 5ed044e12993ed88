#include "harness/judge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace airlight::harness {

namespace {

std::string pixel_text(int x, int y) { return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

float largest_channel(const glm::vec3& p) { return std::max({p.r, p.g, p.b}); }

// Finite and non-negative come first: a NaN would pass any bound it is compared with.
Verdict value_check(const std::string& trial, const Image& method) {
  const std::string bad = bad_value(method);
  return {trial, "finite", 0.0, 0.0, bad.empty(), bad};
}

Verdict rel_rmse_verdict(const std::string& trial, const Image& method, const Image& reference, double bound) {
  const double e = rel_rmse(method, reference);
  return {trial, "rel_rmse", e, bound, e <= bound, e <= bound ? "" : "rRMSE " + number(e) + " > " + number(bound)};
}

}  // namespace

double mean(const Image& image) {
  double sum = 0.0;
  for (const auto& p : image.pixels) sum += double(p.r) + p.g + p.b;
  return sum / (3.0 * static_cast<double>(image.pixels.size()));
}

bool judged(const Scene& scene, const Image& reference) {
  return scene.lights.empty() || mean(reference) >= visible_mean;
}

double rel_rmse(const Image& method, const Image& reference) {
  double squared = 0.0, sum = 0.0;
  for (size_t i = 0; i < reference.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(method.pixels[i][c]) - reference.pixels[i][c];
      squared += d * d;
      sum += reference.pixels[i][c];
    }
  const double n = 3.0 * static_cast<double>(reference.pixels.size());
  return std::sqrt(squared / n) / std::max(sum / n, absolute_floor);
}

WorstPixel worst_pixel(const Image& method, const Image& reference) {
  float peak = 0.0f;
  for (const auto& p : reference.pixels) peak = std::max(peak, largest_channel(p));
  const double judged = std::max(judged_share * peak, absolute_floor);
  WorstPixel worst;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      const double r = largest_channel(reference.at(x, y));
      if (r < judged) continue;
      const glm::vec3 d = glm::abs(method.at(x, y) - reference.at(x, y));
      const double e = largest_channel(d) / r;
      if (e > worst.error || worst.x < 0) worst = {e, x, y};
    }
  return worst;
}

std::string bad_value(const Image& image) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = image.at(x, y)[c];
        if (std::isnan(v)) return pixel_text(x, y) + " is NaN";
        if (std::isinf(v)) return pixel_text(x, y) + " is infinite";
        if (v < 0.0f) return pixel_text(x, y) + " is negative (" + number(v) + ")";
      }
  return {};
}

Verdict judge_reference(const Image& reference, const std::vector<glm::ivec2>& pixels,
                        const std::vector<glm::dvec3>& brute_force) {
  float peak = 0.0f;
  for (const auto& p : reference.pixels) peak = std::max(peak, largest_channel(p));
  Verdict v{"brute force", "worst_pixel", 0.0, reference_bound, true, ""};
  for (size_t k = 0; k < pixels.size(); ++k) {
    const glm::dvec3 r(reference.at(pixels[k].x, pixels[k].y)), b = brute_force[k];
    const double scale = std::max({b.r, b.g, b.b, reference_floor * peak, absolute_floor});
    const double e = std::max({std::abs(r.r - b.r), std::abs(r.g - b.g), std::abs(r.b - b.b)}) / scale;
    if (e <= v.value) continue;
    v.value = e;
    v.pass = e <= reference_bound;
    v.detail = v.pass ? "" : pixel_text(pixels[k].x, pixels[k].y) + ": reference " + number(std::max({r.r, r.g, r.b})) +
                                 " against brute force " + number(std::max({b.r, b.g, b.b})) + ", error " + number(e);
  }
  return v;
}

Verdict judge_defaults(const Image& method, const Image& reference) {
  Verdict finite = value_check("defaults", method);
  if (!finite.pass) return finite;
  float peak = 0.0f, method_peak = 0.0f;
  for (const auto& p : reference.pixels) peak = std::max(peak, largest_channel(p));
  for (const auto& p : method.pixels) method_peak = std::max(method_peak, largest_channel(p));
  if (peak == 0.0f)  // no light reaches the fog: any airlight is made up
    return {"defaults", "zero", method_peak, 0.0, method_peak == 0.0f,
            method_peak == 0.0f ? "" : "airlight " + number(method_peak) + " where the reference has none"};
  return rel_rmse_verdict("defaults", method, reference, default_rel_rmse);
}

Verdict judge_trial(const Trial& trial, const Image& method, const Image& reference) {
  Verdict finite = value_check(trial.name, method);
  if (!finite.pass) return finite;
  if (trial.measure == Trial::Measure::rel_rmse) return rel_rmse_verdict(trial.name, method, reference, trial.bound);
  const WorstPixel w = worst_pixel(method, reference);
  const bool pass = w.error <= trial.bound;
  std::string detail;
  if (!pass)
    detail = pixel_text(w.x, w.y) + ": " + number(largest_channel(method.at(w.x, w.y))) + " against " +
             number(largest_channel(reference.at(w.x, w.y))) + ", error " + number(w.error) + " > " + number(trial.bound);
  return {trial.name, "worst_pixel", w.error, trial.bound, pass, detail};
}

}  // namespace airlight::harness
