#pragma once
// The scene model (docs/design.md §1, §4). Every object is a triangle mesh by the time
// a scene is loaded; phase-function sums are flattened into weighted lobes.
#include <airlight/box.hpp>
#include <airlight/export.hpp>
#include <airlight/image.hpp>
#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace airlight {

using Color = glm::vec3;

// The largest far/near airlight supports: a scene file, a glTF camera or a
// frame beyond it is refused (docs/design.md §4).
inline constexpr double max_far_over_near = 1e5;

struct AIRLIGHT_API Camera {
  glm::vec3 position{0, 2, 8}, look_at{0, 1, 0}, up{0, 1, 0};
  float fov_y_deg = 45.0f;  // full vertical field of view
  float near = 0.05f, far = 50.0f;
};

enum class PhaseType { isotropic, rayleigh, henyey_greenstein, schlick, hazy, murky };

// One normalized phase function; g is used by henyey_greenstein and schlick.
struct AIRLIGHT_API PhaseLobe {
  PhaseType type = PhaseType::isotropic;
  float g = 0.0f;
  float weight = 1.0f;
};

// A weighted sum of lobes, weights summing to 1 (a single function is one lobe).
struct AIRLIGHT_API Phase {
  std::vector<PhaseLobe> lobes{PhaseLobe{}};
};

// The homogeneous medium that fills space.
struct AIRLIGHT_API Medium {
  Color sigma_s{0.0f};  // scattering coefficient, 1/m
  Color sigma_a{0.0f};  // absorption coefficient, 1/m
  Phase phase;
  Color sigma_t() const { return sigma_s + sigma_a; }
};

// A bounded convex volume whose coefficients add to the medium's inside it.
struct AIRLIGHT_API Volume {
  glm::vec3 min{0.0f}, max{0.0f};  // shape "box": the only shape so far
  Color sigma_s{0.0f}, sigma_a{0.0f};
  Phase phase;
  Color sigma_t() const { return sigma_s + sigma_a; }
};

enum class LightModelType { physical, simplified };

// `simplified` is Nilsson 2.5: I / (a1 r^2 + a0), T = 1, isotropic phase.
struct AIRLIGHT_API LightModel {
  LightModelType type = LightModelType::physical;
  float a0 = 0.0f, a1 = 1.0f;
};

enum class LightType { point, spot, directional };

// A directional light's bounded beam (Dobashi §4: parallel light, here in a
// bounded light volume so that its airlight stays finite). The light enters
// through the rectangle of `size` (width along `right`, height along `up` of
// optics::gobo_frame) centred at `origin` and perpendicular to the light's
// direction, and exists for `length` metres downstream of it: the beam is that
// oriented box. A gobo on a directional light maps across the rectangle.
struct AIRLIGHT_API Beam {
  glm::vec3 origin{0.0f};
  glm::vec2 size{1.0f};  // width, height (m)
  float length = 1.0f;   // m, along direction
};

struct AIRLIGHT_API Light {
  LightType type = LightType::point;
  glm::vec3 position{0.0f};           // point, spot
  glm::vec3 direction{0, -1, 0};      // spot: axis; directional: the way light travels (unit)
  Color intensity{0.0f};              // point, spot: W/sr
  Color irradiance{0.0f};             // directional: W/m^2
  float cone_deg = 180.0f;            // spot half-angle
  float edge_deg = 0.0f;              // spot smooth edge width (0 = hard cut, Nilsson eq. 2.9)
  std::shared_ptr<const Image> gobo;  // light map (linear RGB) of a spot or a beam, or null
  glm::vec3 gobo_up{0, 1, 0};         // orients the gobo and the beam (unit, not parallel to direction)
  std::optional<Beam> beam;           // directional: the bounded beam; none = lit everywhere
};

struct AIRLIGHT_API Mesh {
  std::string name;                  // for messages: "objects[2] (hall.obj)"
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    // per vertex, unit; same size as positions
  std::vector<glm::uvec3> triangles; // indices into positions
  Color albedo{0.7f};
  bool casts_shadows = true;         // false: light passes through it (it still ends view rays)
  // Nilsson §5.1's bounding volumes as the file gives them, in world space (moved with the
  // object): the outer one encloses every vertex, the inner one lies inside the closed mesh.
  // None: geometry/bounding_volumes computes them.
  std::optional<OrientedBox> outer_box, inner_box;
};

struct AIRLIGHT_API Scene {
  std::string name;                  // built-in name or file stem
  std::filesystem::path source;      // the scene file, empty for built-ins
  Camera camera;
  Medium medium;
  LightModel light_model;
  std::vector<Volume> volumes;
  std::vector<Light> lights;
  std::vector<Mesh> meshes;
  Color ambient{0.0f};
};

// Loads and validates an airlight-scene/1 JSON file. Throws InputError naming
// the file and the key.
AIRLIGHT_API Scene load_scene(const std::filesystem::path& file);
// Parses scene JSON text; `file` names it in messages and anchors relative paths.
AIRLIGHT_API Scene parse_scene(const std::string& json_text, const std::filesystem::path& file);

// Writes `scene` as an airlight-scene/1 JSON file that load_scene reads back to
// the same Scene: each mesh as FILE_STEM.meshN.obj (world space, its normals)
// and each gobo as FILE_STEM.goboN.exr beside it. Bounding volumes that are not
// axis-aligned are left out (load computes them). Throws InputError for a name
// not ending in .json, Failure when a file cannot be written.
AIRLIGHT_API void save_scene(const Scene& scene, const std::filesystem::path& file);

// Built-in scenes (docs/design.md §4). Throws InputError(source, name) for an
// unknown name, listing the known ones: `source` names where the caller got
// the name (the command passes its option, "--builtin").
AIRLIGHT_API Scene builtin_scene(const std::string& name, const std::string& source = "builtin_scene");
AIRLIGHT_API std::vector<std::string> builtin_scene_names();
// One line on what a built-in scene shows and which document it comes from.
AIRLIGHT_API std::string builtin_scene_description(const std::string& name,
                                                   const std::string& source = "builtin_scene_description");

}  // namespace airlight
