// A scene without lights is valid (docs/scene-format.md), and it is what every
// glTF model without KHR_lights_punctual loads as: every method renders it, its
// L_air zero and its image the surface term alone. Mesa's shader cache is off in
// the command's environment, so every program compiles here: the defects this
// holds (a GLSL array of size 0, a texture of 0 layers, a compiler warning that
// the GL debug output reports) showed only on a cold cache (docs/decisions.md
// "No lights").
#include "app/command_test_support.hpp"
#include "core/image_io.hpp"

#include <cmath>

namespace airlight {
namespace {

using namespace test;

// Casters of each kind the methods build geometry from (closed boxes, a sphere,
// an open plane), in a medium with a bounded volume: only the lights are missing.
const std::string scene = R"({"format": "airlight-scene/1",
  "camera": {"position": [0, 1.5, 6], "look_at": [0, 1, 0], "fov_y_deg": 50, "near": 0.05, "far": 30},
  "medium": {"scattering": 0.05, "absorption": 0.01, "phase": {"type": "henyey_greenstein", "g": 0.4}},
  "volumes": [{"shape": "box", "min": [-1, 0, -1], "max": [1, 2, 1], "scattering": 0.2}],
  "ambient": 0.2,
  "lights": [],
  "objects": [
    {"shape": "box", "min": [-6, -0.1, -6], "max": [6, 0, 6], "albedo": 0.5},
    {"shape": "sphere", "center": [1.5, 1, 0], "radius": 0.6},
    {"shape": "plane", "center": [-1.5, 1, -1], "size": [1, 1], "normal": [0, 0, 1]}]})";

struct Check {
  bool finite = true;
  double largest = 0.0;
};

Check check(const Image& image) {
  Check c;
  for (const auto& p : image.pixels)
    for (const float v : {p.r, p.g, p.b}) {
      c.finite = c.finite && std::isfinite(v);
      c.largest = std::max(c.largest, std::fabs(double(v)));
    }
  return c;
}

TEST(NoLights, EveryMethodRendersZeroAirlightAndTheSurfaceAlone) {
  const fs::path file = write_file("no_lights.json", scene);
  const auto methods = listed_methods();
  ASSERT_GE(methods.size(), 11u);
  for (const std::string& m : methods) {
    const fs::path airlight = work_dir() / (m + "_airlight.pfm"), composite = work_dir() / (m + "_composite.pfm");
    const std::string common = "render --scene " + file.string() + " --method " + m + " --size 32x24";
    const Outcome a = run_airlight(common + " --pass airlight --out " + airlight.string(),
                                   "MESA_SHADER_CACHE_DISABLE=true");
    EXPECT_EQ(a.status, 0) << m << ": " << a.err;
    if (a.status != 0) continue;
    const Check air = check(read_image(airlight));
    EXPECT_TRUE(air.finite) << m;
    EXPECT_EQ(air.largest, 0.0) << m << ": no light, no airlight";
    const Outcome c = run_airlight(common + " --pass composite --out " + composite.string());
    EXPECT_EQ(c.status, 0) << m << ": " << c.err;
    if (c.status != 0) continue;
    const Check lit = check(read_image(composite));
    EXPECT_TRUE(lit.finite) << m;
    EXPECT_GT(lit.largest, 0.0) << m << ": the ambient term lights the surfaces";
  }
}

}  // namespace
}  // namespace airlight
