// Each method's MethodInfo::memory against what its frame allocates on the GPU
// (gpu::allocated_bytes, every buffer and texture the project makes): the
// estimate a command checks before any GL must not fall short of it. On
// three_lights (a 2D map, a cube and a directional map) with the settings that
// size buffers raised above their defaults.
#include "gpu/gl.hpp"
#include "methods/kit/counting/lit_interval_pass.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace airlight::kit::test {
namespace {

constexpr int width = 64, height = 48;

std::vector<std::string> gpu_method_names() {
  std::vector<std::string> names;
  for (const MethodInfo& info : registered_methods())
    if (info.name != "reference") names.push_back(info.name);
  return names;
}

// The raised settings the method has.
std::vector<std::string> raised(const MethodInfo& info) {
  std::vector<std::string> assignments;
  for (const std::string a : {"shadow_resolution=2048", "volume_resolution=384", "capacity=64", "planes=400"})
    for (const SettingSpec& s : info.settings)
      if (a.rfind(s.name + "=", 0) == 0) assignments.push_back(a);
  return assignments;
}

class MemoryEstimate : public ::testing::TestWithParam<std::string> {};

TEST_P(MemoryEstimate, CoversWhatTheFrameAllocates) {
  const MethodInfo& info = find_method(GetParam());
  const Scene scene = builtin_scene("three_lights");
  Settings settings(info.settings);
  for (const std::string& a : raised(info)) settings.set(a, "test");
  double estimate = double(width) * height * info.bytes_per_pixel;
  std::vector<MemoryNeed> needs = info.memory(scene, settings, width, height);
  for (const MemoryNeed& need : needs) estimate += need.bytes;
  const double before = static_cast<double>(gpu::allocated_bytes());
  auto method = prepared(info, scene, raised(info));
  const FrameImages frame = airlight::render(*method, scene, width, height);
  const double allocated = static_cast<double>(gpu::allocated_bytes()) - before;
  std::printf("%s: allocated %.1f MiB, estimated %.1f MiB\n", info.name.c_str(), allocated / 1048576.0,
              estimate / 1048576.0);
  EXPECT_LE(allocated, estimate);
  EXPECT_GT(allocated, 0.25 * estimate);  // the shadow maps alone, 2048² for 8 faces and a depth target, are most of it
  // The light volume mesh's buffer is exactly the triangles the frame built.
  for (const MemoryNeed& need : needs) {
    if (need.setting == "volume_resolution") {
      EXPECT_EQ(need.largest_buffer, stat(frame, "volume_triangles") * sizeof(CountedTriangle)) << need.what;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Registered, MemoryEstimate, ::testing::ValuesIn(gpu_method_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace airlight::kit::test
