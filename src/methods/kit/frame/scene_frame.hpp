#pragma once
// The shared frame (docs/design.md §3): what every GPU method receives. At
// prepare, what the scene fixes: meshes (in object space), bounded volumes,
// gobos. Per frame, from FrameInputs: the camera, lights, medium and object
// transforms, then a G-buffer (eye distance, normals, albedo), one shadow map
// per light and the surface term L_surf·T(d) (the reference's surface pass,
// src/reference/reference.cpp, on the GPU) — or, in an engine's frame, its
// depth buffer and shadow maps converted to airlight's conventions. Shaders
// reach it all through methods/kit/frame/scene.glsl at the binding points below.
//
// Pixels follow geometry::primary_ray (docs/design.md §5): GL's bottom-left origin, so
// GL row y is image row H−1−y; read_image() flips back to top row first.
#include "gpu/gl.hpp"
#include "gpu/program.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/frame/bindings.hpp"
#include "methods/kit/frame/frame_data.hpp"
#include "methods/kit/frame/shadows/caster_bounds.hpp"

#include <airlight/engine.hpp>
#include <airlight/image.hpp>
#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace airlight::kit {

using gpu::Buffer;
using gpu::Framebuffer;
using gpu::PassTimer;
using gpu::Program;
using gpu::Texture;
using gpu::VertexArray;

struct FrameSettings {
  int shadow_resolution = 1024;  // texels per side of each shadow map (and cube face)
  float shadow_bias = 1.0f;      // in shadow-map texels at the point (see scene.glsl)
};

class SceneFrame {
public:
  // Uploads what the scene fixes; needs a current GL context. The gobos share
  // one texture array as large as the widest and the tallest; each keeps its
  // own texels at its layer's corner (never resampled: a 16×16 gobo resampled
  // to 16×24 beside another lit random scene 176 21 % brighter than the reference).
  void prepare(const Scene& scene);

  // One frame: uploads `inputs`, then the G-buffer ("gbuffer", or "depth" from
  // the engine's depth buffer), the shadow maps if any are needed ("shadow":
  // drawn, or converted from the engine's) and the surface shading if needed ("surface"),
  // each timed under that name. Throws InputError for inputs that do not fit
  // the prepared scene, before any GL work.
  // What a frame's method reads: shadow maps (none for the analytic method)
  // and the surface term (none when only L_air is wanted).
  struct Needs {
    bool shadows = true, surface = true;
  };
  void render(const FrameInputs& inputs, const FrameSettings& settings, const EngineFrame* engine, Needs needs,
              PassTimer& timer);
  // render() in two halves: the inputs checked and uploaded, defines() set —
  // where a method starts linking what it will use (GpuMethod::link_ahead) —
  // then the passes.
  void set_inputs(const FrameInputs& inputs, const FrameSettings& settings, const EngineFrame* engine, Needs needs);
  void render_passes(const EngineFrame* engine, Needs needs, PassTimer& timer);

  // Binds the frame block, the scene SSBOs and the textures to binding::*.
  void bind() const;
  // What bind() binds, as values that another thread may bind (the worker's,
  // gpu::run_in_worker_context).
  struct Bindings {
    GLuint frame_block, lights, volumes, lobes, face_normals, objects, pixel_list;
    GLuint distance, normal, geometric_normal, albedo, gobos, shadow_maps, shadow_cubes;
    void bind() const;
  };
  Bindings bindings() const;
  // The warm-up of a per-pixel program (gpu::Warm, or called in this context
  // for a pass that runs here): in the worker's context,
  // this frame's bindings and `bind_pass`'s, then one workgroup over a frame
  // block of zeros, a grid of no pixels where every invocation returns at once
  // (FRAME_PIXEL_OR_RETURN). llvmpipe keys the code it generates by the bound
  // textures' and images' formats and shapes, so `bind_pass` binds the
  // textures and images the pass's run binds — by names it holds, as it runs
  // on the worker's thread, maybe after the frame's build has begun: not a
  // buffer the build may replace, which nothing compiled depends on.
  gpu::Warm warm_pixels(std::function<void()> bind_pass) const;
  // Runs `pass`, which dispatches `program`, with this frame bound, in the
  // context where warm_pixels warmed the program (gpu::run_where_warmed): the
  // worker's, or this one's if this thread took its link back.
  void run_where_warmed(const gpu::Program& program, const std::function<void()>& pass) const;

  // What every program that includes scene.glsl is compiled with, for this
  // frame: the binding points and the scene's structure as constants — light
  // count and, per light, its type, shadow kind, gobo, beam, smooth edge and
  // narrowness; volume count; the phase lobes' types; the light model;
  // whether the media are grey — so that a program pays only for what the
  // scene has (docs/design.md §2). Data (positions, colours, σ, g) stays in
  // the buffers: changing it recompiles nothing; changing the structure
  // compiles each program once more.
  const std::string& defines() const { return defines_; }
  // The first light whose structure (its constants in defines()) is light
  // `light`'s: a program compiled for it with SHARED_LIGHT (scene.glsl) draws
  // every light of that structure.
  int representative(int light) const { return representatives_[light]; }

  // The pixel grid a method renders on (docs/design.md §3, reduced resolution):
  // the G-buffer's after render(), or one that methods/kit/resolution puts in
  // its place — a coarser grid over the same view, or the G-buffer's with
  // pixels left out. `distance` (R32F, width × height) takes the G-buffer
  // distance's binding; the frame block's size follows, and width(),
  // height() and bind() are the grid's. Call bind() after a change. A sparse
  // grid (`pixel_list` not null: a PixelList buffer, pixel.glsl) is the full
  // one's size, its pixels only those listed, which dispatch_pixels() runs;
  // its distance is negative at every other pixel, which the passes that
  // draw rather than dispatch (a fragment tests t against the distance) skip.
  void use_grid(const Texture& distance, int width, int height, const Buffer* pixel_list = nullptr);
  // The G-buffer's grid, all of it or (`pixel_list` not null) the pixels
  // listed, for passes that only dispatch.
  void use_gbuffer_grid(const Buffer* pixel_list = nullptr);
  // Runs the bound per-pixel program (pixel.glsl) over the grid: every
  // workgroup of width() × height(), or a sparse grid's list (an indirect
  // dispatch); then a memory barrier, as gpu::dispatch_pixels.
  void dispatch_pixels() const;

  // This frame's inputs (their width and height are the G-buffer's).
  const FrameInputs& inputs() const { return inputs_; }
  int width() const { return grid_width_; }
  int height() const { return grid_height_; }
  // The G-buffer's size, which holds every grid of the frame: a method's own
  // per-pixel textures take it, so that a frame on two grids allocates once.
  int gbuffer_width() const { return inputs_.width; }
  int gbuffer_height() const { return inputs_.height; }
  int light_count() const { return static_cast<int>(inputs_.lights.size()); }
  // Per light, this frame's shadow map kind (shadow_none, shadow_map or shadow_cube: shadow_projection.hpp).
  const std::vector<int>& shadow_kinds() const { return shadow_kinds_; }
  // Texels per side of this frame's shadow maps and cube faces.
  int shadow_resolution() const { return shadow_resolution_; }
  const Texture& distance() const { return grid_distance_ ? *grid_distance_ : distance_; }  // the grid's
  const Texture& gbuffer_distance() const { return distance_; }
  // DEPTH_COMPONENT32F of the G-buffer pass (1 where no surface is hit), for
  // methods that rasterize with the depth test against the scene (always the
  // G-buffer's grid: those methods take no reduced resolution).
  const Texture& depth() const { return depth_; }
  const Texture& albedo() const { return albedo_; }  // rgb albedo, a = 1 where a surface is hit
  const Texture& surface() const { return surface_; }

private:
  struct ShadowLayout {  // how many 2D maps and cube maps the lights use
    int maps = 0, cubes = 0;
    bool operator==(const ShadowLayout&) const = default;
  };
  struct ShadowDraw {  // one 2D map or one cube face of a light
    int light = 0;
    bool cube = false;
    int layer = 0;  // array layer (2D), or 6·cube + face
    glm::mat4 matrix{1.0f};
    const EngineShadow* engine = nullptr;  // converted from the engine's map instead of drawn
  };

  void upload_meshes(const Scene& scene);
  void upload_volumes(const Scene& scene);
  void upload_gobos(const Scene& scene);
  struct Media {  // what upload_medium put in the buffers
    std::vector<shader::SceneLobe> lobes;
    std::vector<shader::SceneVolume> volumes;
  };
  void upload_inputs(const FrameSettings& settings, const EngineFrame* engine, bool shadows);
  Media upload_medium();
  std::vector<shader::SceneLight> upload_lights(const EngineFrame* engine, int resolution, bool shadows);
  void resize(int width, int height);
  void allocate_shadow_maps(const ShadowLayout& layout, int resolution);
  void update_frame_block(const FrameSettings& settings);
  void draw_gbuffer();
  void import_depth(const EngineDepth& depth);
  void draw_shadow_maps();
  void draw_shadow_layer(const ShadowDraw& draw);
  void import_shadow_layer(const ShadowDraw& draw);
  void shade_surfaces();

  Scene scene_;  // as prepared, meshes in object space
  FrameInputs inputs_;
  std::string defines_;
  std::vector<int> representatives_;  // per light (representative())
  std::vector<ShadowDraw> shadow_draws_;
  std::vector<int> shadow_kinds_;  // per light
  ShadowLayout shadow_layout_;
  std::vector<const Image*> gobo_images_;  // per gobo layer
  std::vector<Bounds> caster_bounds_;  // per mesh, in object space (caster_bounds)
  int index_count_ = 0, caster_index_count_ = 0, shadow_resolution_ = 0;
  const Texture* grid_distance_ = nullptr;  // null: the G-buffer's
  const Buffer* grid_list_ = nullptr;       // null: every pixel
  int grid_width_ = 0, grid_height_ = 0;

  VertexArray vertex_array_;
  Buffer vertices_, indices_, face_normals_, objects_;
  Buffer frame_block_, lights_, volumes_, lobes_;
  Buffer empty_block_;  // a frame block of zeros (warm_pixels)
  Texture gobos_;
  Texture distance_, normal_, geometric_normal_, albedo_, depth_, surface_;
  Framebuffer gbuffer_fbo_, shadow_fbo_;
  Texture shadow_maps_, shadow_cubes_, shadow_depth_;
  gpu::Sampler nearest_;  // reads engine textures as stored, whatever their parameters
};

}  // namespace airlight::kit
