// The harness with a method made to fail: it is judged failing, and shrinking
// drops every light, mesh and volume the failure does not need while the scene
// stays visible.
#include "harness/run.hpp"

#include <gtest/gtest.h>

namespace airlight::harness {
namespace {

// Airlight zero everywhere: fails every visible scene, passes one without lights.
class Dark final : public Method {
public:
  void prepare(const Scene&) override {}
  void render_frame(const FrameInputs& in) override { size_ = {in.width, in.height}; }
  FrameImages read_back() override { return {Image(size_.x, size_.y), Image(size_.x, size_.y), {}, 0.0, {}}; }

private:
  glm::ivec2 size_{0};
};

MethodInfo dark() {
  MethodInfo info;
  info.name = "dark";
  info.create = [](const Settings&) { return std::make_unique<Dark>(); };
  return info;
}

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
