#include "methods/kit/planes/plane_pass.hpp"

#include "gpu/program.hpp"
#include "methods/kit/method/memory_needs.hpp"
#include "methods/kit/sampling/noise.hpp"

#include <algorithm>
#include <cstddef>
#include <cmath>

namespace airlight::kit {
namespace {

constexpr GLuint jitter_unit = binding::first_free_texture;
constexpr int max_planes = 8192;  // per light: dz never below 1/8192 of the lit depth
constexpr const char* fragment_stage = "methods/kit/planes/planes.frag.glsl";

// Two triangles per cell of an n×n lattice over (n + 1)² vertices, row-major.
std::vector<GLuint> lattice_indices(int n) {
  std::vector<GLuint> indices;
  const auto at = [n](int i, int j) { return static_cast<GLuint>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      indices.insert(indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  return indices;
}

}  // namespace

std::vector<SettingSpec> plane_settings(bool cut) {
  using T = SettingSpec::Type;
  std::vector<SettingSpec> all{{"planes", T::integer, 100, 1, max_planes, {},
           "n: virtual planes per light, evenly spaced in view depth from the eye to the far end of the light's "
           "lit region (Dobashi Fig. 5: 15, 30, 75; Table 1: 50 and 150)"},
          {"spacing", T::real, 0.0, 0.0, 100.0, {},
           "dz: the planes' spacing in metres of view depth instead of their count (0 = use planes)"},
          {"lattice", T::integer, 0, 0, 512, {},
           "ξ on an n×n lattice mesh per plane, interpolated across its cells (Dobashi §5.1, Fig. 6: 5, 20, 80); "
           "0 = ξ per fragment. The light map, the cone and the shadow test are per fragment either way"},
          {"jitter", T::choice, 0, 0, 0, jitter_choices,
           "per-pixel offset of the samples within their slabs (Dobashi §7): none = the middle; white or blue "
           "noise turn the planes' banding into noise"},
          {"sampling", T::choice, 0, 0, 0, {"lit", "plane"},
           "plane = Dobashi's: one sample per plane at the middle of its slab's part in front of the surface, "
           "weighted by Δt; lit = the slab's piece cut to the light's lit interval (a spot's cone, a beam's box), "
           "sampled evenly in the angle seen from a point or spot light with the falloff integrated exactly, and "
           "with more samples where the piece sweeps a gobo, passes beside the light or crosses a dense medium, and cut "
           "at bounded volumes' chord ends (lattice: ξ stays sampled)"},
          {"clip", T::boolean, 1, 0, 1, {},
           "clip the planes to the light's influence volume (a pyramid around a spot's cone, a beam's box), so "
           "fragments outside it are never shaded (Nilsson 3.1)"}};
  if (cut)  // each plane samples its slab's middle, where its regions are classified
    std::erase_if(all, [](const SettingSpec& s) { return s.name == "lattice" || s.name == "jitter"; });
  return all;
}

PlaneSettings PlaneSettings::from(const Settings& s, PlaneCut cut) {
  enum class Sampling { lit, plane };  // the `sampling` setting's choices, in order
  const bool whole = cut == PlaneCut::none;
  return {s.integer("planes"),
          s.real("spacing"),
          whole ? s.integer("lattice") : 0,
          whole ? s.option<Jitter>("jitter") : Jitter::none,
          s.option<Sampling>("sampling") == Sampling::lit,
          s.boolean("clip"),
          cut};
}

void PlanePass::prepare(const Scene& scene) {
  const std::vector<float> offsets = settings_.jitter == Jitter::blue ? blue_noise() : white_noise();
  noise_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32F, noise_size, noise_size);
  glTextureSubImage2D(noise_.id(), 0, 0, 0, noise_size, noise_size, GL_RED, GL_FLOAT, offsets.data());
  const std::vector<GLuint> indices = lattice_indices(std::max(settings_.lattice, 1));
  index_count_ = static_cast<int>(indices.size());
  indices_ = gpu::make_buffer(indices.size() * sizeof(GLuint), indices.data());
  mesh_ = gpu::make_vertex_array();  // no attributes: vertices come from gl_VertexID
  glVertexArrayElementBuffer(mesh_.id(), indices_.id());
  piece_mesh_ = gpu::make_vertex_array();  // PieceVertex: position, then plane
  piece_vertices_.release();  // bound to the new piece_mesh_ when made again
  glEnableVertexArrayAttrib(piece_mesh_.id(), 0);
  glVertexArrayAttribFormat(piece_mesh_.id(), 0, 3, GL_FLOAT, GL_FALSE, offsetof(PieceVertex, position));
  glVertexArrayAttribBinding(piece_mesh_.id(), 0, 0);
  glEnableVertexArrayAttrib(piece_mesh_.id(), 1);
  glVertexArrayAttribIFormat(piece_mesh_.id(), 1, 1, GL_INT, offsetof(PieceVertex, plane));
  glVertexArrayAttribBinding(piece_mesh_.id(), 1, 0);
  no_vertices_ = gpu::make_vertex_array();
  fbo_ = gpu::make_framebuffer();
  invocations_.prepare();
  light_bounds_.prepare(scene);
  if (settings_.cut != PlaneCut::none) slab_pieces_.prepare(scene);
}

// A sample lies anywhere in its slab, up to dz/2 in depth, i.e. dz/(2 cos)
// along its ray, from the middle where the clip distances and the regions are taken.
float PlanePass::reach(const Slabs& s) const { return 0.5f * s.dz / cos_edge_; }

std::vector<MemoryNeed> slab_piece_needs(const Scene& scene, const Settings& settings, int, int) {
  // Measured per plane and caster, the polygons and their beam-tree pieces
  // (docs/decisions.md "Memory for settings").
  constexpr double bytes_per_piece_set = 3000.0;
  constexpr double bytes_per_buffer = 2.0 * 8 * 3 * sizeof(PieceVertex);  // about 8 triangles, the buffer grown 2×
  const double spacing = settings.real("spacing"), casters = caster_count(scene);
  const double planes = std::clamp(spacing > 0.0 ? std::ceil(scene.camera.far / spacing) : settings.integer("planes"),
                                   1.0, double(max_planes));
  if (casters == 0.0 || scene.lights.empty()) return {};
  return {{spacing > 0.0 ? "spacing" : "planes",
           "the slab regions of " + counted(planes, "plane") + " across the bounding volumes of " +
               counted(casters, "caster") + " (about 3 KB per plane and caster)",
           bytes_per_piece_set * planes * casters, bytes_per_buffer * planes * casters}};
}

PlanePass::Slabs PlanePass::slabs(const LightBounds& volume) const {
  const double depth = lit_far_depth(volume, camera_, far_);
  if (!(depth > 0.0)) return {};
  const int count = settings_.spacing > 0.0 ? static_cast<int>(std::ceil(depth / settings_.spacing)) : settings_.planes;
  const int n = std::clamp(count, 1, max_planes);
  return {n, static_cast<float>(depth / n)};
}

void PlanePass::plan(const SceneFrame& frame) {
  light_bounds_.update(frame.inputs());
  camera_ = geometry::camera_basis(frame.inputs().camera);
  far_ = frame.inputs().camera.far;
  // cos of the angle between the view axis and the ray through an image corner
  cos_edge_ = static_cast<float>(
      1.0 / geometry::corner_distance(frame.inputs().camera, double(frame.width()) / frame.height(), 1.0));
  slab_pieces_.reset();
  plans_.clear();
  for (int i = 0; i < static_cast<int>(light_bounds_.bounds().size()); ++i) {
    plans_.push_back(plan_light(frame, i, light_bounds_.bounds()[i]));
    for (const Part part : parts(plans_.back()))
      gpu::link_ahead({{GL_VERTEX_SHADER, vertex_stage(part)}, {GL_FRAGMENT_SHADER, fragment_stage}},
                      frame.defines() + defines(frame, i, part));
  }
}

// Nilsson §5.3–5.4 with every sample where planes would take it. A plane's
// regions hold at its slab's middle, which is where the sample of a slab wholly
// in front of the surface lies (sampling=plane): those slabs are drawn as the
// fully lit and uncertain polygons (FULL_SLABS). The one slab per pixel that
// the surface cuts samples elsewhere; a full-screen pass takes it with the
// shadow test (CUT_SLABS). So sampling=plane gives planes' image, with fewer
// fragments. Lit sampling's pieces and Γ over a fully lit slab reach the whole
// slab: its regions are then taken with that margin (slab_pieces.hpp).
PlanePass::LightPlan PlanePass::plan_light(const SceneFrame& frame, int light, const LightBounds& volume) {
  LightPlan plan{slabs(volume), settings_.clip ? volume.clip : std::vector<glm::vec4>{}, {}};
  if (plan.slabs.count == 0 || settings_.cut == PlaneCut::none) return plan;
  std::vector<glm::vec4> widened = plan.clip;
  for (glm::vec4& h : widened) h.w += reach(plan.slabs);
  plan.pieces = slab_pieces_.build(frame.inputs(), light, plan.slabs.count, plan.slabs.dz, reach(plan.slabs), widened);
  return plan;
}

std::vector<PlanePass::Part> PlanePass::parts(const LightPlan& plan) const {
  if (plan.slabs.count == 0) return {};
  if (settings_.cut == PlaneCut::none) return {Part::lattice};
  std::vector<Part> drawn;
  if (!plan.pieces.fully_lit.empty()) drawn.push_back(Part::fully_lit);
  if (!plan.pieces.uncertain.empty()) drawn.push_back(Part::uncertain);
  drawn.push_back(Part::cut_slabs);
  return drawn;
}

void PlanePass::run(const SceneFrame& frame, const gpu::Texture& target) {
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(target.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, frame.depth().id(), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, frame.width(), frame.height());
  // A plane passes where its near face is not behind the scene's depth; the
  // fragment shader weighs only the part of its slab in front of the surface,
  // so a tie passes (GL_LEQUAL), and no plane is clipped at the far plane
  // (depth clamp): with far/near = 8·10⁴ a near face within 1 mm of a 0.4 m
  // far plane rounds to the far plane's depth, and the slab holding a light
  // just short of it was lost (random scene 554: rRMSE 1.16 at 1024 planes).
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glEnable(GL_DEPTH_CLAMP);
  glDepthMask(GL_FALSE);  // the scene's depth is only tested against
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  for (GLenum c = 0; c < 8; ++c) glEnable(GL_CLIP_DISTANCE0 + c);
  glBindTextureUnit(jitter_unit, noise_.id());
  planes_drawn_ = 0.0;
  invocations_.begin();
  for (int i = 0; i < static_cast<int>(plans_.size()); ++i) {
    for (const Part part : parts(plans_[i])) draw(frame, i, part, plans_[i]);
    planes_drawn_ += plans_[i].slabs.count;
  }
  invocations_.end();
  for (GLenum c = 0; c < 8; ++c) glDisable(GL_CLIP_DISTANCE0 + c);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// The program for one part of the planes of light `light`'s structure: the
// first light of that structure as the constant index, shared with the
// others (the light drawn is the uniform shared_light: scene.glsl), and the
// settings as constants (planes.frag.glsl).
std::string PlanePass::defines(const SceneFrame& frame, int light, Part part) const {
  const std::string index = std::to_string(frame.representative(light));
  std::string d = "#define BINDING_JITTER " + std::to_string(jitter_unit) + "\n#define SHARED_LIGHT " + index + "\n";
  if (settings_.lattice > 0) d += "#define LATTICE_XI\n";
  if (settings_.jitter != Jitter::none) d += "#define JITTER\n";
  if (settings_.lit_sampling) d += "#define LIT_SAMPLING\n";
  if (part == Part::fully_lit || part == Part::uncertain) d += "#define FULL_SLABS\n";
  if (part == Part::cut_slabs) d += "#define CUT_SLABS\n";
  if (part == Part::fully_lit)
    d += settings_.cut == PlaneCut::gamma ? "#define FULLY_LIT_GAMMA\n" : "#define FULLY_LIT\n";
  return d;
}

void PlanePass::upload(const std::vector<PieceVertex>& vertices) {
  if (piece_vertices_.assign(vertices))
    glVertexArrayVertexBuffer(piece_mesh_.id(), 0, piece_vertices_.id(), 0, sizeof(PieceVertex));
}

const char* PlanePass::vertex_stage(Part part) {
  return part == Part::lattice     ? "methods/kit/planes/planes.vert.glsl"
         : part == Part::cut_slabs ? "methods/kit/frame/fullscreen.vert.glsl"
                                   : "methods/kit/planes/piece_planes.vert.glsl";
}

void PlanePass::draw(const SceneFrame& frame, int light, Part part, const LightPlan& plan) {
  const gpu::Program& program = gpu::cached_program(
      {{GL_VERTEX_SHADER, vertex_stage(part)}, {GL_FRAGMENT_SHADER, fragment_stage}},
      frame.defines() + defines(frame, light, part));
  glUseProgram(program.id());
  gpu::set_uniform(program, "shared_light", light);
  gpu::set_uniform(program, "dz", plan.slabs.dz);
  if (part == Part::cut_slabs) {  // full screen, the shader finding the slab the surface cuts
    gpu::set_uniform(program, "plane_count", plan.slabs.count);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(no_vertices_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
    return;
  }
  gpu::set_uniform(program, "clip_planes", plan.clip);
  gpu::set_uniform(program, "clip_count", static_cast<int>(plan.clip.size()));
  gpu::set_uniform(program, "clip_margin", reach(plan.slabs));
  if (part != Part::lattice) {
    const std::vector<PieceVertex>& pieces = part == Part::fully_lit ? plan.pieces.fully_lit : plan.pieces.uncertain;
    upload(pieces);
    glEnable(GL_CULL_FACE);  // the pieces' triangles face the eye (slab_pieces.cpp)
    glBindVertexArray(piece_mesh_.id());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(pieces.size()));
    glDisable(GL_CULL_FACE);
    return;
  }
  gpu::set_uniform(program, "lattice", std::max(settings_.lattice, 1));
  glBindVertexArray(mesh_.id());
  glDrawElementsInstanced(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr, plan.slabs.count);
}

std::vector<std::pair<std::string, double>> PlanePass::stats() const {
  std::vector<std::pair<std::string, double>> s{{"planes", planes_drawn_},
                                                {"fragments", invocations_.latest().value_or(-1.0)},
                                                {"rebuilt_lights", light_bounds_.rebuilt()},
                                                {"rebuild_s", light_bounds_.seconds()}};
  if (settings_.cut == PlaneCut::none) return s;
  const auto more = slab_pieces_.stats();
  s.insert(s.end(), more.begin(), more.end());
  return s;
}

}  // namespace airlight::kit
