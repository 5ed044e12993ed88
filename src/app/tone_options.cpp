#include "app/tone_options.hpp"

#include <airlight/error.hpp>

#include <cmath>
#include <cstdio>

namespace airlight::app {

std::optional<float> parse_exposure(const std::string& text) {
  if (text == "auto") return std::nullopt;
  size_t end = 0;
  float value = 0.0f;
  try {
    value = std::stof(text, &end);
  } catch (const std::logic_error&) {  // not a number, or out of float's range
    end = 0;
  }
  if (end == 0 || end != text.size() || !std::isfinite(value) || value <= 0.0f)
    throw InputError("--exposure", "", "must be a positive number or auto, got '" + text + "'");
  return value;
}

void ToneOptions::add_options(CLI::App& command) {
  command.add_option("--tonemap", curve, "PNG tone curve: agx (highlights roll off), aces, clamp (clip at 1)")
      ->check(CLI::IsMember({"agx", "aces", "clamp"}))
      ->capture_default_str();
  command
      .add_option_function<std::string>(
          "--exposure", [this](const std::string& text) { exposure = parse_exposure(text); },
          "PNG exposure: radiance is multiplied by this before the curve; auto: 0.18 / log-average luminance")
      ->default_str("1");
}

ToneMap ToneOptions::resolve(const Image& image, const std::string& command) const {
  const ToneMap tone{exposure ? *exposure : auto_exposure(image), *tone_curve(curve)};
  if (!exposure) std::fprintf(stderr, "%s: --exposure auto: %.4g\n", command.c_str(), tone.exposure);
  return tone;
}

}  // namespace airlight::app
