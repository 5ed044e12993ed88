// analytic's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/quality.hpp"

namespace airlight::kit::test {
namespace {

// clang-format off
const Case rows[] = {
  // analytic (Sun et al. 2005 via Kingston 4.2) has no volumetric shadows, so no
  // built-in scene is here (each has occluders whose shadows it cannot show). Its
  // rows use bench/scenes/open_fog*.json: a spot and a point light in front of a
  // wall x < 1.05, z < −4; every lit point seen lies at z > −4 or (past the wall's
  // edge) at x > 1.05, in a half-space with both lights that the wall does not
  // enter, so nothing is shadowed and the reference is Γ itself.
  {"analytic", "open_fog.json", {"F=table"}, 0.005,
   "isotropic: Sun et al. with F from the table, whose bound on Γ is 0.5% (measured 2.2e-5)"},
  {"analytic", "open_fog.json", {"F=shader"}, 0.001,
   "isotropic: F integrated in the shader; the reference's rel_tol 1e-3 (measured 4.4e-6)"},
  {"analytic", "open_fog_anisotropic.json", {}, 0.001,
   "Henyey–Greenstein + Rayleigh: Biri's angular integral by Gauss–Legendre; the reference's "
   "rel_tol 1e-3 (measured 5.1e-6)"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
