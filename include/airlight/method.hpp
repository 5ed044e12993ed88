#pragma once
// The method contract (docs/design.md §3). A method is prepared once per scene
// (what it derives from the geometry, the tables it builds); then every frame
// brings its own inputs — camera, size, the lights and the medium as they are
// in this frame, a transform per object — and the method writes L_air where it
// keeps its output: a float GPU texture for GPU methods. Reading images back to
// the CPU is a separate step (read_back) that batch commands ask for and an
// interactive caller never pays. An engine hands in its own depth buffer and
// shadow maps and receives L_air and T(d) in its own textures
// (<airlight/engine.hpp>).
#include <airlight/export.hpp>
#include <airlight/image.hpp>
#include <airlight/scene.hpp>
#include <airlight/settings.hpp>
#include <airlight/timing.hpp>
#include <cstdint>
#include <functional>
#include <glm/mat4x4.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace airlight {

struct EngineFrame;  // <airlight/engine.hpp>

// What a frame may change without a new prepare. Lights may move, change
// colour, cone, type or number; a gobo must be one the prepared scene's lights
// already use. Bounded volumes and meshes' shapes are fixed at prepare; meshes
// move by their transforms.
struct AIRLIGHT_API FrameInputs {
  Camera camera;
  int width = 0, height = 0;
  std::vector<Light> lights;
  Medium medium;
  LightModel light_model;
  // Object → world per mesh of the prepared scene, in Scene::meshes' order;
  // empty means every mesh stays where the scene put it.
  std::vector<glm::mat4> transforms;
  // Whether the surface term L_surf·T(d) is wanted as well (read_back's
  // `surface`); false skips its pass. An engine's frame computes it only for
  // an EngineTarget::surface.
  bool surface = true;
};

// The scene as loaded, at width × height: the first frame's inputs.
AIRLIGHT_API FrameInputs frame_inputs(const Scene& scene, int width, int height);

// Throws InputError("frame", key) for inputs that do not fit the prepared
// scene: a size outside 1–16384, a transform count other than the mesh count,
// non-finite numbers, a zero light direction, a cone outside (0, 180], a
// negative colour or coefficient, and every other value the scene loader
// checks (phase lobes, light model, gobo_up, beams). Every render_frame checks
// this first.
AIRLIGHT_API void check_frame_inputs(const Scene& scene, const FrameInputs& inputs);

// The scene a frame shows: the inputs' camera, lights, medium and light model,
// and its meshes moved by the transforms (what the reference renders).
AIRLIGHT_API Scene posed_scene(const Scene& scene, const FrameInputs& inputs);

enum class Pass { composite, airlight, surface };

// A frame read back to the CPU.
struct AIRLIGHT_API FrameImages {
  Image airlight;                      // L_air, W/(m²·sr)
  Image surface;                       // L_surf·T(d)
  std::vector<PassTime> times;         // per pass, in the order run
  double readback_s = 0.0;             // reading the images back: what an interactive caller never pays
  std::vector<std::pair<std::string, double>> stats;  // method-specific counters
};

// Pass times and counters without images: what an interactive caller shows
// every frame without paying for read_back. Reading them never waits for the
// GPU, so they are of the newest frame whose results the GPU has written:
// `frame`, counting the frames rendered since prepare() from 0 (-1: none yet;
// the last frame once the GPU is idle). Counters a method reads from GPU queries
// (fragments) are likewise of a frame the GPU has finished; the others are the
// last frame's.
struct AIRLIGHT_API FrameNumbers {
  std::int64_t frame = -1;
  std::vector<PassTime> times;
  std::vector<std::pair<std::string, double>> stats;
};

class AIRLIGHT_API Method {
public:
  virtual ~Method() = default;
  // Keeps what it needs of `scene`: the caller may drop it once this returns.
  virtual void prepare(const Scene& scene) = 0;
  // Renders a frame of the prepared scene; its images stay where the method
  // keeps them until read_back(). Throws Failure before prepare().
  virtual void render_frame(const FrameInputs& inputs) = 0;
  // GPU methods: renders a frame in the caller's current GL context from the
  // engine's depth buffer and shadow maps into its textures. Others throw Failure.
  virtual void render_frame(const FrameInputs& inputs, const EngineFrame& engine);
  // The last frame: its images (read from the GPU), pass times and counters.
  virtual FrameImages read_back() const = 0;
  // Times and counters alone, without waiting (FrameNumbers); empty for a
  // method that has none without read_back (the CPU reference).
  virtual FrameNumbers numbers() const { return {}; }
};

// Batch use (render, compare, bench): the scene as loaded at width × height,
// rendered and read back (with the surface term when `surface`). `method` must
// have been prepared with `scene`.
AIRLIGHT_API FrameImages render(Method& method, const Scene& scene, int width, int height, bool surface = true);

// Memory a frame needs beyond the per-pixel estimate: how many bytes, what
// they hold, the setting that sizes them (empty when the scene alone does: its
// lights, casters or triangles), and the largest single GL buffer and texture
// among them (an implementation caps each object's size, whatever the memory).
struct AIRLIGHT_API MemoryNeed {
  std::string setting;
  std::string what;  // "the light volume meshes of 1 cube map (6 faces × 2·2048² triangles), 80 bytes a triangle"
  double bytes = 0.0;
  double largest_buffer = 0.0, largest_texture = 0.0;
};

// A method's MemoryNeeds for a frame of a scene at width × height.
using MemoryEstimate = std::function<std::vector<MemoryNeed>(const Scene&, const Settings&, int width, int height)>;

// What a method models of the physical model (docs/design.md §1) and what it
// reads: a scene is judged by a method only with what the method models,
// against the reference of the same scene with the rest removed (the random
// scenes' harness). Every method models every light type, phase sum and light
// model the format has; they differ in shadows, bounded volumes, gobos and in
// what they need.
struct AIRLIGHT_API Capabilities {
  bool volumetric_shadows = true;  // false: L_air as if no caster stood in the lights' way
  bool bounded_volumes = true;     // false: as if only the medium that fills space were there
  bool gobos = true;               // false: as if no light carried a gobo
  bool engine_maps = true;         // renders from an engine's depth and shadow maps (<airlight/engine.hpp>)
  bool caster_triangles = false;   // reads the casters' triangles, not the shadow maps alone: costs grow with them
  // The CPU reference: the ground truth every other method is judged against,
  // seconds a frame and the same image each time.
  bool ground_truth = false;
};

// The scene whose reference a method's image is judged against: the scene
// with what the method does not model taken out (no caster shadows the lights
// for a method without volumetric shadows, no bounded volume, no gobo), named
// after it with what was taken out ("biri_sphere_without_shadows").
AIRLIGHT_API Scene judged_scene(const Scene& scene, const Capabilities& capabilities);

// How the random scenes' harness (docs/design.md §6) holds a method to the
// reference beyond what it asks of every method at its defaults (finite,
// non-negative, rRMSE ≤ 10 %): at these settings, by this measure, within this
// bound, for this reason.
struct AIRLIGHT_API Trial {
  // rel_rmse: docs/design.md §6's rRMSE. worst_pixel: the largest relative error
  // of a pixel (its largest channel error over its largest reference channel)
  // among the pixels whose reference reaches 1 % of the image's maximum.
  enum class Measure { rel_rmse, worst_pixel };
  std::string name;                   // "exact", "high quality", ...
  std::vector<std::string> settings;  // key=value over the method's defaults
  Measure measure = Measure::rel_rmse;
  double bound = 0.0;
  std::string reason;
  // Another method whose image, at these settings over its defaults, widens
  // the reference's bracket at each pixel (a pixel between the two is right):
  // where what the trial bounds is the method's own error given an input both
  // share (light_volume's against the march through the same shadow maps,
  // whose own error raymarch's trials bound). An empty method: the reference alone.
  struct Baseline {
    std::string method;
    std::vector<std::string> settings;
  };
  Baseline baseline{};
};

// A bound a method puts on the scenes it takes, held by one of its integer
// settings: past it a frame would take the method far longer than it is meant
// to (minutes, or gigabytes), so a caller refuses the scene before any work,
// naming the setting, which may be raised to render it anyway.
struct AIRLIGHT_API SceneLimit {
  std::string setting;                        // the method's integer setting holding the bound
  std::string counted;                        // what count() counts, plural: "caster triangles"
  std::string why;                            // what grows with it: "its beam trees are built ..."
  std::function<double(const Scene&)> count;  // the scene's count, cheap next to a frame
};

struct AIRLIGHT_API MethodInfo {
  std::string name;
  std::string source;       // the document it comes from
  std::string description;
  std::vector<SettingSpec> settings;
  std::function<std::unique_ptr<Method>(const Settings&)> create;
  // About how much memory a frame takes per pixel at the default settings, CPU
  // and GPU together (on llvmpipe the GPU's is the process's): measured, with a
  // margin (docs/decisions.md, "Memory per pixel"). Sizes are refused up front
  // when this times the pixel count exceeds the memory available.
  int bytes_per_pixel = 0;
  // The frame's buffers that the settings and the scene size (shadow maps,
  // crossing pools, meshes, ...), at width × height: with bytes_per_pixel, what
  // a caller checks against the memory it has before any GL allocation. Empty
  // for a method whose memory is all per pixel.
  MemoryEstimate memory;
  Capabilities capabilities;
  std::vector<Trial> trials;
  std::vector<SceneLimit> limits;  // docs/decisions.md "A million triangles"
};

// Every registered method, in the order of docs/design.md §3.
AIRLIGHT_API const std::vector<MethodInfo>& registered_methods();
// Throws InputError(source, name) for an unknown method, listing the known
// ones; `source` names where the name came from (a command: its option).
AIRLIGHT_API const MethodInfo& find_method(const std::string& name, const std::string& source = "find_method");

// L = L_surf·T + L_air, or one of its terms.
AIRLIGHT_API Image select_pass(const FrameImages& frame, Pass pass);

}  // namespace airlight
