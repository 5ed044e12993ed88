// planes (Dobashi 2000) against the reference: convergence in the number of
// planes (Fig. 5), the lattice (Fig. 6), float accumulation, clipping to the
// light's influence volume, jitter, and a scene with every feature.
#include "core/metrics.hpp"
#include "methods/kit/testing/test_support.hpp"
#include "reference/reference.hpp"

#include <airlight/scene.hpp>
#include <gtest/gtest.h>

namespace airlight::methods {
namespace {

using namespace kit::test;

constexpr int width = 128, height = 96;

double error_of(const Scene& scene, const std::vector<std::string>& settings) {
  const FrameImages f = render(find_method("planes"), scene, settings, width, height);
  EXPECT_TRUE(kit::test::all_finite_and_non_negative(f.airlight));
  return compare_images(f.airlight, kit::test::reference_airlight(scene, width, height)).rel_rmse;
}

const Scene& teapot_spot() {
  static const Scene scene = builtin_scene("teapot_spot");
  return scene;
}

// The fraction of pixels that one image shows lit (luminance above `level`)
// and the other dark.
double pattern_mismatch(const Image& a, const Image& b, float level) {
  auto lit = [level](const glm::vec3& p) { return p.r + p.g + p.b > 3.0f * level; };
  int differ = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) differ += lit(a.pixels[i]) != lit(b.pixels[i]);
  return double(differ) / double(a.pixels.size());
}

// Dobashi Fig. 5: 15, 30 and 75 planes sampled as his (one sample per plane
// at its slab's middle); the banding of the shaft and its shadow falls with n.
TEST(Planes, ErrorFallsAsPlanesGrow) {
  double previous = 1e30;
  for (int n : {15, 30, 75}) {
    const double e = error_of(teapot_spot(), {"planes=" + std::to_string(n), "sampling=plane"});
    std::printf("teapot_spot, %d planes, sampling=plane: rRMSE %.4f\n", n, e);
    EXPECT_LT(e, previous) << n << " planes";
    previous = e;
  }
}

// Sampling each slab's lit piece (the cone's part of it, evenly in the angle
// from the spot) with 15 planes beats Dobashi's sampling with 75: the shaft's
// edges and the apex no longer fall between planes.
TEST(Planes, LitSamplingBeatsPlaneSampling) {
  const double lit = error_of(teapot_spot(), {"planes=15", "sampling=lit"});
  const double plane = error_of(teapot_spot(), {"planes=75", "sampling=plane"});
  std::printf("teapot_spot: rRMSE %.4f with 15 planes sampling=lit, %.4f with 75 sampling=plane\n", lit, plane);
  EXPECT_LT(lit, 0.1 * plane);
  // What is left is the 1024² shadow map's texels along the teapot's shadow
  // edges, as for raymarch at N = 256 equiangular (quality_test).
  EXPECT_LT(lit, 0.005);
}

// Float blending has no quantization floor (Dobashi §7 worried about 8-bit
// frame buffers): 500 planes beat 100.
TEST(Planes, FloatAccumulationKeepsConverging) {
  const double e100 = error_of(teapot_spot(), {"planes=100", "sampling=plane"});
  const double e500 = error_of(teapot_spot(), {"planes=500", "sampling=plane"});
  std::printf("teapot_spot: rRMSE %.5f at 100 planes, %.5f at 500\n", e100, e500);
  EXPECT_LT(e500, e100);
}

// Dobashi Fig. 6: ξ on 5×5, 20×20 and 80×80 lattices against ξ per fragment,
// at 75 planes sampled as his. A coarse lattice misses the 1/r² peak near the light.
TEST(Planes, LatticeErrorFallsWithItsResolution) {
  const Image exact = render(find_method("planes"), teapot_spot(), {"planes=75", "sampling=plane"}, width, height).airlight;
  double previous = 1e30;
  for (int n : {5, 20, 80}) {
    const Image lattice =
        render(find_method("planes"), teapot_spot(), {"planes=75", "sampling=plane", "lattice=" + std::to_string(n)}, width,
               height)
            .airlight;
    const double e = compare_images(lattice, exact).rel_rmse;
    std::printf("teapot_spot, 75 planes, %dx%d lattice vs per fragment: rRMSE %.4f\n", n, n, e);
    EXPECT_LT(e, previous) << n << "x" << n;
    previous = e;
  }
  // Cells of 1.6×1.2 pixels at 128×96: only ξ's 1/r² peak beside the spot's
  // apex, which is in view, curves within a cell (Dobashi Fig. 6's "differences
  // around the light source").
  EXPECT_LT(previous, 0.005);
}

// Clipping to the spot's pyramid only skips fragments the light cannot reach.
TEST(Planes, ClippingSkipsOnlyUnlitFragments) {
  const FrameImages clipped = render(find_method("planes"), teapot_spot(), {"planes=30"}, width, height);
  const FrameImages unclipped = render(find_method("planes"), teapot_spot(), {"planes=30", "clip=false"}, width, height);
  const ImageError diff = compare_images(clipped.airlight, unclipped.airlight);
  EXPECT_LT(diff.max_abs, 1e-6 * diff.mean_reference);  // identical up to the order of float additions
  auto stat = [](const FrameImages& f, const std::string& name) {
    for (const auto& [key, value] : f.stats)
      if (key == name) return value;
    return -1.0;
  };
  std::printf("fragments: %.0f clipped, %.0f unclipped\n", stat(clipped, "fragments"), stat(unclipped, "fragments"));
  if (stat(clipped, "fragments") < 0) GTEST_SKIP() << "no GL_ARB_pipeline_statistics_query to count fragments";
  // The 25° cone's pyramid covers about a third of the view's slabs.
  EXPECT_LT(stat(clipped, "fragments"), 0.5 * stat(unclipped, "fragments"));
}

// The mean of a 4×4 block of pixels: what the eye sees of fine noise.
Image block_mean(const Image& image) {
  Image out(image.width / 4, image.height / 4);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      glm::vec3 sum(0.0f);
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) sum += image.at(4 * x + i, 4 * y + j);
      out.at(x, y) = sum / 16.0f;
    }
  return out;
}

// Jitter (Dobashi §7) trades the planes' banding for noise: per pixel the
// error is similar, but it no longer survives averaging over 4×4 pixels.
TEST(Planes, JitterTurnsBandingIntoNoise) {
  const Image& reference = kit::test::reference_airlight(teapot_spot(), width, height);
  auto blurred_error = [&](const std::string& jitter) {
    const Image a =
        render(find_method("planes"), teapot_spot(), {"planes=15", "sampling=plane", "jitter=" + jitter}, width, height)
            .airlight;
    return compare_images(block_mean(a), block_mean(reference)).rel_rmse;
  };
  const double banded = blurred_error("none"), jittered = blurred_error("blue");
  std::printf("15 planes, 4x4 block means: rRMSE %.4f without jitter, %.4f with blue-noise jitter\n", banded, jittered);
  EXPECT_LT(jittered, 0.8 * banded);
}

// Spot, point and directional lights, a two-lobe phase function and a box
// volume of its own (march_test_support.hpp).
TEST(Planes, EveryFeatureMatchesReference) {
  const double e = error_of(kit::test::every_feature_scene(), {"planes=200"});
  std::printf("every_feature, 200 planes: rRMSE %.4f\n", e);
  // Midpoint slabs through the volume's faces and the shadows' edges; the
  // 1024² shadow maps' texels.
  EXPECT_LT(e, 0.01);
}

// The eye inside a spot's cone, the light behind it: every pixel's first
// slab starts at the eye, its geometry just past the near plane.
TEST(Planes, CameraInsideTheCone) {
  Scene s = kit::test::every_feature_scene();
  s.name = "inside_cone";
  s.lights = {kit::test::make_light(LightType::spot, {0.0f, 3.5f, 10.0f}, {0.0f, -0.15f, -1.0f}, 300.0f, 30.0f)};
  const double e = error_of(s, {"planes=200"});
  std::printf("camera inside the cone, 200 planes: rRMSE %.4f\n", e);
  // Midpoint slabs across the shadows' edges and the volume's faces.
  EXPECT_LT(e, 0.05);
}

// The polka dots the gobos of `stage` throw on its floor, through the shared
// frame's surface pass (the same in every GPU method), against the reference's.
TEST(Planes, StageGoboPatternMatchesReferenceSurface) {
  const Scene stage = builtin_scene("stage");
  const Image surface = render(find_method("planes"), stage, {"planes=30"}, width, height).surface;
  const Image reference = reference::render(stage, width, height).surface;
  const ImageError e = compare_images(surface, reference);
  const double mismatch = pattern_mismatch(surface, reference, 0.5f * e.mean_reference);
  std::printf("stage surface: rRMSE %.3g, max abs %.3g, dot pattern mismatch %.3g of the pixels\n", e.rel_rmse,
              e.max_abs, mismatch);
  // The same formulas in float against double; a pixel whose
  // shadow test flipped at a prop's shadow edge (1024² map) would exceed it.
  EXPECT_LT(e.rel_rmse, 1e-3);
  EXPECT_LT(mismatch, 0.002);  // ≤ 24 of 12288 pixels on the wrong side of a dot's edge
}

// What a frame rebuilds (docs/design.md §3): each light's lit region is traced
// again only when that light moved, and every light's when an object moved.
TEST(Planes, RebuildsOnlyTheLitRegionsAFrameMoves) {
  const Scene scene = builtin_scene("three_lights");
  auto method = prepared(find_method("planes"), scene, {"planes=15"});
  const auto rebuilt = [&](const FrameInputs& inputs) {
    method->render_frame(inputs);
    for (const auto& [name, value] : method->read_back().stats)
      if (name == "rebuilt_lights") return static_cast<int>(value);
    ADD_FAILURE() << "no rebuilt_lights counter";
    return -1;
  };
  FrameInputs inputs = frame_inputs(scene, 32, 24);
  EXPECT_EQ(rebuilt(inputs), 3);  // the first frame traces every light
  inputs.camera.position.x += 0.5f;
  inputs.lights[2].irradiance *= 2.0f;
  EXPECT_EQ(rebuilt(inputs), 0);  // the camera and a colour change no lit region
  inputs.lights[1].position.y += 0.3f;
  EXPECT_EQ(rebuilt(inputs), 1);
  inputs.transforms.assign(scene.meshes.size(), glm::mat4(1.0f));
  inputs.transforms[0][3] = glm::vec4(0.0f, 0.1f, 0.0f, 1.0f);
  EXPECT_EQ(rebuilt(inputs), 3);  // an object moved: every light's rays meet it anew
}

}  // namespace
}  // namespace airlight::methods
