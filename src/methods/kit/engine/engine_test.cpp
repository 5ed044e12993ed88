// An engine's frame (<airlight/engine.hpp>): the engine's own depth buffer and
// shadow maps — in its conventions, made here on the CPU by Embree rays, so
// that nothing of airlight's own frame is handed back — give the image
// airlight's own frame gives; the targets hold L_air, T(d) and L_surf·T + L_air;
// the caller's GL state comes back as it was; bad targets are refused by name.
#include "geometry/camera.hpp"
#include "gpu/context.hpp"
#include "gpu/gl.hpp"
#include "gpu/program.hpp"
#include "reference/ray_caster.hpp"

#include "core/metrics.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <airlight/engine.hpp>
#include <airlight/error.hpp>
#include <airlight/method.hpp>
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace airlight::kit {
namespace {

constexpr int width = 64, height = 48, shadow_size = 512;

// The engine's camera: airlight's pose and pixel grid, with a reversed-Z,
// infinite-far projection in [0, 1] depth (near → 1, infinity → 0).
struct EngineCamera {
  glm::mat4 view, projection;
};

EngineCamera engine_camera(const Camera& camera) {
  const geometry::CameraBasis b = geometry::camera_basis(camera);
  const float f = static_cast<float>(1.0 / b.tan_half_fov_y), aspect = float(width) / height;
  glm::mat4 p(0.0f);
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[2][3] = -1.0f;
  p[3][2] = camera.near;
  return {glm::lookAt(glm::vec3(b.position), glm::vec3(b.position + b.forward), glm::vec3(b.up)), p};
}

// A single-channel float texture with the caller's parameters (compare mode on,
// as engines set for hardware PCF): airlight must read it as stored anyway.
gpu::Texture depth_texture(GLenum target, int size_x, int size_y, int layers = 1) {
  gpu::Texture t = gpu::make_texture(target, target == GL_TEXTURE_CUBE_MAP ? GL_R32F : GL_DEPTH_COMPONENT32F, size_x,
                                     size_y, layers);
  if (target != GL_TEXTURE_CUBE_MAP) {
    glTextureParameteri(t.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }
  return t;
}

// The engine's depth buffer: window depth of each pixel ray's first hit (0 where none).
gpu::Texture engine_depth(const Scene& scene, const reference::RayCaster& rays, const EngineCamera& cam) {
  std::vector<float> depth(static_cast<size_t>(width) * height, 0.0f);
  for (int y = 0; y < height; ++y)  // GL row y is image row height − 1 − y
    for (int x = 0; x < width; ++x) {
      const optics::Ray ray = geometry::primary_ray(scene.camera, width, height, x + 0.5, height - 1 - y + 0.5);
      const auto hit = rays.intersect(ray, 0.0, geometry::far_distance(scene.camera, ray.dir));
      if (!hit) continue;
      const glm::vec4 clip = cam.projection * cam.view * glm::vec4(glm::vec3(ray.origin + hit->t * ray.dir), 1.0f);
      depth[static_cast<size_t>(y) * width + x] = clip.z / clip.w;
    }
  gpu::Texture t = depth_texture(GL_TEXTURE_2D, width, height);
  glTextureSubImage2D(t.id(), 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  return t;
}

// A 2D shadow map drawn through the engine's own light camera ([−1, 1] depth,
// its own near and far), window depth of the nearest occluder per texel (1: none).
gpu::Texture engine_map(const reference::RayCaster& rays, const EngineShadow& e) {
  const glm::mat4 inverse = glm::inverse(e.projection * e.view);
  std::vector<float> depth(static_cast<size_t>(shadow_size) * shadow_size, 1.0f);
  for (int j = 0; j < shadow_size; ++j)
    for (int i = 0; i < shadow_size; ++i) {
      const glm::vec2 ndc(2.0f * (i + 0.5f) / shadow_size - 1.0f, 2.0f * (j + 0.5f) / shadow_size - 1.0f);
      const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f), b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::dvec3 from(glm::vec3(a) / a.w), to(glm::vec3(b) / b.w);
      const auto hit = rays.intersect({from, glm::normalize(to - from)}, 0.0, glm::length(to - from));
      if (!hit) continue;
      const glm::vec4 clip = e.projection * e.view * glm::vec4(glm::vec3(from + hit->t * glm::normalize(to - from)), 1);
      depth[static_cast<size_t>(j) * shadow_size + i] = 0.5f * clip.z / clip.w + 0.5f;
    }
  gpu::Texture t = depth_texture(GL_TEXTURE_2D, shadow_size, shadow_size);
  glTextureSubImage2D(t.id(), 0, 0, 0, shadow_size, shadow_size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  return t;
}

// A cube map of distances from a point light (GL's face order and orientation).
gpu::Texture engine_cube(const reference::RayCaster& rays, const glm::vec3& light) {
  gpu::Texture t = depth_texture(GL_TEXTURE_CUBE_MAP, shadow_size, shadow_size);
  std::vector<float> distance(static_cast<size_t>(shadow_size) * shadow_size);
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < shadow_size; ++j)
      for (int i = 0; i < shadow_size; ++i) {
        const double s = 2.0 * (i + 0.5) / shadow_size - 1.0, u = 2.0 * (j + 0.5) / shadow_size - 1.0;
        const glm::dvec3 dirs[6] = {{1, -u, -s}, {-1, -u, s}, {s, 1, u}, {s, -1, -u}, {s, -u, 1}, {-s, -u, -1}};
        const auto hit = rays.intersect({glm::dvec3(light), glm::normalize(dirs[face])}, 0.0, 1e4);
        distance[static_cast<size_t>(j) * shadow_size + i] = hit ? static_cast<float>(hit->t) : FLT_MAX;
      }
    glTextureSubImage3D(t.id(), 0, 0, 0, face, shadow_size, shadow_size, 1, GL_RED, GL_FLOAT, distance.data());
  }
  return t;
}

// Each light's map as the engine draws it: a spot through a perspective a bit
// wider than its cone, the sun through an orthographic box, a point light as
// a cube of distances.
struct EngineMaps {
  std::vector<gpu::Texture> textures;
  std::vector<std::optional<EngineShadow>> shadows;
};

EngineMaps engine_maps(const Scene& scene, const reference::RayCaster& rays) {
  EngineMaps maps;
  for (const Light& light : scene.lights) {
    EngineShadow e;
    const glm::vec3 dir = glm::normalize(light.direction);
    const glm::vec3 up = std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    if (light.type == LightType::point) {
      e.kind = EngineShadow::Kind::cube;
      e.stores = EngineShadow::Stores::distance;
      maps.textures.push_back(engine_cube(rays, light.position));
    } else {
      if (light.type == LightType::spot) {
        e.view = glm::lookAt(light.position, light.position + dir, up);
        e.projection = glm::perspective(glm::radians(2.0f * light.cone_deg + 10.0f), 1.0f, 0.05f, 40.0f);
      } else {
        e.view = glm::lookAt(-20.0f * dir, glm::vec3(0.0f), up);
        e.projection = glm::ortho(-14.0f, 14.0f, -14.0f, 14.0f, 1.0f, 60.0f);
      }
      maps.textures.push_back(engine_map(rays, e));
    }
    e.texture = maps.textures.back().id();
    maps.shadows.push_back(e);
  }
  return maps;
}

std::unique_ptr<Method> prepared(const Scene& scene) {
  return test::prepared(find_method("raymarch"), scene, {"steps=64", "sampling=equiangular"});
}

Image read_texture(GLuint texture) {
  std::vector<glm::vec4> texels(static_cast<size_t>(width) * height);
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)),
                    texels.data());
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, height - 1 - y) = glm::vec3(texels[static_cast<size_t>(y) * width + x]);
  return image;
}

// The engine's colour buffer before the frame: its surfaces' radiance.
constexpr float engine_surface[4] = {0.5f, 0.25f, 0.125f, 1.0f};

struct EngineImages {
  Image l_air, t, l;  // L_air, T(d), and the colour buffer after the frame
};

// One frame into the engine's targets — L_air in RGBA32F, T(d) and the colour
// buffer in RGBA16F as engines keep them — with the engine's depth and maps.
EngineImages engine_frame(Method& method, const Scene& scene, const gpu::Texture& depth, const EngineCamera& cam,
                          const std::vector<std::optional<EngineShadow>>& shadows) {
  const gpu::Texture airlight = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
  const gpu::Texture transmittance = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA16F, width, height);
  const gpu::Texture color = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA16F, width, height);
  glClearTexImage(color.id(), 0, GL_RGBA, GL_FLOAT, engine_surface);
  EngineFrame engine;
  engine.depth = EngineDepth{depth.id(), cam.view, cam.projection, DepthRange::zero_to_one};
  engine.shadows = shadows;
  engine.target = {airlight.id(), transmittance.id(), color.id()};
  method.render_frame(frame_inputs(scene, width, height), engine);
  return {read_texture(airlight.id()), read_texture(transmittance.id()), read_texture(color.id())};
}

class Engine : public ::testing::TestWithParam<const char*> {};

TEST_P(Engine, OwnDepthAndShadowMapsGiveAirlightsImage) {
  gpu::Context& context = gpu::Context::headless();
  const Scene scene = builtin_scene(GetParam());
  auto method = prepared(scene);
  const FrameImages own = render(*method, scene, width, height);

  const reference::RayCaster rays(scene);
  const EngineCamera cam = engine_camera(scene.camera);
  const gpu::Texture depth = engine_depth(scene, rays, cam);
  EngineMaps maps = engine_maps(scene, rays);
  const auto [l_air, t, l] = engine_frame(*method, scene, depth, cam, maps.shadows);
  context.check("engine frame");

  // The engine's maps are 512² through other projections than airlight's 1024²
  // ones: pixels whose ray grazes a shadow edge may flip between lit and dark.
  const ImageError e = compare_images(l_air, own.airlight);
  std::printf("%s: engine's depth and maps against airlight's own: rRMSE %.5f, max abs %.4f\n", GetParam(),
              e.rel_rmse, e.max_abs);
  EXPECT_LT(e.rel_rmse, 0.01);
  EXPECT_GT(e.mean_reference, 0.0);

  // T(d) = exp(−σt·d) to the engine's surface, or to the far plane where it has none;
  // L = L_surf·T + L_air. RGBA16F targets: half-float rounding, 2^-11 relative.
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const optics::Ray ray = geometry::primary_ray(scene.camera, width, height, i + 0.5, j + 0.5);
      const double far = geometry::far_distance(scene.camera, ray.dir);
      const auto hit = rays.intersect(ray, 0.0, far);
      for (int c = 0; c < 3; ++c) {
        const double expected_t = std::exp(-scene.medium.sigma_t()[c] * (hit ? hit->t : far));
        ASSERT_NEAR(t.at(i, j)[c], expected_t, 2e-3 * expected_t + 1e-6) << i << "," << j;
        const double expected_l = engine_surface[c] * t.at(i, j)[c] + l_air.at(i, j)[c];
        ASSERT_NEAR(l.at(i, j)[c], expected_l, 2e-3 * expected_l + 1e-6) << i << "," << j;
      }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, Engine, ::testing::Values("teapot_spot", "three_lights"));

// A scene without lights in an engine's frame: no shadow map to give, L_air = 0,
// and the composite the engine's surface seen through the fog, L_surf·T(d).
TEST(EngineState, SceneWithoutLightsGivesZeroAirlight) {
  // Before the process's context exists: every program compiles here, where the
  // defects of a scene without lights showed (docs/decisions.md "No lights").
  ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  gpu::Context& context = gpu::Context::headless();
  Scene scene = builtin_scene("teapot_spot");
  scene.lights.clear();
  auto method = prepared(scene);
  const reference::RayCaster rays(scene);
  const EngineCamera cam = engine_camera(scene.camera);
  const gpu::Texture depth = engine_depth(scene, rays, cam);
  const auto [l_air, t, l] = engine_frame(*method, scene, depth, cam, {});
  context.check("engine frame without lights");
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(l_air.at(i, j)[c], 0.0f) << i << "," << j;
        ASSERT_GT(t.at(i, j)[c], 0.0f) << i << "," << j;
        // RGBA16F targets: half-float rounding, 2^-11 relative.
        const double expected_l = engine_surface[c] * t.at(i, j)[c];
        ASSERT_NEAR(l.at(i, j)[c], expected_l, 2e-3 * expected_l + 1e-6) << i << "," << j;
      }
}

// What the caller had bound and enabled is bound and enabled again afterwards.
TEST(EngineState, CallersStateIsRestored) {
  gpu::Context& context = gpu::Context::headless();
  const Scene scene = builtin_scene("teapot_spot");
  auto method = prepared(scene);
  const gpu::Texture color = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA16F, width, height);
  const gpu::Framebuffer fbo = gpu::make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
  const gpu::VertexArray vao = gpu::make_vertex_array();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glBindVertexArray(vao.id());
  glViewport(1, 2, 30, 20);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_CULL_FACE);
  glActiveTexture(GL_TEXTURE3);

  EngineFrame engine;
  engine.target.color = color.id();
  method->render_frame(frame_inputs(scene, width, height), engine);

  GLint value = 0, viewport[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &value);
  EXPECT_EQ(GLuint(value), fbo.id());
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &value);
  EXPECT_EQ(GLuint(value), vao.id());
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[0] + viewport[1] + viewport[2] + viewport[3], 1 + 2 + 30 + 20);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &value);
  EXPECT_EQ(value, GL_ZERO_TO_ONE);
  glGetIntegerv(GL_DEPTH_FUNC, &value);
  EXPECT_EQ(value, GL_GREATER);
  GLboolean mask = GL_TRUE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
  EXPECT_EQ(mask, GL_FALSE);
  EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
  glGetIntegerv(GL_BLEND_SRC_RGB, &value);
  EXPECT_EQ(value, GL_SRC_ALPHA);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
  EXPECT_EQ(value, GL_TEXTURE3);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);  // leave the context as the other tests expect it
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glActiveTexture(GL_TEXTURE0);
  context.check("engine state");
}

TEST(EngineState, BadTargetsAndShadowMapsAreRefusedByName) {
  gpu::Context::headless();
  const Scene scene = builtin_scene("teapot_spot");
  auto method = prepared(scene);
  const gpu::Texture bytes = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA8, width, height);
  const gpu::Texture small = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width / 2, height);
  EngineFrame engine;
  engine.target.airlight = bytes.id();
  try {
    method->render_frame(frame_inputs(scene, width, height), engine);
    ADD_FAILURE() << "an RGBA8 target was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "EngineTarget: airlight: must be an RGBA32F or RGBA16F texture");
  }
  engine.target.airlight = 0;
  engine.target.transmittance = small.id();
  try {
    method->render_frame(frame_inputs(scene, width, height), engine);
    ADD_FAILURE() << "a target of another size was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "EngineTarget: transmittance: is 32x48, the frame is 64x48");
  }
  engine.target.transmittance = 0;
  FrameInputs sun = frame_inputs(scene, width, height);
  sun.lights[0].type = LightType::directional;  // a light may change type between frames
  EngineShadow cube;
  cube.kind = EngineShadow::Kind::cube;
  engine.shadows = {cube};
  try {
    method->render_frame(sun, engine);
    ADD_FAILURE() << "a cube map for a directional light was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "EngineFrame: shadows[0]: is a cube map, but light 0 is directional (it needs a 2D map)");
  }
}

// A caller with no shading of its own (the viewer) takes airlight's L_air and
// L_surf·T(d) into its textures: the same images read_back gives, bit for bit
// (both are copies of the same RGBA32F textures), and the same pass list.
TEST(EngineState, SurfaceTargetAndNumbersMatchReadBack) {
  gpu::Context& context = gpu::Context::headless();
  const Scene scene = builtin_scene("teapot_spot");
  auto method = prepared(scene);
  const FrameImages own = render(*method, scene, width, height);
  const gpu::Texture airlight = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
  const gpu::Texture surface = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
  EngineFrame engine;
  engine.target.airlight = airlight.id();
  engine.target.surface = surface.id();
  method->render_frame(frame_inputs(scene, width, height), engine);
  const FrameNumbers numbers = method->numbers();
  EXPECT_EQ(compare_images(read_texture(airlight.id()), own.airlight).max_abs, 0.0);
  EXPECT_EQ(compare_images(read_texture(surface.id()), own.surface).max_abs, 0.0);
  EXPECT_GT(compare_images(Image(width, height), own.surface).mean_reference, 0.0);  // the surface was shaded
  std::vector<std::string> passes;
  for (const PassTime& t : numbers.times) passes.push_back(t.pass);
  EXPECT_EQ(passes, (std::vector<std::string>{"gbuffer", "shadow", "surface", "airlight", "engine"}));
  context.check("surface target");
}

TEST(EngineState, SurfaceTargetNeedsAirlightsOwnGbuffer) {
  gpu::Context::headless();
  const Scene scene = builtin_scene("teapot_spot");
  auto method = prepared(scene);
  const gpu::Texture surface = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
  EngineFrame engine;
  engine.target.surface = surface.id();
  FrameInputs inputs = frame_inputs(scene, width, height);
  inputs.surface = false;
  try {
    method->render_frame(inputs, engine);
    ADD_FAILURE() << "a surface target without FrameInputs::surface was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "EngineTarget: surface: needs FrameInputs::surface and no EngineFrame::depth");
  }
}

TEST(EngineState, CpuReferenceCannotRenderIntoAnEnginesFrame) {
  const Scene scene = builtin_scene("teapot_spot");
  const MethodInfo& info = find_method("reference");
  auto method = info.create(Settings(info.settings));
  method->prepare(scene);
  EXPECT_THROW(method->render_frame(frame_inputs(scene, width, height), EngineFrame{}), Failure);
}

}  // namespace
}  // namespace airlight::kit
