#include "harness/run.hpp"

#include "reference/brute_force.hpp"
#include "reference/reference.hpp"

#include <airlight/error.hpp>

#include <chrono>
#include <map>
#include <exception>

namespace airlight::harness {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

const Trial* find_trial(const MethodInfo& method, const std::string& name) {
  for (const Trial& t : method.trials)
    if (t.name == name) return &t;
  if (name == "defaults") return nullptr;
  throw InputError("--trial", name, "is not a trial of " + method.name);
}

// Drops the elements of `list` one at a time, each for good when the scene without it still fails.
template <class T, class Fails>
void drop_while_failing(Scene& scene, std::vector<T> Scene::*list, const Fails& still_fails) {
  for (size_t i = (scene.*list).size(); i-- > 0;) {
    Scene smaller = scene;
    (smaller.*list).erase((smaller.*list).begin() + static_cast<long>(i));
    if (still_fails(smaller)) scene = std::move(smaller);
  }
}

// Where the reference is checked against brute force: its brightest pixel (a
// light's image, a shaft's core), the middle, and two more on the diagonals.
std::vector<glm::ivec2> checked_pixels(const Image& reference) {
  glm::ivec2 brightest(0);
  float peak = -1.0f;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x)
      if (const glm::vec3 p = reference.at(x, y); p.r + p.g + p.b > peak) {
        peak = p.r + p.g + p.b;
        brightest = {x, y};
      }
  const int w = reference.width, h = reference.height;
  return {brightest, {w / 2, h / 2}, {w / 4, h / 4}, {3 * w / 4, 3 * h / 4}};
}

}  // namespace

Harness::Harness(std::vector<const MethodInfo*> methods, int width, int height)
    : methods_(std::move(methods)), width_(width), height_(height) {}

Reference Harness::reference(const Scene& scene, const Capabilities& capabilities) const {
  const Scene judged_by = judged_scene(scene, capabilities);
  std::vector<Image> images{reference::render(judged_by, width_, height_).airlight};
  const std::vector<bool> sharp = sharp_pixels(images[0]);
  const auto at_sharp_pixels = [&](reference::Settings settings) {
    settings.pixels = sharp;
    Image image = reference::render(judged_by, width_, height_, settings).airlight;
    for (size_t i = 0; i < sharp.size(); ++i)
      if (!sharp[i]) image.pixels[i] = images[0].pixels[i];  // smooth there: the centre's value
    images.push_back(std::move(image));
  };
  for (const glm::dvec2 shift : {glm::dvec2(bracket_shift, 0.0), {-bracket_shift, 0.0}, {0.0, bracket_shift},
                                 {0.0, -bracket_shift}})
    at_sharp_pixels({.subpixel = glm::dvec2(0.5) + shift});
  for (const double shift : {near_margin(scene.camera), -near_margin(scene.camera)})
    at_sharp_pixels({.near_shift = shift});
  return bracket(images);
}

// `method`'s airlight on `scene` with `settings` over its defaults (`origin`
// names where they come from in messages).
Image Harness::airlight(const Scene& scene, const MethodInfo& method, const std::vector<std::string>& settings,
                        const std::string& origin) const {
  Settings chosen(method.settings);
  for (const std::string& s : settings) chosen.set(s, origin);
  auto instance = method.create(chosen);
  instance->prepare(scene);
  return render(*instance, scene, width_, height_, false).airlight;
}

Verdict Harness::judge(const Scene& scene, const MethodInfo& method, const Trial* trial, const Reference& reference,
                       double* seconds) const {
  const std::string name = trial ? trial->name : "defaults";
  const auto start = std::chrono::steady_clock::now();
  Image image;
  try {
    image = airlight(scene, method, trial ? trial->settings : std::vector<std::string>{}, "trial " + name);
  } catch (const std::exception& e) {  // a valid scene must render: any refusal or failure is the method's defect
    if (seconds) *seconds = seconds_since(start);
    return {name, "renders", 0.0, 0.0, false, e.what()};
  }
  if (seconds) *seconds = seconds_since(start);
  if (!trial) return judge_defaults(image, reference);
  if (trial->baseline.method.empty()) return judge_trial(*trial, image, reference);
  Image baseline;
  try {
    baseline = airlight(scene, find_method(trial->baseline.method), trial->baseline.settings,
                        "trial " + name + "'s baseline");
  } catch (const std::exception& e) {
    return {name, "renders", 0.0, 0.0, false, "the baseline " + trial->baseline.method + ": " + e.what()};
  }
  return judge_trial(*trial, image, widened(reference, baseline));
}

Outcome Harness::judge(const Scene& scene) const {
  Outcome outcome;
  const Reference full = reference(scene, {});
  outcome.reference_mean = mean(full.centre);
  outcome.visible = judged(scene, full.centre);
  if (!outcome.visible) return outcome;
  const std::vector<glm::ivec2> pixels = checked_pixels(full.centre);
  const auto start = std::chrono::steady_clock::now();
  Judgement brute{"reference", judge_reference(full.centre, pixels, reference::brute_force_airlight(
                                                                 scene, width_, height_, pixels)), 0.0};
  brute.seconds = seconds_since(start);
  outcome.judgements.push_back(std::move(brute));
  // One reference per scene judged: judged_scene names each by what it took out.
  std::map<std::string, Reference> references{{scene.name, full}};
  for (const MethodInfo* method : methods_) {
    const Scene judged_by = judged_scene(scene, method->capabilities);
    auto [own, fresh] = references.try_emplace(judged_by.name);
    if (fresh) own->second = reference(scene, method->capabilities);
    std::vector<const Trial*> trials{nullptr};
    for (const Trial& t : method->trials) trials.push_back(&t);
    for (const Trial* t : trials) {
      Judgement j{method->name, {}, 0.0};
      j.verdict = judge(scene, *method, t, own->second, &j.seconds);
      outcome.judgements.push_back(std::move(j));
    }
  }
  return outcome;
}

Verdict Harness::judge(const Scene& scene, const MethodInfo& method, const std::string& trial) const {
  return judge(scene, method, find_trial(method, trial), reference(scene, method.capabilities), nullptr);
}

// A smaller scene counts only while it is still one the harness would judge:
// dropping the light that makes the fog visible leaves a near-black reference
// whose relative errors say nothing.
Scene Harness::shrink(Scene scene, const MethodInfo& method, const std::string& trial) const {
  const Trial* t = find_trial(method, trial);
  const auto still_fails = [&](const Scene& s) {
    const Reference r = reference(s, method.capabilities);
    return judged(s, r.centre) && fails(judge(s, method, t, r, nullptr));
  };
  drop_while_failing(scene, &Scene::lights, still_fails);
  drop_while_failing(scene, &Scene::meshes, still_fails);
  drop_while_failing(scene, &Scene::volumes, still_fails);
  return scene;
}

}  // namespace airlight::harness
