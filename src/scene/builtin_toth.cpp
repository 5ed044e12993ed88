// The built-in scene after Tóth and Umenhoffer 2009 (builtin_families.hpp).
#include "scene/builtin_families.hpp"
#include "scene/builtin_parts.hpp"

#include <optional>

namespace airlight::scene_builtin {

using namespace scene_mesh;

// Tóth and Umenhoffer 2009, §5: "The scene consists of 66000 triangles and is
// illuminated by a point light" (their Fig. 3, which did not survive: this
// hall is a stand-in to that count and light). A closed stone hall, its nave
// between two arcades of eight
// columns carrying round arches and a beam, a teapot on a pedestal as the
// statue, and one point light in the left aisle at the far end: its light
// crosses the nave through the arcade toward the camera at the near end, in
// shafts between the columns' shadows. 66 308 triangles, 50 400 of them the
// statue's (builtin_scenes_test.cpp holds the count within 60k–72k).
Scene toth_hall() {
  Scene s;
  s.name = "toth_hall";
  s.camera.position = {0.6f, 1.7f, 7.0f};
  s.camera.look_at = {0.0f, 2.5f, -8.0f};
  s.camera.fov_y_deg = 60.0f;
  s.medium.sigma_s = Color(0.08f);
  s.medium.sigma_a = Color(0.01f);
  s.medium.phase = single_lobe(PhaseType::henyey_greenstein, 0.3f);
  s.ambient = Color(0.03f);
  const Color stone(0.45f, 0.42f, 0.38f);
  add_pieces(s, make_room({{-8.0f, 0.0f, -17.0f}, {8.0f, 8.0f, 7.5f}}, std::nullopt, 0.3f), stone);
  // The arcades' x, the first column's z, the column spacing, the capitals' top.
  const float row = 3.0f, first = -15.0f, bay = 2.5f, height = 4.6f;
  for (const float x : {-row, row}) {
    for (int i = 0; i < 8; ++i) add_pieces(s, make_column({x, first + bay * i}, height, 128), stone);
    for (int i = 0; i < 7; ++i) {  // from capital to capital, turned to span along the row
      Transform t;
      t.translate = {x, height, first + bay * (i + 0.5f)};
      t.rotate_deg = {0.0f, 90.0f, 0.0f};
      const float inner = 0.5f * bay - 0.45f, outer = 0.5f * bay;  // from the capitals' edges to their centres
      s.meshes.push_back(place(make_arch(glm::vec3(0.0f), inner, outer, 0.6f, 64), t, stone, "arch"));
    }
    const float crown = height + 0.5f * bay;
    add_box(s, {x - 0.3f, crown, first - 0.45f}, {x + 0.3f, crown + 0.5f, first + 7.0f * bay + 0.45f}, stone,
            "beam");
  }
  add_box(s, {-0.6f, 0.0f, -6.6f}, {0.6f, 1.2f, -5.4f}, stone, "pedestal");
  Transform t;
  t.translate = {0.0f, 1.2f, -6.0f};
  t.rotate_deg = {0.0f, 30.0f, 0.0f};
  t.scale = 1.4f;
  s.meshes.push_back(place(make_teapot(28), t, Color(0.7f, 0.65f, 0.55f), "statue"));
  Light point;
  point.type = LightType::point;
  point.position = {-5.5f, 3.0f, -12.0f};
  point.intensity = Color(2000.0f, 1800.0f, 1500.0f);
  s.lights.push_back(point);
  return s;
}

}  // namespace airlight::scene_builtin
