// light_volume's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // light_volume counts a mesh that follows the 1024² shadow map on a 256²
  // grid (the default): what remains is the grid's cells along shadow edges,
  // where a face cuts a cell diagonally, Γ and the reference's quadrature.
  {"light_volume", "biri_sphere", {}, 0.03, "the sphere's round shadow edge on a 256² grid, beside the apex in view (measured 0.016)"},
  {"light_volume", "teapot_spot", {}, 0.006, "the teapot's shadow edges on a 256² grid (measured 0.0022)"},
  {"light_volume", "three_lights", {}, 0.01, "three kinds of maps, a point light's cube among them (measured 0.0028)"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
