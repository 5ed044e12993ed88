// hybrid_clip's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // hybrid_clip (Nilsson §5.3) takes planes' samples (hybrid_clip_test.cpp
  // shows the same image per pixel), so planes' tolerances and reasons hold:
  // lit sampling at 100 planes and the 1024² shadow map's texels at shadow edges.
  {"hybrid_clip", "nilsson_toplight", {}, 0.02, "planes' sampling and shadow-map texels (measured 0.0087)"},
  {"hybrid_clip", "nilsson_multiple", {}, 0.02, "planes' sampling and shadow-map texels of 25 objects (measured 0.0063)"},
  {"hybrid_clip", "nilsson_parallel", {}, 0.03, "planes' sampling and the bars' shadow-map texels (measured 0.013)"},
  {"hybrid_clip", "under_table.json", {}, 0.04, "the cone's core proved unlit; planes' sampling of the shafts beside the table (measured 0.015 at 256×192)"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
