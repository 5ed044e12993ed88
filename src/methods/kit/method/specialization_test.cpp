// Programs specialized to the scene (docs/design.md §2): a frame that moves
// lights and the camera or changes colours and the medium compiles nothing; a
// frame that changes the scene's structure (a light's type) compiles its
// variant once, and returning to a known structure compiles nothing again.
#include "gpu/program.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <airlight/method.hpp>
#include <gtest/gtest.h>

namespace airlight::kit {
namespace {

TEST(Specialization, MovingLightsRecompilesNothingChangingTheirTypeOnce) {
  const Scene scene = builtin_scene("three_lights");
  for (const char* method : {"raymarch", "planes", "analytic"}) {
    auto m = test::prepared(find_method(method), scene, {});
    FrameInputs inputs = frame_inputs(scene, 32, 24);
    m->render_frame(inputs);
    const int compiled = gpu::cached_program_count();

    inputs.camera.position.x += 0.3f;
    for (Light& light : inputs.lights) {
      light.position += glm::vec3(0.2f, -0.1f, 0.3f);
      light.intensity *= 1.5f;
      light.irradiance *= 0.5f;
    }
    inputs.medium.sigma_s *= 2.0f;
    m->render_frame(inputs);
    EXPECT_EQ(gpu::cached_program_count(), compiled) << method << ": moving lights compiled a program";

    FrameInputs spot = inputs;
    spot.lights[0].type = spot.lights[0].type == LightType::spot ? LightType::point : LightType::spot;
    m->render_frame(spot);
    const int with_variant = gpu::cached_program_count();
    EXPECT_GT(with_variant, compiled) << method << ": a light's type is structure";
    m->render_frame(inputs);
    m->render_frame(spot);
    EXPECT_EQ(gpu::cached_program_count(), with_variant) << method << ": a known structure compiled again";
  }
}

}  // namespace
}  // namespace airlight::kit
