// The million-triangle scene at a tenth of its size (issue 26): 10⁵ separate
// caster triangles written as an OBJ (harness/sieve_scene), loaded and
// rendered by the reference (Embree over them) and raymarch (a shadow map of
// them) through `airlight compare`. shadow_planes, whose planes grow with the
// triangles, would add 3–4 s of CPU at any size; scripts/million-triangles
// runs every method at 10⁶ (docs/decisions.md "A million triangles").
#include "app/command_test_support.hpp"
#include "harness/sieve_scene.hpp"

#include <fstream>
#include <string>

namespace airlight {
namespace {

using namespace test;

long faces(const fs::path& obj) {
  std::ifstream in(obj);
  long count = 0;
  for (std::string line; std::getline(in, line);) count += line.rfind("f ", 0) == 0;
  return count;
}

// Both images finite (compare fails on a non-finite value), the reference lit,
// and raymarch at its defaults within rRMSE 0.05 of it: 0.017 measured, the
// rest left for its shadow map's texels along the tiles' edges, which move
// with the rasterizer's rounding.
TEST(MillionTriangles, AHundredThousandRenderLikeTheReference) {
  const fs::path scene = harness::write_sieve_scene(work_dir(), 100000), csv = work_dir() / "sieve.csv";
  EXPECT_EQ(faces(work_dir() / "sieve.obj"), 100000);
  const Outcome o = run_airlight("compare --scene " + scene.string() + " --methods raymarch --size 64x48 "
                                 "--out " + (work_dir() / "sieve.png").string() + " --csv " + csv.string() +
                                 " --cache " + (work_dir() / "cache").string());
  ASSERT_EQ(o.status, 0) << o.err;
  const Table table = read_csv(csv);
  ASSERT_EQ(table.size(), 3u);
  EXPECT_GT(std::stod(table[1][column(table, "mean_radiance")]), 0.01) << "the reference is black";
  EXPECT_LT(std::stod(table[2][column(table, "rel_rmse")]), 0.05);
}

}  // namespace
}  // namespace airlight
