// light_volume's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/reduced_quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // light_volume counts a mesh that follows the 1024² shadow map on a 256²
  // grid (the default), each cell a step at the depth of the texel under its
  // centre: what remains is the grid's cells along shadow edges, each all lit
  // or all shadowed, Γ and the reference's quadrature. Issue 24 asks for 1%
  // at the defaults on these three scenes: no bound above it.
  {"light_volume", "biri_sphere", {}, 0.01, "the sphere's round shadow edge on a 256² grid, beside the apex in view (measured 0.0084)"},
  {"light_volume", "teapot_spot", {}, 0.006, "the teapot's shadow edges on a 256² grid (measured 0.0014)"},
  {"light_volume", "three_lights", {}, 0.01, "three kinds of maps, a point light's cube among them (measured 0.0030)"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

// At scale = 1/2 (kit/resolution) against the reference: the full scale's error and what the
// upsampling adds where L_air changes within a coarse pixel (testing/reduced_quality.hpp); at
// 128×96 such pixels are many, at 1024×768 few (docs/decisions.md "Reduced resolution").
// clang-format off
const Case reduced_rows[] = {
  {"light_volume", "teapot_spot", {}, 0.02,
   "measured 0.0097 (full scale 0.0014): the spot's cone edge and the teapot's shadow edges between coarse pixels that agree"},
  {"light_volume", "stage", {}, 0.06,
   "measured 0.0250 (full scale 0.0056): the gobos' stripes, a coarse pixel wide, between coarse pixels that agree"},
  {"light_volume", "biri_sphere", {}, 0.1,
   "measured 0.0252 (full scale 0.0086): a lit sliver beside the sphere, narrower than a coarse pixel: no coarse neighbour sees it"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Reduced, ReducedQuality, ::testing::ValuesIn(reduced_rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
