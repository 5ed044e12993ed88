// beam_volumes' rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/reduced_quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // beam_volumes (Nilsson §3.2) bounds each light's lit region by pyramids over
  // the visible set of the same triangles the reference sees: exact shadows,
  // so what remains is Γ's accuracy, the reference's quadrature (rel_tol 1e-3)
  // and the beam tree's ε-thick planes (a band of ~1e-6 of the scene's size).
  {"beam_volumes", "nilsson_toplight", {}, 0.01, "exact shadows, Nilsson's simplified model in Γ (measured 5e-5)"},
  {"beam_volumes", "nilsson_multiple", {}, 0.01, "exact shadows of 25 objects (measured 0.0023: the reference's 32 segments beside the apex)"},
  {"beam_volumes", "nilsson_parallel", {}, 0.01, "exact shadows, prisms toward a directional beam (measured 0.0018)"},
  {"beam_volumes", "biri_sphere", {}, 0.01, "exact shadows (measured 1e-4)"},
  {"beam_volumes", "teapot_spot", {}, 0.01,
   "exact shadows of 4160 triangles, whose pyramids' sides meet edge-on in many places: each crossing decided by "
   "an exact ray test, not the rasterizer's snapped coverage (measured 7e-4; 0.019 before, from one pixel)"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

// At scale = 1/2 (kit/resolution) against the reference: the full scale's error and what the
// upsampling adds where L_air changes within a coarse pixel (testing/reduced_quality.hpp); at
// 128×96 such pixels are many, at 1024×768 few (docs/decisions.md "Reduced resolution").
// clang-format off
const Case reduced_rows[] = {
  {"beam_volumes", "teapot_spot", {}, 0.02,
   "measured 0.0097: the spot's cone edge and the teapot's shadow edges between coarse pixels that agree"},
  {"beam_volumes", "stage", {}, 0.06,
   "measured 0.0250 (full scale 0.0055): the gobos' stripes, a coarse pixel wide, between coarse pixels that agree"},
  {"beam_volumes", "biri_sphere", {}, 0.099,
   "measured 0.0246: a lit sliver beside the sphere, narrower than a coarse pixel: no coarse neighbour sees it"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Reduced, ReducedQuality, ::testing::ValuesIn(reduced_rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
