#pragma once
// Seeded random scenes for the differential harness (docs/design.md §6): a seed
// gives the same scene under any compiler (harness/random.hpp's own generator
// and distributions, never std:: distributions). Scenes are drawn in
// dimensionless terms (optical depth, sizes from millimetres to kilometres,
// far/near within what airlight supports) so that images are neither black nor
// blown out, and one of the special cases the harness must cover is forced in
// every draw that can have it.
#include <airlight/scene.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace airlight::harness {

// Configurations a method is most likely to get wrong; each is forced in about
// a tenth of the draws, and found geometrically on the scene drawn (a case is
// listed only when the scene has it, forced or not).
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
  // A hash of the structure drawn (room or open, casters, light count and
  // types, shadow kinds, edges, gobos, beams, volume count, phase lobes, light
  // model, grey or coloured media: every scene property the shader defines
  // depend on), equal across a group of structure_group seeds, so methods'
  // programs compile once per group when the seeds run in order.
  std::uint64_t structure = 0;
  double size = 0.0;  // L, the scale the scene was drawn in (m): 1 mm to 1 km, log-uniform
};

// Seeds share a structure in groups of this many: the structure is drawn from
// seed / structure_group, the sizes, placements and colours from the seed.
inline constexpr std::uint64_t structure_group = 8;

GeneratedScene random_scene(std::uint64_t seed);

// The room around a drawn scene and the ground under an open one are meshes of
// this name (the loader makes it "objects[i] (enclosure)"): they end view rays,
// cast no shadows, and are not casters in the special cases' sense.
inline constexpr std::string_view enclosure_name = "enclosure";
bool is_enclosure(const Mesh& mesh);

// Whether `scene` has the case, found from its geometry: "in view" is in the
// image of any width ≥ height, a hair is 10⁻⁴ of the scene's size.
bool has_case(const Scene& scene, SpecialCase c);
// Every case the scene has, in the enum's order.
std::vector<SpecialCase> special_cases(const Scene& scene);

// What the scene has, for the harness's coverage: "light:spot", "spot:smooth_edge",
// "gobo:beam", "phase:murky", "phase:sum", "volume", "media:coloured",
// "model:simplified", "space:room", "caster:teapot", "open_mesh", "non_caster", ...
std::vector<std::string> features(const Scene& scene);

}  // namespace airlight::harness
