// analytic's rows of the quality table (docs/design.md §6), each tolerance beside its reason.
#include "methods/kit/testing/reduced_quality.hpp"

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

// At scale = 1/2 (kit/resolution) against the reference: the full scale's error and what the
// upsampling adds where L_air changes within a coarse pixel (testing/reduced_quality.hpp); at
// 128×96 such pixels are many, at 1024×768 few (docs/decisions.md "Reduced resolution").
// clang-format off
const Case reduced_rows[] = {
  {"analytic", "teapot_spot", {}, 0.017,
   "measured 0.0074: the spot's cone edge and the teapot's shadow edges between coarse pixels that agree"},
  {"analytic", "stage", {}, 0.034,
   "measured 0.0144: the gobos' stripes, a coarse pixel wide, between coarse pixels that agree"},
  {"analytic", "biri_sphere", {}, 0.058,
   "measured 0.0064: a lit sliver beside the sphere, narrower than a coarse pixel: no coarse neighbour sees it"},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Reduced, ReducedQuality, ::testing::ValuesIn(reduced_rows), case_name);

}  // namespace
}  // namespace airlight::kit::test
