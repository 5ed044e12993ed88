#include "harness/judge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace airlight::harness {

namespace {

std::string pixel_text(int x, int y) { return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

float largest_channel(const glm::vec3& p) { return std::max({p.r, p.g, p.b}); }

// How far outside the reference's bracket `value` lies, per channel.
glm::vec3 outside(const glm::vec3& value, const Reference& reference, size_t i) {
  return glm::max(glm::max(value - reference.high.pixels[i], reference.low.pixels[i] - value), glm::vec3(0.0f));
}

float peak_of(const Image& image) {
  float peak = 0.0f;
  for (const auto& p : image.pixels) peak = std::max(peak, largest_channel(p));
  return peak;
}

std::string against(const Reference& r, int x, int y) {
  const float c = largest_channel(r.centre.at(x, y)), lo = largest_channel(r.low.at(x, y)),
              hi = largest_channel(r.high.at(x, y));
  return number(c) + (lo == hi ? "" : " (" + number(lo) + " to " + number(hi) + " near the pixel's centre)");
}

// Finite and non-negative come first: a NaN would pass any bound it is compared with.
Verdict value_check(const std::string& trial, const Image& method) {
  const std::string bad = bad_value(method);
  return {trial, "finite", 0.0, 0.0, bad.empty(), bad};
}

Verdict rel_rmse_verdict(const std::string& trial, const Image& method, const Reference& reference, double bound) {
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

Reference bracket(const std::vector<Image>& images) {
  Reference r{images.at(0), images[0], images[0]};
  for (const Image& shifted : images)
    for (size_t i = 0; i < r.centre.pixels.size(); ++i) {
      r.low.pixels[i] = glm::min(r.low.pixels[i], shifted.pixels.at(i));
      r.high.pixels[i] = glm::max(r.high.pixels[i], shifted.pixels[i]);
    }
  return r;
}

std::vector<bool> sharp_pixels(const Image& centre) {
  std::vector<bool> sharp(centre.pixels.size(), false);
  for (int y = 0; y < centre.height; ++y)
    for (int x = 0; x < centre.width; ++x) {
      const double c = largest_channel(centre.at(x, y));
      bool edge = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= centre.width || ny >= centre.height) continue;
          edge = edge || std::abs(largest_channel(centre.at(nx, ny)) - c) > bracket_sharpness * c;
        }
      sharp[static_cast<size_t>(y * centre.width + x)] = edge;
    }
  return sharp;
}

double rel_rmse(const Image& method, const Reference& reference) {
  double squared = 0.0, sum = 0.0;
  const std::vector<glm::vec3>& centre = reference.centre.pixels;
  for (size_t i = 0; i < centre.size(); ++i) {
    const glm::dvec3 d(outside(method.pixels[i], reference, i));
    squared += glm::dot(d, d);
    sum += double(centre[i].r) + centre[i].g + centre[i].b;
  }
  const double n = 3.0 * static_cast<double>(centre.size());
  return std::sqrt(squared / n) / std::max(sum / n, absolute_floor);
}

WorstPixel worst_pixel(const Image& method, const Reference& reference) {
  const Image& centre = reference.centre;
  const double judged = std::max(judged_share * peak_of(centre), absolute_floor);
  WorstPixel worst;
  for (int y = 0; y < centre.height; ++y)
    for (int x = 0; x < centre.width; ++x) {
      const double r = largest_channel(centre.at(x, y));
      if (r < judged) continue;
      const size_t i = static_cast<size_t>(y) * static_cast<size_t>(centre.width) + static_cast<size_t>(x);
      const glm::vec3 nearest = glm::clamp(method.at(x, y), reference.low.pixels[i], reference.high.pixels[i]);
      const double e = largest_channel(outside(method.at(x, y), reference, i)) / std::max(r, double(largest_channel(nearest)));
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
  const float peak = peak_of(reference);
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

Verdict judge_defaults(const Image& method, const Reference& reference) {
  Verdict finite = value_check("defaults", method);
  if (!finite.pass) return finite;
  const float method_peak = peak_of(method);
  if (peak_of(reference.high) == 0.0f)  // no light reaches the fog: any airlight is made up
    return {"defaults", "zero", method_peak, 0.0, method_peak == 0.0f,
            method_peak == 0.0f ? "" : "airlight " + number(method_peak) + " where the reference has none"};
  return rel_rmse_verdict("defaults", method, reference, default_rel_rmse);
}

Verdict judge_trial(const Trial& trial, const Image& method, const Reference& reference) {
  Verdict finite = value_check(trial.name, method);
  if (!finite.pass) return finite;
  if (trial.measure == Trial::Measure::rel_rmse) return rel_rmse_verdict(trial.name, method, reference, trial.bound);
  const WorstPixel w = worst_pixel(method, reference);
  const bool pass = w.error <= trial.bound;
  std::string detail;
  if (!pass)
    detail = pixel_text(w.x, w.y) + ": " + number(largest_channel(method.at(w.x, w.y))) + " against " +
             against(reference, w.x, w.y) + ", error " + number(w.error) + " > " + number(trial.bound);
  return {trial.name, "worst_pixel", w.error, trial.bound, pass, detail};
}

Reference widened(Reference reference, const Image& other) {
  for (size_t i = 0; i < other.pixels.size(); ++i) {
    reference.low.pixels[i] = glm::min(reference.low.pixels[i], other.pixels[i]);
    reference.high.pixels[i] = glm::max(reference.high.pixels[i], other.pixels[i]);
  }
  return reference;
}

}  // namespace airlight::harness
