// The harness with a method made to fail: it is judged failing, and shrinking
// drops every light, mesh and volume the failure does not need while the scene
// stays visible.
#include "harness/run.hpp"

#include "methods/kit/method/registry.hpp"
#include "reference/reference.hpp"

#include <gtest/gtest.h>

namespace airlight::harness {
namespace {

// Airlight zero everywhere: fails every visible scene, passes one without lights.
class Dark final : public Method {
public:
  void prepare(const Scene&) override {}
  void render_frame(const FrameInputs& in) override { size_ = {in.width, in.height}; }
  FrameImages read_back() const override { return {Image(size_.x, size_.y), Image(size_.x, size_.y), {}, 0.0, {}}; }

private:
  glm::ivec2 size_{0};
};

MethodInfo dark() {
  MethodInfo info;
  info.name = "dark";
  info.create = [](const Settings&) { return std::make_unique<Dark>(); };
  return info;
}

// Half the reference's airlight: off the reference by 50 % in every pixel.
// Registered (in this test binary only), so that a trial can name it as its baseline.
class Half final : public Method {
public:
  void prepare(const Scene& s) override { scene_ = s; }
  void render_frame(const FrameInputs& in) override {
    image_ = reference::render(scene_, in.width, in.height).airlight;
    for (glm::vec3& p : image_.pixels) p *= 0.5f;
  }
  FrameImages read_back() const override { return {image_, Image(image_.width, image_.height), {}, 0.0, {}}; }

private:
  Scene scene_;
  Image image_;
};

MethodInfo half() {
  MethodInfo info;
  info.name = "half_reference";
  info.settings = {{"scale", SettingSpec::Type::real, 0.5, 0.5, 0.5, {}, "the one scale it has"}};
  info.create = [](const Settings&) { return std::make_unique<Half>(); };
  return info;
}
AIRLIGHT_REGISTER_METHOD(99, half);

// Two spots each bright enough alone, a box, a sphere and a volume.
Scene scene() {
  Scene s = builtin_scene("biri_sphere");
  s.lights.push_back(s.lights.front());
  s.lights.back().position.x += 0.5f;
  s.volumes.push_back({{-1, 0, -1}, {1, 2, 1}, glm::vec3(0.1f), glm::vec3(0.0f), {}});
  return s;
}

TEST(Harness, AMethodThatDropsTheAirlightFailsItsDefaults) {
  const MethodInfo info = dark();
  const Harness harness({&info}, 16, 12);
  const Outcome outcome = harness.judge(scene());
  ASSERT_TRUE(outcome.visible);
  ASSERT_EQ(outcome.judgements.size(), 2u);  // the reference against brute force, then the method
  EXPECT_EQ(outcome.judgements[0].method, "reference");
  EXPECT_TRUE(outcome.judgements[0].verdict.pass) << outcome.judgements[0].verdict.detail;
  EXPECT_FALSE(outcome.judgements[1].verdict.pass);
  EXPECT_EQ(outcome.judgements[1].verdict.measure, "rel_rmse");
  EXPECT_GE(outcome.judgements[1].verdict.value, 1.0);  // a black image's rRMSE is √(mean r²)/mean r ≥ 1
}

TEST(Harness, ShrinkingKeepsOneLightAndNothingElse) {
  const MethodInfo info = dark();
  const Harness harness({&info}, 16, 12);
  const Scene shrunk = harness.shrink(scene(), info, "defaults");
  EXPECT_EQ(shrunk.lights.size(), 1u);  // the last light is what keeps the scene visible
  EXPECT_EQ(shrunk.meshes.size(), 0u);
  EXPECT_EQ(shrunk.volumes.size(), 0u);
}

TEST(Harness, ASceneWithoutLightsIsJudgedAndZeroPasses) {
  const MethodInfo info = dark();
  Scene s = scene();
  s.lights.clear();
  const Outcome outcome = Harness({&info}, 16, 12).judge(s);
  ASSERT_TRUE(outcome.visible);
  ASSERT_EQ(outcome.judgements.size(), 2u);
  EXPECT_TRUE(outcome.judgements[1].verdict.pass);
  EXPECT_EQ(outcome.judgements[1].verdict.measure, "zero");
}

TEST(Harness, ATrialWithABaselineIsJudgedAgainstTheBaselinesImage) {
  MethodInfo info = half();
  info.trials = {{"halved", {}, Trial::Measure::worst_pixel, 1e-6, "the same image", {"half_reference", {}}}};
  const Harness harness({&info}, 16, 12);
  // The bracket runs from the baseline (half) to the reference: inside it everywhere.
  const Verdict against_baseline = harness.judge(scene(), info, "halved");
  EXPECT_TRUE(against_baseline.pass) << against_baseline.detail;
  EXPECT_EQ(against_baseline.value, 0.0);
  info.trials[0].baseline = {};
  // Against the reference, half of it is missing: 0.5 but where the bracket of a
  // sharp pixel (judge.hpp) spans a little of the gap.
  const double against_reference = harness.judge(scene(), info, "halved").value;
  EXPECT_GT(against_reference, 0.49);
  EXPECT_LE(against_reference, 0.5 + 1e-6);
  info.trials[0].baseline = {"half_reference", {"scale=2"}};
  const Verdict bad = harness.judge(scene(), info, "halved");
  EXPECT_EQ(bad.measure, "renders");
  EXPECT_NE(bad.detail.find("the baseline half_reference: "), std::string::npos) << bad.detail;
  EXPECT_NE(bad.detail.find("trial halved's baseline"), std::string::npos) << bad.detail;
}

TEST(Harness, AnInvisibleSceneIsRejectedUnjudged) {
  const MethodInfo info = dark();
  Scene s = scene();
  for (Light& l : s.lights) l.intensity *= 1e-6f;
  const Outcome outcome = Harness({&info}, 16, 12).judge(s);
  EXPECT_FALSE(outcome.visible);
  EXPECT_LT(outcome.reference_mean, visible_mean);
  EXPECT_TRUE(outcome.judgements.empty());
}

}  // namespace
}  // namespace airlight::harness
