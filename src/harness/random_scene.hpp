#pragma once
// Seeded random scenes for the differential harness (docs/design.md §6): a seed
// gives the same scene under any compiler (harness/random.hpp's own generator
// and distributions, never std:: distributions). Scenes are drawn in
// dimensionless terms (optical depth, sizes from millimetres to kilometres,
// far/near within what airlight supports) so that images are neither black nor
// blown out, and the special cases the harness must cover are forced in a share
// of draws.
#include <airlight/scene.hpp>

#include <cstdint>
#include <string_view>
#include <vector>

namespace airlight::harness {

// Configurations a method is most likely to get wrong; each is forced in at
// least 5 % of draws and checked geometrically on the scene drawn (a case is
// listed only when the scene has it).
enum class SpecialCase {
  camera_in_shadow,        // the eye inside a caster's shadow volume of some light
  camera_in_cone,          // the eye inside a spot's cone or a beam's box
  camera_in_volume,        // the eye inside a bounded volume
  camera_on_shadow_plane,  // the eye on the plane of a shadow's side (a silhouette edge and the light)
  light_on_view_ray,       // a light's position within the image
  light_in_caster_box,     // a light inside a caster's bounding box
  light_grazing_wall,      // a light within a hair of a wall's plane
  caster_across_near,      // a caster crossing the near plane
  far_cuts_lit_region,     // the far plane cutting a light's lit region
};
inline constexpr int special_case_count = 9;
std::string_view case_name(SpecialCase c);

struct GeneratedScene {
  Scene scene;                     // passes load-time and per-frame checks
  std::vector<SpecialCase> cases;  // the special cases this scene has
  // Seeds whose structure is equal draw the same structure (light count and
  // types, shadow kinds, gobos, beams, volume count, phase lobes, light model,
  // grey or coloured media), so methods' programs compile once per structure
  // when the seeds run in order.
  std::uint64_t structure = 0;
};

GeneratedScene random_scene(std::uint64_t seed);

}  // namespace airlight::harness
