// shadow_planes' rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/reduced_quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // shadow_planes (Biri 2006) sees the reference's own triangles: its shadows
  // are exact, and what remains is Γ's accuracy and the reference's quadrature
  // (rel_tol 1e-3). A plane missing from a silhouette flips the count behind
  // it along every ray that crosses it: a wedge of pixels off by the whole
  // shaft, far above these bounds (docs/decisions.md).
  {"shadow_planes", "biri_sphere", {}, 0.005, "exact shadows: Γ and the reference's quadrature (measured 1e-4)"},
  {"shadow_planes", "biri_pens", {}, 0.005, "exact shadows, nested volumes: Γ and the reference (measured 0.0010)"},
  {"shadow_planes", "teapot_spot", {}, 0.005, "exact shadows of the closed teapot: Γ and the reference (measured 0.0007)"},
  // What Γ has no closed form for, by the ratio sampled at 64 points a lit interval.
  {"shadow_planes", "stage", {}, 0.02,
   "gobos (the white spot's stripes converge on its apex) by the sampled ratio (measured 0.009, the reference's own "
   "error there: raymarch at N = 1024 shows the same)"},
  {"shadow_planes", "stained_glass", {}, 0.04, "the window's gobo along the beam by the sampled ratio (measured 0.020)"},
  {"shadow_planes", "biri_media", {}, 0.015,
   "three bounded volumes: Γ per piece and medium, the light's leg through the other volumes by the sampled ratio "
   "(measured 0.005, and 0.009 in the moved frame, where the volumes stay and the light's legs through them grow; "
   "with the piece's σt all the way to the light, Biri's approximation, 0.73)"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

// At scale = 1/2 (kit/resolution) against the reference: the full scale's error and what the
// upsampling adds where L_air changes within a coarse pixel (testing/reduced_quality.hpp); at
// 128×96 such pixels are many, at 1024×768 few (docs/decisions.md "Reduced resolution").
// clang-format off
const Case reduced_rows[] = {
  {"shadow_planes", "teapot_spot", {}, 0.019,
   "measured 0.0087: the spot's cone edge and the teapot's shadow edges between coarse pixels that agree"},
  {"shadow_planes", "stage", {}, 0.059,
   "measured 0.0242 (full scale 0.0055): the gobos' stripes, a coarse pixel wide, between coarse pixels that agree"},
  {"shadow_planes", "biri_sphere", {}, 0.098,
   "measured 0.0242: a lit sliver beside the sphere, narrower than a coarse pixel: no coarse neighbour sees it"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Reduced, ReducedQuality, ::testing::ValuesIn(reduced_rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
