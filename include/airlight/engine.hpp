#pragma once
// airlight inside an engine's frame (docs/design.md §3, "engine"): the engine
// draws its scene with its own depth buffer and shadow maps, then asks a GPU
// method for the light shafts, as NVIDIA's volumetric lighting library does
// (scene depth and camera, each light with its shadow map, the result into the
// engine's target). Everything here is a GL texture name of the caller's
// context; airlight converts the caller's conventions (reversed-Z, its own
// projections, window depth or distance) to its own.
//
//   airlight::use_current_gl_context();           // once, with the engine's context current
//   auto method = airlight::find_method("raymarch").create(settings);
//   method->prepare(scene);                       // meshes, lights, media
//   airlight::EngineFrame engine{...};            // per frame: depth, shadow maps, targets
//   method->render_frame(airlight::frame_inputs(scene, w, h), engine);
//
// The context: prepare, render_frame, read_back and the method's destructor
// run with the engine's context current on the calling thread; call
// use_current_gl_context() before the first prepare (methods prepared before
// it keep the headless context). airlight installs no debug callback in the
// engine's context; it reads glGetError after each frame and throws Failure.
//
// GL state: render_frame saves and restores the current program, the draw and
// read framebuffers, the viewport, the vertex array, the clip control, depth
// test, function and mask, blending (enable, functions, equations), face
// culling, scissor and stencil tests, polygon offset fill, depth clamp,
// framebuffer sRGB, colour mask, clip distances 0–7 and the active texture
// unit. It leaves its own objects bound to texture units 0–15 (with no sampler
// object), image units 0–3, shader storage bindings 0–15 and uniform binding 0:
// rebind yours there after it. The caller's textures are only read (depth,
// shadow maps: through airlight's own nearest sampler, so compare mode and
// filters set for hardware PCF do not matter) or written (targets); their
// parameters are not changed. Multisampled textures are not accepted.
#include <airlight/export.hpp>
#include <array>
#include <glm/mat4x4.hpp>
#include <optional>
#include <vector>

namespace airlight {

// How window depth maps to normalized device z: glClipControl's depth mode.
enum class DepthRange { negative_one_to_one, zero_to_one };

// The engine's depth buffer: a texture of the frame's size (DEPTH_COMPONENT*,
// or R32F holding window depth), drawn through `view` and `projection` from
// FrameInputs::camera's pose with its pixel grid (docs/design.md §5). Any
// projection works — reversed-Z, infinite far plane — as long as it can be
// inverted; where the depth is the clear value (no surface) or beyond the
// camera's far plane, the view ray ends at the far plane.
struct AIRLIGHT_API EngineDepth {
  unsigned texture = 0;
  glm::mat4 view{1.0f}, projection{1.0f};
  DepthRange range = DepthRange::negative_one_to_one;
};

// A light's shadow map as the engine drew it.
struct AIRLIGHT_API EngineShadow {
  enum class Kind {
    map,   // a 2D texture, or layer `layer` of a 2D array, through view and projection
    cube,  // a cube map around the light's position, GL's face order and orientation
  };
  enum class Stores {
    window_depth,  // depth of `projection` (for cubes: of each 90° face's projection)
    distance,      // linear distance from the light's position (cubes; common in engines)
  };
  Kind kind = Kind::map;
  unsigned texture = 0;
  int layer = -1;  // for 2D arrays
  Stores stores = Stores::window_depth;
  glm::mat4 view{1.0f}, projection{1.0f};  // map: the light's camera; cube: projection of every face
  DepthRange range = DepthRange::negative_one_to_one;
};

// Where the result goes; each texture the frame's size (another size or format
// throws InputError("EngineTarget", "airlight" | "transmittance" | "colour")
// before anything is drawn). 0 leaves that output out.
struct AIRLIGHT_API EngineTarget {
  unsigned airlight = 0;       // RGBA32F or RGBA16F: L_air, W/(m²·sr)
  unsigned transmittance = 0;  // RGBA32F or RGBA16F: T(d) per channel, what compositing needs
  unsigned color = 0;          // any colour-renderable texture holding linear L_surf in W/(m²·sr)
                               // (before exposure and tone mapping): becomes L_surf·T + L_air
  unsigned surface = 0;        // RGBA32F or RGBA16F: airlight's own L_surf·T(d) (its G-buffer and
                               // shading, as read_back's `surface`), for a caller with no shading of
                               // its own (the viewer); needs FrameInputs::surface and no engine depth
};

struct AIRLIGHT_API EngineFrame {
  // The engine's depth buffer; none: airlight draws its own G-buffer.
  std::optional<EngineDepth> depth;
  // Per light of FrameInputs::lights (shorter: the rest have none); none:
  // airlight draws that light's shadow map itself.
  std::vector<std::optional<EngineShadow>> shadows;
  EngineTarget target;
};

// From now on GPU methods render in the GL 4.5 context current on this thread
// (the engine's) instead of creating a headless one. Throws Failure when no
// context is current or it is older than OpenGL 4.5.
AIRLIGHT_API void use_current_gl_context();

}  // namespace airlight
