// check_frame_inputs (<airlight/method.hpp>): every value the scene loader checks
// is checked again per frame, where an engine or the viewer sets it, and refused
// by name ("frame: <key>: ...") before any GL work.
#include <airlight/error.hpp>
#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>

namespace airlight {
namespace {

struct BadFrame {
  const char* name;
  std::function<void(FrameInputs&)> change;
  const char* message;
};

void PrintTo(const BadFrame& c, std::ostream* out) { *out << c.name; }

const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();

// teapot_spot's light made a directional beam, which every beam check needs.
void beam(FrameInputs& in) {
  in.lights[0].type = LightType::directional;
  in.lights[0].direction = {0, -1, 0};
  in.lights[0].irradiance = Color(1.0f);
  in.lights[0].gobo_up = {0, 0, 1};
  in.lights[0].beam = Beam{{0, 5, 0}, {2, 1}, 6};
}

const BadFrame cases[] = {
    {"Size", [](FrameInputs& in) { in.width = 0; }, "frame: size: must be 1 to 16384 pixels per side, got 0x96"},
    {"Transforms", [](FrameInputs& in) { in.transforms.resize(1); },
     "frame: transforms: needs one per mesh (3), got 1"},
    {"PhaseG", [](FrameInputs& in) { in.medium.phase.lobes[0].g = nan; },
     "frame: medium.phase.lobes[0].g: must be in (-1, 1), got nan"},
    {"PhaseGOne", [](FrameInputs& in) { in.medium.phase.lobes[0].g = 1.0f; },
     "frame: medium.phase.lobes[0].g: must be in (-1, 1), got 1"},
    {"PhaseWeight", [](FrameInputs& in) { in.medium.phase.lobes[0].weight = -0.5f; },
     "frame: medium.phase.lobes[0].weight: must be in [0, 1], got -0.5"},
    {"PhaseWeightsSum", [](FrameInputs& in) { in.medium.phase.lobes = {{PhaseType::isotropic, 0.0f, 0.5f}}; },
     "frame: medium.phase.lobes: the weights must sum to 1, not 0.5"},
    {"NoLobes", [](FrameInputs& in) { in.medium.phase.lobes.clear(); },
     "frame: medium.phase.lobes: the weights must sum to 1, not 0"},
    {"LightModelA0", [](FrameInputs& in) { in.light_model.a0 = -1.0f; },
     "frame: light_model.a0: must be finite and >= 0, got -1"},
    {"LightModelA1", [](FrameInputs& in) { in.light_model.a1 = inf; },
     "frame: light_model.a1: must be finite and >= 0, got inf"},
    {"GoboUpZero", [](FrameInputs& in) { in.lights[0].gobo_up = glm::vec3(0.0f); },
     "frame: lights[0].gobo_up: must be finite and not zero"},
    {"GoboUpParallel",
     [](FrameInputs& in) {
       beam(in);
       in.lights[0].gobo_up = {0, 2, 0};
     },
     "frame: lights[0].gobo_up: must not be parallel to direction"},
    {"BeamOrigin",
     [](FrameInputs& in) {
       beam(in);
       in.lights[0].beam->origin.x = nan;
     },
     "frame: lights[0].beam.origin: must be finite"},
    {"BeamSize",
     [](FrameInputs& in) {
       beam(in);
       in.lights[0].beam->size = {0, 1};
     },
     "frame: lights[0].beam.size: must be finite and > 0, got [0, 1]"},
    {"BeamLength",
     [](FrameInputs& in) {
       beam(in);
       in.lights[0].beam->length = nan;
     },
     "frame: lights[0].beam.length: must be finite and > 0, got nan"},
    {"Near", [](FrameInputs& in) { in.camera.near = 0.0f; }, "frame: camera.near: must be finite and > 0, got 0"},
    {"FarBelowNear", [](FrameInputs& in) { in.camera.far = 0.01f; },
     "frame: camera.far: must be finite and greater than near (0.05), got 0.01"},
    {"DepthRange",
     [](FrameInputs& in) {
       in.camera.near = 1e-4f;
       in.camera.far = 200.0f;
     },
     "frame: camera.far: far/near = 2e+06 is above the 100000 airlight supports (depth precision)"},
    {"Cone", [](FrameInputs& in) { in.lights[0].cone_deg = 200.0f; },
     "frame: lights[0].cone_deg: must be in (0, 180], got 200.000000"},
};

class Contract : public ::testing::TestWithParam<BadFrame> {};

TEST_P(Contract, RefusesTheFrameNamingTheKey) {
  const Scene scene = builtin_scene("teapot_spot");
  FrameInputs in = frame_inputs(scene, 128, 96);
  EXPECT_NO_THROW(check_frame_inputs(scene, in));
  GetParam().change(in);
  try {
    check_frame_inputs(scene, in);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), GetParam().message);
  }
}

INSTANTIATE_TEST_SUITE_P(Inputs, Contract, ::testing::ValuesIn(cases),
                         [](const auto& info) { return std::string(info.param.name); });

// A phase lobe's g, a gobo_up, a beam and far/near at their valid extremes pass.
TEST(Contract, AcceptsTheLoadersValidValues) {
  const Scene scene = builtin_scene("teapot_spot");
  FrameInputs in = frame_inputs(scene, 128, 96);
  in.medium.phase.lobes = {{PhaseType::henyey_greenstein, 0.95f, 0.25f}, {PhaseType::isotropic, 0.0f, 0.75f}};
  in.light_model = {LightModelType::simplified, 0.0f, 0.0f};
  in.camera.near = 0.5f;
  in.camera.far = 50000.0f;  // far/near exactly max_far_over_near
  beam(in);
  EXPECT_NO_THROW(check_frame_inputs(scene, in));
  in.lights[0].beam.reset();
  in.lights[0].gobo_up = in.lights[0].direction;  // no gobo, no beam: gobo_up orients nothing
  EXPECT_NO_THROW(check_frame_inputs(scene, in));
}

}  // namespace
}  // namespace airlight
