// planes's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // planes (Dobashi 2000), 100 planes per light. sampling=plane is Dobashi's one
  // sample per plane: where a slab holds a shaft's edge or passes a light, one
  // sample misses or overshoots it. sampling=lit (the default) samples each
  // slab's lit piece evenly in the angle from the light, integrating 1/r².
  {"planes", "teapot_spot", {"planes=100", "sampling=plane"}, 0.10,
   "one sample per slab: the cone's edges and the apex band (measured 0.064)"},
  {"planes", "stage", {"planes=100", "sampling=plane"}, 4.5,
   "one sample per slab: the five lamps are in view, and beside each the 1/r² peak and the gobo's dots "
   "pass within one slab, so those pixels read 0 or several times the reference's 3.3 (measured 3.2)"},
  {"planes", "stained_glass", {"planes=100", "sampling=plane"}, 0.2,
   "one sample per slab across the beam's faces and its stained-glass pattern (measured 0.13)"},
  {"planes", "teapot_spot", {"planes=100"}, 0.006,
   "measured 0.0021: the 1024² shadow map's texels along the teapot's shadow edges"},
  {"planes", "stage", {"planes=100"}, 0.025,
   "measured 0.0099: the pixels beside the five lamps, whose pieces sweep the gobo's dots and the soft "
   "edges within millimetres, sampled every π/256 rad"},
  {"planes", "stained_glass", {"planes=100"}, 0.05,
   "measured 0.026 in a dim image (mean 0.0065): the shadow map's texels at the table's and the "
   "pillar's silhouettes inside the beam"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
