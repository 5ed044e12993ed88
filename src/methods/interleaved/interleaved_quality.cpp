// interleaved's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/reduced_quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // interleaved (Tóth §4.1): each pixel marches N/16 of the samples; the 4×4 gather
  // blurs visibility across shadow and silhouette edges. The documents' variant
  // (uniform steps, no guard) keeps that blur whatever N; the guard (the default)
  // clamps it to each pixel's own estimate ± 2 standard errors from 8 own samples on.
  {"interleaved", "teapot_spot", {"steps=256", "sampling=uniform", "guard=0"}, 0.25,
   "uniform steps as raymarch's (the spot's apex) plus the 4×4 blur (measured 0.175)"},
  {"interleaved", "biri_sphere", {"steps=256", "sampling=uniform", "guard=0"}, 4.5,
   "uniform steps: the pixels beside the spot's apex dominate, as for raymarch (measured 3.36)"},
  {"interleaved", "three_lights", {"steps=256", "sampling=uniform", "guard=0"}, 0.35,
   "uniform steps near the point light, as raymarch (measured 0.25)"},
  {"interleaved", "teapot_spot", {"steps=256", "sampling=equiangular"}, 0.02,
   "measured 0.010: the 4×4 gather's blur of the teapot's shadow edges, where the guard's 16 own samples "
   "do not yet clamp it"},
  {"interleaved", "biri_sphere", {"steps=256", "sampling=equiangular"}, 0.15,
   "measured 0.076: the 4×4 blur of the sphere's shadow edge beside the bright apex, partly clamped"},
  {"interleaved", "three_lights", {"steps=256", "sampling=equiangular"}, 0.06,
   "measured 0.029: the 4×4 blur of the pillars' shadows around the point light, partly clamped"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

// At scale = 1/2 (kit/resolution) against the reference: the full scale's error and what the
// upsampling adds where L_air changes within a coarse pixel (testing/reduced_quality.hpp); at
// 128×96 such pixels are many, at 1024×768 few (docs/decisions.md "Reduced resolution").
// clang-format off
const Case reduced_rows[] = {
  {"interleaved", "teapot_spot", {}, 0.032,
   "measured 0.0192 (full scale 0.0125): the spot's cone edge and the teapot's shadow edges between coarse pixels that agree"},
  {"interleaved", "stage", {}, 1.4,
   "interleaved's own error on stage at full scale, 1.20: its 4x4 gather across the gobos' stripes at 128x96; the upsampling adds 0.02 (measured 1.2225)"},
  {"interleaved", "biri_sphere", {}, 0.22,
   "measured 0.1320 (full scale 0.0992): a lit sliver beside the sphere, narrower than a coarse pixel: no coarse neighbour sees it"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Reduced, ReducedQuality, ::testing::ValuesIn(reduced_rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
