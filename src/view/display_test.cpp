// display.frag.glsl is the GLSL twin of core/tonemap.cpp: the viewer shows
// what `airlight render` writes to a PNG.
#include "view/display.hpp"

#include "core/tonemap.hpp"
#include "gpu/context.hpp"

#include <gtest/gtest.h>
#include <ostream>
#include <vector>

namespace airlight {
// ctest names the case by its curve, not by the enum's bytes.
void PrintTo(ToneCurve curve, std::ostream* out) { *out << tone_curve_name(curve); }
}  // namespace airlight

namespace airlight::view {
namespace {

// Radiances across every curve's range: black, the toe, mid grey, lamp cores,
// far beyond every curve's shoulder, and one NaN channel.
std::vector<glm::vec3> radiances() {
  std::vector<glm::vec3> v{{0, 0, 0}, {1e-6f, 2e-5f, 3e-4f}, {0.18f, 0.18f, 0.18f}, {0.5f, 0.1f, 0.02f},
                           {3.0f, 7.0f, 1.0f}, {40.0f, 1e3f, 1e7f}, {NAN, 0.3f, 0.2f}};
  for (float x = 1e-4f; x < 1e4f; x *= 1.7f) v.push_back({x, 0.6f * x, 0.2f * x});
  return v;
}

gpu::Texture texture_of(const std::vector<glm::vec3>& pixels) {
  gpu::Texture t = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, static_cast<int>(pixels.size()), 1);
  std::vector<glm::vec4> rgba;
  for (const glm::vec3& p : pixels) rgba.emplace_back(p, 1.0f);
  glTextureSubImage2D(t.id(), 0, 0, 0, static_cast<int>(pixels.size()), 1, GL_RGBA, GL_FLOAT, rgba.data());
  return t;
}

class DisplayTwin : public ::testing::TestWithParam<ToneCurve> {};

// The GPU's log2, pow and float rounding differ from libm's by a few ulp;
// through the curves' slopes that stays under 2e-4 in sRGB, a twentieth of
// one 8-bit step.
TEST_P(DisplayTwin, ShaderMatchesTheCppCurve) {
  gpu::Context& context = gpu::Context::headless();
  const std::vector<glm::vec3> in = radiances();
  const int n = static_cast<int>(in.size());
  const gpu::Texture radiance = texture_of(in), zero = texture_of(std::vector<glm::vec3>(in.size()));
  const gpu::Texture out = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, n, 1);
  const gpu::Framebuffer fbo = gpu::make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, out.id(), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  const ToneMap tone{1.7f, GetParam()};
  const Display display;
  display.draw(radiance.id(), zero.id(), 0, 0, n, 1, Pass::composite, tone);
  std::vector<glm::vec4> shown(in.size());
  glGetTextureImage(out.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(shown.size() * sizeof(glm::vec4)),
                    shown.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  context.check("display twin");
  for (int i = 0; i < n; ++i) {
    const glm::vec3 expected = tone_map(in[i], tone);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(shown[i][c], expected[c], 2e-4f) << "radiance " << in[i][0] << " " << in[i][1] << " " << in[i][2];
  }
}

INSTANTIATE_TEST_SUITE_P(Curves, DisplayTwin, ::testing::Values(ToneCurve::agx, ToneCurve::aces, ToneCurve::clamp),
                         [](const auto& info) { return std::string(tone_curve_name(info.param)); });

}  // namespace
}  // namespace airlight::view
