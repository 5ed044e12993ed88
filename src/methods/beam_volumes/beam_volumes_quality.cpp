// beam_volumes' rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/quality.hpp"

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
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
