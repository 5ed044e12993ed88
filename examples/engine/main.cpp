// An engine's frame with airlight's light shafts in it. The "engine" here draws
// the scene with its own conventions — reversed-Z depth with an infinite far
// plane, its own shadow-map projections and bias, its own surface shading —
// then hands its depth buffer and shadow maps to airlight through
// <airlight/engine.hpp>; airlight turns the engine's colour L_surf into
// L_surf·T + L_air. It writes L_air and that composite as PFM.
//
//   engine_example [--builtin NAME | --scene FILE.json] [--size WxH]
//                  [--method NAME] [--set key=value]...
//                  [--out-airlight FILE.pfm] [--out-composite FILE.pfm]
// Defaults: teapot_spot, 640x480, raymarch with steps=256 sampling=equiangular.
#include <airlight/engine.hpp>
#include <airlight/error.hpp>
#include <airlight/method.hpp>
#include <airlight/scene.hpp>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr int max_spots = 4;            // the surface shader's light slots
constexpr int shadow_resolution = 2048;

// A headless GL 4.5 core context on Mesa's surfaceless EGL platform: no
// display, no window; everything renders into framebuffer objects.
void make_context() {
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr) || !eglBindAPI(EGL_OPENGL_API))
    throw std::runtime_error("no surfaceless EGL display (Mesa's EGL is needed)");
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    throw std::runtime_error("no OpenGL 4.5 core context");
}

void check_gl(const char* where) {
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    char text[96];
    std::snprintf(text, sizeof text, "OpenGL error 0x%04x in %s", error, where);
    throw std::runtime_error(text);
  }
}

GLuint compile(const std::vector<std::pair<GLenum, const char*>>& stages) {
  const GLuint program = glCreateProgram();
  for (const auto& [type, source] : stages) {
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    glAttachShader(program, shader);
    glDeleteShader(shader);  // freed with the program
  }
  glLinkProgram(program);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader: ") + log);
  }
  return program;
}

const char* const vertex_shader = R"(#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 view_projection;
out vec3 world_position, world_normal;
void main() {
  world_position = position;  // the scene's meshes are in world space
  world_normal = normal;
  gl_Position = view_projection * vec4(position, 1.0);
})";

// The engine's own shading: Lambert from each spot, hard cone, hardware PCF.
const char* const surface_shader = R"(#version 450 core
in vec3 world_position, world_normal;
out vec4 colour;
uniform vec3 albedo, ambient;
uniform int spot_count;
uniform vec3 spot_position[4], spot_direction[4], spot_intensity[4];
uniform float spot_cos_cone[4];
uniform mat4 spot_shadow[4];
uniform sampler2DShadow shadow_maps[4];
void main() {
  vec3 n = normalize(world_normal), radiance = ambient * albedo;
  for (int i = 0; i < spot_count; ++i) {
    vec3 to_light = spot_position[i] - world_position;
    float r2 = dot(to_light, to_light);
    vec3 l = to_light * inversesqrt(r2);
    vec4 clip = spot_shadow[i] * vec4(world_position, 1.0);
    vec3 window = clip.xyz / clip.w * 0.5 + 0.5;  // the shadow maps use GL's default -1..1 depth
    float lit = texture(shadow_maps[i], window) * step(spot_cos_cone[i], dot(-l, spot_direction[i]));
    radiance += albedo / 3.14159265 * spot_intensity[i] * max(dot(n, l), 0.0) / r2 * lit;
  }
  colour = vec4(radiance, 1.0);
})";

struct GpuMesh {
  GLuint vertex_array = 0;
  GLsizei indices = 0;
  glm::vec3 albedo{0.0f};
};

GpuMesh upload(const airlight::Mesh& mesh) {
  GpuMesh m{0, static_cast<GLsizei>(3 * mesh.triangles.size()), mesh.albedo};
  GLuint buffers[3];
  glCreateBuffers(3, buffers);
  glNamedBufferStorage(buffers[0], mesh.positions.size() * sizeof(glm::vec3), mesh.positions.data(), 0);
  glNamedBufferStorage(buffers[1], mesh.normals.size() * sizeof(glm::vec3), mesh.normals.data(), 0);
  glNamedBufferStorage(buffers[2], mesh.triangles.size() * sizeof(glm::uvec3), mesh.triangles.data(), 0);
  glCreateVertexArrays(1, &m.vertex_array);
  for (GLuint a = 0; a < 2; ++a) {
    glVertexArrayVertexBuffer(m.vertex_array, a, buffers[a], 0, sizeof(glm::vec3));
    glVertexArrayAttribFormat(m.vertex_array, a, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(m.vertex_array, a, a);
    glEnableVertexArrayAttrib(m.vertex_array, a);
  }
  glVertexArrayElementBuffer(m.vertex_array, buffers[2]);
  return m;
}

GLuint texture_2d(GLenum format, int width, int height) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, width, height);
  return texture;
}

// Reversed-Z with an infinite far plane: window depth = near / view depth, 1 at
// the near plane, 0 at infinity. The frustum's sides are airlight's camera's:
// pixel (i, j) looks through ((i + 0.5)/W, (j + 0.5)/H) of the image plane.
glm::mat4 reversed_infinite_projection(const airlight::Camera& camera, int width, int height) {
  const float t = std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  glm::mat4 p(0.0f);
  p[0][0] = 1.0f / (t * aspect);
  p[1][1] = 1.0f / t;
  p[2][3] = -1.0f;  // clip w = view depth
  p[3][2] = camera.near;
  return p;
}

// The engine's shadow camera of a spot: a square frustum a little wider than
// the cone, from a near plane of its own to the far side of the scene.
std::optional<airlight::EngineShadow> spot_shadow_camera(const airlight::Light& light, glm::vec3 lo, glm::vec3 hi) {
  const float half_angle = light.cone_deg + light.edge_deg + 5.0f;
  if (light.type != airlight::LightType::spot || half_angle > 80.0f) return std::nullopt;  // airlight draws it
  float far = 1.0f;
  for (int c = 0; c < 8; ++c)
    far = std::max(far, glm::distance(light.position, glm::vec3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y,
                                                                   c & 4 ? hi.z : lo.z)));
  const glm::vec3 up = std::abs(light.direction.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  airlight::EngineShadow s;
  s.view = glm::lookAt(light.position, light.position + light.direction, up);
  s.projection = glm::perspective(glm::radians(2.0f * half_angle), 1.0f, 0.1f, 1.01f * far);
  s.range = airlight::DepthRange::negative_one_to_one;
  s.texture = texture_2d(GL_DEPTH_COMPONENT32F, shadow_resolution, shadow_resolution);
  // Set for the engine's hardware PCF; airlight reads the map as it is.
  glTextureParameteri(s.texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(s.texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(s.texture, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(s.texture, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glTextureParameteri(s.texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(s.texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return s;
}

void draw(const std::vector<GpuMesh>& meshes, GLuint program) {
  for (const GpuMesh& m : meshes) {
    glProgramUniform3fv(program, glGetUniformLocation(program, "albedo"), 1, glm::value_ptr(m.albedo));
    glBindVertexArray(m.vertex_array);
    glDrawElements(GL_TRIANGLES, m.indices, GL_UNSIGNED_INT, nullptr);
  }
}

// PFM: linear float RGB, bottom row first — GL's row order, so no flip.
void write_pfm(GLuint texture, int width, int height, const std::string& file) {
  std::vector<float> rgb(3 * static_cast<size_t>(width) * height);
  glGetTextureImage(texture, 0, GL_RGB, GL_FLOAT, static_cast<GLsizei>(rgb.size() * sizeof(float)), rgb.data());
  FILE* out = std::fopen(file.c_str(), "wb");
  if (!out) throw std::runtime_error("cannot write " + file);
  std::fprintf(out, "PF\n%d %d\n-1.0\n", width, height);  // negative scale: little-endian
  const size_t written = std::fwrite(rgb.data(), sizeof(float), rgb.size(), out);
  if (std::fclose(out) != 0 || written != rgb.size()) throw std::runtime_error("cannot write " + file);
}

struct Options {
  std::string scene_file, builtin = "teapot_spot", method = "raymarch";
  std::vector<std::string> settings{"steps=256", "sampling=equiangular"};
  int width = 640, height = 480;
  std::string out_airlight = "airlight.pfm", out_composite = "composite.pfm";
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 == argc) throw airlight::InputError(arg, "", "a value is missing");
    const std::string value = argv[++i];
    if (arg == "--scene") o.scene_file = value;
    else if (arg == "--builtin") o.builtin = value;
    else if (arg == "--method") o.method = value;
    else if (arg == "--set") o.settings.push_back(value);  // later ones win
    else if (arg == "--out-airlight") o.out_airlight = value;
    else if (arg == "--out-composite") o.out_composite = value;
    else if (arg != "--size") throw airlight::InputError(arg, "", "unknown option");
    else if (std::sscanf(value.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 1 || o.height < 1)
      throw airlight::InputError(arg, "", "expected WxH, got " + value);
  }
  return o;
}

void run(const Options& o) {
  make_context();
  const airlight::Scene scene = o.scene_file.empty() ? airlight::builtin_scene(o.builtin, "--builtin")
                                                     : airlight::load_scene(o.scene_file);
  const int w = o.width, h = o.height;
  const airlight::FrameInputs inputs = airlight::frame_inputs(scene, w, h);

  std::vector<GpuMesh> meshes;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const airlight::Mesh& mesh : scene.meshes) {
    meshes.push_back(upload(mesh));
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  const GLuint depth_only = compile({{GL_VERTEX_SHADER, vertex_shader}});
  const GLuint shaded = compile({{GL_VERTEX_SHADER, vertex_shader}, {GL_FRAGMENT_SHADER, surface_shader}});
  GLuint framebuffer = 0;
  glCreateFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glEnable(GL_DEPTH_TEST);

  // 1. Shadow maps of the spots: GL's default depth range, depth test LESS and
  //    a slope-scaled bias of the engine's choosing.
  std::vector<std::optional<airlight::EngineShadow>> shadows;
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glDepthFunc(GL_LESS);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  glViewport(0, 0, shadow_resolution, shadow_resolution);
  int spots = 0;
  for (const airlight::Light& light : inputs.lights) {
    shadows.push_back(spots < max_spots ? spot_shadow_camera(light, lo, hi) : std::nullopt);
    auto& s = shadows.back();
    if (!s) continue;
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, s->texture, 0);
    glNamedFramebufferDrawBuffer(framebuffer, GL_NONE);
    glClear(GL_DEPTH_BUFFER_BIT);
    const glm::mat4 light_view_projection = s->projection * s->view;
    glProgramUniformMatrix4fv(depth_only, glGetUniformLocation(depth_only, "view_projection"), 1, GL_FALSE,
                              glm::value_ptr(light_view_projection));
    glUseProgram(depth_only);
    draw(meshes, depth_only);
    // The surface shader's slot for this spot.
    auto uniform = [&](const std::string& name) {
      return glGetUniformLocation(shaded, (name + "[" + std::to_string(spots) + "]").c_str());
    };
    glProgramUniform3fv(shaded, uniform("spot_position"), 1, glm::value_ptr(light.position));
    glProgramUniform3fv(shaded, uniform("spot_direction"), 1, glm::value_ptr(glm::normalize(light.direction)));
    glProgramUniform3fv(shaded, uniform("spot_intensity"), 1, glm::value_ptr(light.intensity));
    glProgramUniform1f(shaded, uniform("spot_cos_cone"), std::cos(glm::radians(light.cone_deg)));
    glProgramUniformMatrix4fv(shaded, uniform("spot_shadow"), 1, GL_FALSE, glm::value_ptr(light_view_projection));
    glProgramUniform1i(shaded, uniform("shadow_maps"), spots);
    glBindTextureUnit(spots++, s->texture);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  check_gl("shadow maps");

  // 2. The camera's view: reversed-Z into the engine's own depth and colour.
  airlight::EngineDepth depth;
  depth.texture = texture_2d(GL_DEPTH_COMPONENT32F, w, h);
  const airlight::Camera& camera = inputs.camera;
  depth.view = glm::lookAt(camera.position, camera.look_at, camera.up);
  depth.projection = reversed_infinite_projection(camera, w, h);
  depth.range = airlight::DepthRange::zero_to_one;
  const GLuint color = texture_2d(GL_RGBA16F, w, h);
  glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, depth.texture, 0);
  glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, color, 0);
  glNamedFramebufferDrawBuffer(framebuffer, GL_COLOR_ATTACHMENT0);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDepthFunc(GL_GREATER);
  const float far_depth = 0.0f, black[4] = {0, 0, 0, 1};
  glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &far_depth);
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, black);
  glViewport(0, 0, w, h);
  const glm::mat4 view_projection = depth.projection * depth.view;
  glProgramUniformMatrix4fv(shaded, glGetUniformLocation(shaded, "view_projection"), 1, GL_FALSE,
                            glm::value_ptr(view_projection));
  glProgramUniform3fv(shaded, glGetUniformLocation(shaded, "ambient"), 1, glm::value_ptr(scene.ambient));
  glProgramUniform1i(shaded, glGetUniformLocation(shaded, "spot_count"), spots);
  glUseProgram(shaded);
  draw(meshes, shaded);
  check_gl("surfaces");

  // 3. airlight's shafts from the engine's depth and shadow maps: L_air and
  //    T(d) into the engine's textures, and colour becomes L_surf·T + L_air.
  airlight::use_current_gl_context();
  const airlight::MethodInfo& info = airlight::find_method(o.method, "--method");
  airlight::Settings settings(info.settings);
  for (const std::string& assignment : o.settings) settings.set(assignment, "--set");
  const std::unique_ptr<airlight::Method> method = info.create(settings);
  method->prepare(scene);
  airlight::EngineFrame frame;
  frame.depth = depth;
  frame.shadows = shadows;
  frame.target.airlight = texture_2d(GL_RGBA32F, w, h);
  frame.target.transmittance = texture_2d(GL_RGBA32F, w, h);
  frame.target.color = color;
  method->render_frame(inputs, frame);
  check_gl("airlight");

  write_pfm(frame.target.airlight, w, h, o.out_airlight);
  write_pfm(color, w, h, o.out_composite);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    run(parse(argc, argv));
    return 0;
  } catch (const airlight::InputError& e) {
    std::fprintf(stderr, "engine_example: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engine_example: error: %s\n", e.what());
    return 1;
  }
}
