// hybrid's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // hybrid (Nilsson §5.4): Γ over fully lit slabs, planes' samples over the
  // uncertain ones, so at most planes' error, which its tolerances state; with
  // his own sampling (one sample per slab at dz = 0.5) far below it.
  {"hybrid", "nilsson_toplight", {}, 0.02, "planes' lit sampling and shadow-map texels in the uncertain slabs (measured 0.0087)"},
  {"hybrid", "nilsson_multiple", {}, 0.02, "as planes: 25 objects' shadow-map texels (measured 0.0063)"},
  {"hybrid", "nilsson_parallel", {}, 0.03, "as planes: the bars' shadow-map texels (measured 0.013)"},
  {"hybrid", "teapot_spot", {}, 0.006, "as planes: the teapot's shadow edges in the 1024² map (measured 0.0021)"},
  {"hybrid", "nilsson_toplight", {"sampling=plane", "spacing=0.5"}, 0.15,
   "Nilsson's dz = 0.5, one sample per half-metre slab where uncertain (beside the objects), Γ where fully lit "
   "(measured 0.108; planes 0.376)"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
