// raymarch's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/reduced_quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // Uniform steps (the documents' raymarch): a view ray passing within decimetres
  // of a light has a 1/r² peak narrower than one step (far plane 50 m / 256), which
  // the samples miss or overshoot. Away from the lights the error is ~0.2% at
  // N = 256; these bounds are set by the few pixels beside each light.
  {"raymarch", "teapot_spot", {"steps=256", "sampling=uniform"}, 0.15,
   "uniform steps: the pixels beside the spot's apex (measured 0.10); elsewhere the "
   "1024² shadow map's aliasing along the teapot's shadow edges"},
  {"raymarch", "biri_sphere", {"steps=256", "sampling=uniform"}, 4.0,
   "uniform steps: 4 pixels beside the spot's apex read 0 where the reference has 5.9, "
   "against an image mean of 0.03 (measured 3.1)"},
  {"raymarch", "three_lights", {"steps=256", "sampling=uniform"}, 0.35,
   "uniform steps: the point light's 1/r² peak between samples (measured 0.25), and its "
   "cube map (1024² faces) at the pillars' edges"},
  // Equiangular samples (Kulla & Fajardo 2012) integrate 1/r² exactly per light; what
  // is left is the smooth factors' midpoint error and the shadow maps' edges.
  {"raymarch", "teapot_spot", {"steps=256", "sampling=equiangular"}, 0.01,
   "measured 0.0009: the 1024² shadow map's edge pixels along the teapot's shadow"},
  {"raymarch", "biri_sphere", {"steps=256", "sampling=equiangular"}, 0.02,
   "measured 0.0038: the sphere's shadow edge through the 1024² map, in a mostly dark image"},
  {"raymarch", "three_lights", {"steps=256", "sampling=equiangular"}, 0.02,
   "measured 0.0029: cube-map (1024² faces) edges at the pillars"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

// At scale = 1/2 (kit/resolution) against the reference: the full scale's error and what the
// upsampling adds where L_air changes within a coarse pixel (testing/reduced_quality.hpp); at
// 128×96 such pixels are many, at 1024×768 few (docs/decisions.md "Reduced resolution").
// clang-format off
const Case reduced_rows[] = {
  {"raymarch", "teapot_spot", {}, 0.02,
   "measured 0.0098 (full scale 0.0025): the spot's cone edge and the teapot's shadow edges between coarse pixels that agree"},
  {"raymarch", "stage", {}, 0.06,
   "measured 0.0250 (full scale 0.0055): the gobos' stripes, a coarse pixel wide, between coarse pixels that agree"},
  {"raymarch", "biri_sphere", {}, 0.1,
   "measured 0.0273 (full scale 0.0156): a lit sliver beside the sphere, narrower than a coarse pixel: no coarse neighbour sees it"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Reduced, ReducedQuality, ::testing::ValuesIn(reduced_rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
