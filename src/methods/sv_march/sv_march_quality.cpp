// sv_march's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/reduced_quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // At its defaults (N = 64 equiangular steps, the 1024² map on a 64² shell):
  // the march's steps over the shells of the shadow edges, Γ elsewhere.
  {"sv_march", "teapot_spot", {}, 0.002, "the teapot's shadow edges, 64 steps across its shell (measured 0.0011)"},
  {"sv_march", "biri_sphere", {}, 0.02, "the sphere's shadow cone, whose shell reaches the floor, with the apex in view "
                                        "(measured 0.0073)"},
  // Over 20 s with Mesa's shader cache off: a spot's, a point's cube and a directional
  // light's maps in one program, compiled for the first frame (docs/decisions.md "Build").
  {"sv_march", "three_lights", {}, 0.01, "three kinds of maps, a point light's cube among them (measured 0.0046)"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

// At scale = 1/2 (kit/resolution) against the reference: the full scale's error and what the
// upsampling adds where L_air changes within a coarse pixel (testing/reduced_quality.hpp); at
// 128×96 such pixels are many, at 1024×768 few (docs/decisions.md "Reduced resolution").
// clang-format off
const Case reduced_rows[] = {
  {"sv_march", "teapot_spot", {}, 0.02,
   "measured 0.0097: the spot's cone edge and the teapot's shadow edges between coarse pixels that agree"},
  {"sv_march", "stage", {}, 0.06,
   "measured 0.0250 (full scale 0.0055): the gobos' stripes, a coarse pixel wide, between coarse pixels that agree"},
  {"sv_march", "biri_sphere", {}, 0.1,
   "measured 0.0253 (full scale 0.0073): a lit sliver beside the sphere, narrower than a coarse pixel: no coarse neighbour sees it"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Reduced, ReducedQuality, ::testing::ValuesIn(reduced_rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
