#include "methods/planes/plane_pass.hpp"

#include "gpu/program.hpp"
#include "methods/kit/noise.hpp"

#include <algorithm>
#include <cmath>

namespace airlight::methods {
namespace {

constexpr GLuint jitter_unit = kit::binding::first_free_texture;
constexpr int max_planes = 8192;  // per light: dz never below 1/8192 of the lit depth

// Two triangles per cell of an n×n lattice over (n + 1)² vertices, row-major.
std::vector<GLuint> lattice_indices(int n) {
  std::vector<GLuint> indices;
  const auto at = [n](int i, int j) { return static_cast<GLuint>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      indices.insert(indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  return indices;
}

// cos of the angle between the view axis and the ray through an image corner.
float corner_cos(double tan_half_fov_y, double aspect) {
  const double t = tan_half_fov_y;
  return static_cast<float>(1.0 / std::sqrt(1.0 + t * t * (1.0 + aspect * aspect)));
}

}  // namespace

std::vector<SettingSpec> plane_settings() {
  using T = SettingSpec::Type;
  return {{"planes", T::integer, 100, 1, max_planes, {},
           "n: virtual planes per light, evenly spaced in view depth from the eye to the far end of the light's "
           "lit region (Dobashi Fig. 5: 15, 30, 75; Table 1: 50 and 150)"},
          {"spacing", T::real, 0.0, 0.0, 100.0, {},
           "dz: the planes' spacing in metres of view depth instead of their count (0 = use planes)"},
          {"lattice", T::integer, 0, 0, 512, {},
           "ξ on an n×n lattice mesh per plane, interpolated across its cells (Dobashi §5.1, Fig. 6: 5, 20, 80); "
           "0 = ξ per fragment. The light map, the cone and the shadow test are per fragment either way"},
          {"jitter", T::choice, 0, 0, 0, kit::jitter_choices,
           "per-pixel offset of the samples within their slabs (Dobashi §7): none = the middle; white or blue "
           "noise turn the planes' banding into noise"},
          {"sampling", T::choice, 0, 0, 0, {"lit", "plane"},
           "plane = Dobashi's: one sample per plane at the middle of its slab's part in front of the surface, "
           "weighted by Δt; lit = the slab's piece cut to the light's lit interval (a spot's cone, a beam's box), "
           "sampled evenly in the angle seen from a point or spot light with the falloff integrated exactly, and "
           "with more samples where the piece sweeps a gobo or passes beside the light (lattice: ξ stays sampled)"},
          {"clip", T::boolean, 1, 0, 1, {},
           "clip the planes to the light's influence volume (a pyramid around a spot's cone, a beam's box), so "
           "fragments outside it are never shaded (Nilsson 3.1)"}};
}

PlaneSettings PlaneSettings::from(const Settings& s) {
  enum class Sampling { lit, plane };  // the `sampling` setting's choices, in order
  return {s.integer("planes"), s.real("spacing"), s.integer("lattice"), s.option<kit::Jitter>("jitter"),
          s.option<Sampling>("sampling") == Sampling::lit, s.boolean("clip")};
}

void PlanePass::prepare(const Scene& scene) {
  const std::vector<float> offsets = settings_.jitter == kit::Jitter::blue ? kit::blue_noise() : kit::white_noise();
  noise_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32F, kit::noise_size, kit::noise_size);
  glTextureSubImage2D(noise_.id(), 0, 0, 0, kit::noise_size, kit::noise_size, GL_RED, GL_FLOAT, offsets.data());
  const std::vector<GLuint> indices = lattice_indices(std::max(settings_.lattice, 1));
  index_count_ = static_cast<int>(indices.size());
  indices_ = gpu::make_buffer(indices.size() * sizeof(GLuint), indices.data());
  mesh_ = gpu::make_vertex_array();  // no attributes: vertices come from gl_VertexID
  glVertexArrayElementBuffer(mesh_.id(), indices_.id());
  fbo_ = gpu::make_framebuffer();
  if (epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query")) {
    GLuint id = 0;
    glGenQueries(1, &id);  // Mesa's glCreateQueries refuses the statistics targets
    invocations_ = gpu::Query(id);
  }
  regions_.prepare(scene);
}

PlanePass::Slabs PlanePass::slabs(const kit::LightBounds& volume) const {
  const double depth = kit::lit_far_depth(volume, camera_, far_);
  if (!(depth > 0.0)) return {};
  const int count = settings_.spacing > 0.0 ? static_cast<int>(std::ceil(depth / settings_.spacing)) : settings_.planes;
  const int n = std::clamp(count, 1, max_planes);
  return {n, static_cast<float>(depth / n)};
}

void PlanePass::run(const kit::SceneFrame& frame, const gpu::Texture& target) {
  regions_.update(frame.inputs());
  camera_ = geometry::camera_basis(frame.inputs().camera);
  far_ = frame.inputs().camera.far;
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(target.id(), 0, GL_RGBA, GL_FLOAT, zero);
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, frame.depth().id(), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, frame.width(), frame.height());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);  // the scene's depth is only tested against
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  for (GLenum c = 0; c < 8; ++c) glEnable(GL_CLIP_DISTANCE0 + c);
  cos_edge_ = corner_cos(camera_.tan_half_fov_y, double(frame.width()) / frame.height());
  glBindTextureUnit(jitter_unit, noise_.id());
  glBindVertexArray(mesh_.id());
  planes_drawn_ = 0.0;
  if (invocations_) glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, invocations_.id());
  for (int i = 0; i < static_cast<int>(regions_.bounds().size()); ++i) draw_light(frame, i, regions_.bounds()[i]);
  if (invocations_) {
    glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    GLuint64 count = 0;
    glGetQueryObjectui64v(invocations_.id(), GL_QUERY_RESULT, &count);
    fragments_ = static_cast<double>(count);
  }
  for (GLenum c = 0; c < 8; ++c) glDisable(GL_CLIP_DISTANCE0 + c);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Light `light`'s program: its index and the settings as constants (planes.frag.glsl).
std::string PlanePass::defines(int light) const {
  std::string d = "#define BINDING_JITTER " + std::to_string(jitter_unit) + "\n#define PLANE_LIGHT " +
                  std::to_string(light) + "\n";
  if (settings_.lattice > 0) d += "#define LATTICE_XI\n";
  if (settings_.jitter != kit::Jitter::none) d += "#define JITTER\n";
  if (settings_.lit_sampling) d += "#define LIT_SAMPLING\n";
  return d;
}

void PlanePass::draw_light(const kit::SceneFrame& frame, int light, const kit::LightBounds& volume) {
  const Slabs s = slabs(volume);
  if (s.count == 0) return;
  const std::vector<glm::vec4> clip = settings_.clip ? volume.clip : std::vector<glm::vec4>{};
  const gpu::Program& program = gpu::cached_program(
      {{GL_VERTEX_SHADER, "methods/planes/planes.vert.glsl"}, {GL_FRAGMENT_SHADER, "methods/planes/planes.frag.glsl"}},
      frame.defines() + defines(light));
  glUseProgram(program.id());
  gpu::set_uniform(program, "lattice", std::max(settings_.lattice, 1));
  gpu::set_uniform(program, "dz", s.dz);
  gpu::set_uniform(program, "clip_planes", clip);
  gpu::set_uniform(program, "clip_count", static_cast<int>(clip.size()));
  // A sample lies anywhere in its slab, up to dz/2 in depth, i.e. dz/(2 cos)
  // along its ray, from the middle where the clip distances are taken.
  gpu::set_uniform(program, "clip_margin", 0.5f * s.dz / cos_edge_);
  glDrawElementsInstanced(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr, s.count);
  planes_drawn_ += s.count;
}

}  // namespace airlight::methods
