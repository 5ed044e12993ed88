#include "view/viewer.hpp"

#include "app/contact_sheet.hpp"
#include "app/method_settings.hpp"
#include "app/output_check.hpp"
#include "core/metrics.hpp"
#include "core/image_io.hpp"
#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "view/camera_control.hpp"

#include <airlight/engine.hpp>
#include <airlight/error.hpp>

#define GLFW_INCLUDE_NONE  // epoxy provides GL
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <thread>

namespace airlight::view {

struct Viewer::Targets {
  int width = 0, height = 0;
  gpu::Texture airlight, surface;  // RGBA32F: what the method writes through EngineTarget

  void fit(int w, int h) {
    if (w == width && h == height) return;
    width = w;
    height = h;
    airlight = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, w, h);
    surface = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, w, h);
  }
};

namespace {

// How long after the last camera move the reduced size is kept: mouse drags
// deliver moves every frame or two, so a pause shorter than this is still moving.
constexpr std::chrono::milliseconds settle_time{250};

std::string glfw_error;

void remember_glfw_error(int, const char* description) { glfw_error = description; }

// GLFW needs an X display (or Wayland); without one there is no window to open.
void init_glfw() {
  glfwSetErrorCallback(remember_glfw_error);
  if (glfwInit()) return;
  throw Failure("view: no display to open a window on (" + glfw_error +
                "); run it under a virtual X server: xvfb-run -s \"-screen 0 1280x800x24\" airlight view ...");
}

GLFWwindow* open_window(int width, int height) {
  init_glfw();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(width, height, "airlight view", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw Failure("view: no OpenGL 4.5 core window (" + glfw_error +
                  "); Mesa's llvmpipe gives one on any X server, e.g. under xvfb-run");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(0);  // measure the method, not the display's refresh
  return window;
}

// A hidden window whose context shares `window`'s objects, for the thread that
// links programs ahead (gpu::link_ahead): a new method's first frame links its
// largest programs beside its earlier passes. nullptr if the system gives none:
// programs are then linked in place.
GLFWwindow* open_worker_window(GLFWwindow* window) {
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  GLFWwindow* worker = glfwCreateWindow(1, 1, "airlight worker", nullptr, window);
  glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
  return worker;
}

// An image as an RGBA32F texture (GL's rows bottom first).
gpu::Texture upload(const Image& image) {
  gpu::Texture texture = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, image.width, image.height);
  std::vector<glm::vec3> rows;
  rows.reserve(image.pixels.size());
  for (int y = image.height - 1; y >= 0; --y)
    for (int x = 0; x < image.width; ++x) rows.push_back(image.at(x, y));
  glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGB, GL_FLOAT, rows.data());
  return texture;
}

// |method − reference|, the largest over RGB, through inferno up to `top` (as compare's heat maps).
Image heat_map(const Image& method, const Image& reference, double top) {
  Image heat(method.width, method.height);
  for (size_t k = 0; k < heat.pixels.size(); ++k) {
    const glm::vec3 d = glm::abs(method.pixels[k] - reference.pixels[k]);
    heat.pixels[k] = glm::vec3(app::inferno(std::max({d.r, d.g, d.b}) / top));
  }
  return heat;
}

bool same_view(const Camera& a, const Camera& b) {
  return a.position == b.position && a.look_at == b.look_at && a.fov_y_deg == b.fov_y_deg;
}

}  // namespace

std::vector<std::string> viewer_methods() {
  std::vector<std::string> names;
  // The CPU reference renders seconds per frame: the issue keeps it to the background.
  for (const MethodInfo& m : registered_methods())
    if (!m.capabilities.ground_truth) names.push_back(m.name);
  return names;
}

namespace {

// Throws InputError(source, name) for an unknown method or the CPU reference.
const MethodInfo& viewer_method(const std::string& name, const std::string& source) {
  const MethodInfo& info = find_method(name, "--method");
  const auto methods = viewer_methods();
  if (std::find(methods.begin(), methods.end(), info.name) == methods.end())
    throw InputError(source, info.name, "the viewer shows GPU methods; the CPU reference renders only for the error view");
  return info;
}

}  // namespace

Viewer::Viewer(ViewOptions options)
    : options_(std::move(options)), scene_(options_.scene), full_(std::make_unique<Targets>()),
      reduced_(std::make_unique<Targets>()) {
  const MethodInfo& info = viewer_method(options_.method, "--method");
  const Settings settings = app::method_settings(info, options_.assignments);
  window_ = open_window(options_.width, options_.height);
  use_current_gl_context();
  if ((worker_window_ = open_worker_window(window_)))
    gpu::Context::current().give_worker({[w = worker_window_] { glfwMakeContextCurrent(w); },
                                         [] { glfwMakeContextCurrent(nullptr); }});
  display_ = std::make_unique<Display>();
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
  inputs_ = frame_inputs(scene_, options_.width, options_.height);
  last_camera_ = inputs_.camera;
  last_frame_ = std::chrono::steady_clock::now();
  create_method(info.name, settings);
}

Viewer::~Viewer() {
  reference_.reset();
  method_.reset();  // its GL objects go while the context is current
  full_.reset();
  reduced_.reset();
  display_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  gpu::stop_linking();  // the worker lets its context go before its window goes
  gpu::Context::current().give_worker({});
  if (worker_window_) glfwDestroyWindow(worker_window_);
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::pair<int, int> Viewer::shown_size() const {
  return shown_ ? std::pair{shown_->width, shown_->height} : std::pair{0, 0};
}

bool Viewer::open() const { return !glfwWindowShouldClose(window_); }

void Viewer::quit() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Viewer::create_method(const std::string& name, const Settings& settings) {
  const MethodInfo& info = find_method(name, "--method");
  app::check_limits(scene_, {&info, &settings});  // before the method's work, as the command checks it
  auto method = info.create(settings);
  method->prepare(scene_);
  method_ = std::move(method);
  method_name_ = info.name;
  settings_ = settings;
  widgets_ = setting_widgets(info.settings);
  ++method_generation_;
  status_ = "prepared " + method_name_;
}

void Viewer::switch_method(const std::string& name) {
  const MethodInfo& info = viewer_method(name, "method");
  create_method(info.name, Settings(info.settings));
}

void Viewer::set_setting(const std::string& label, const std::string& value) {
  Settings changed = settings_;
  set_widget(widgets_, changed, label, value);
  create_method(method_name_, changed);
}

void Viewer::frame() {
  // Nothing to redraw and no reference running: wait for input rather than spin.
  const bool waiting = idle_ && !(reference_ && !reference_->finished());
  waiting ? glfwWaitEventsTimeout(0.1) : glfwPollEvents();
  const auto now = std::chrono::steady_clock::now();
  frame_s_ = std::chrono::duration<double>(now - last_frame_).count();
  last_frame_ = now;
  ++frames_;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (options_.interactive) handle_input(static_cast<float>(frame_s_));
  if (!same_view(inputs_.camera, last_camera_)) last_move_ = now;
  last_camera_ = inputs_.camera;

  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  if (width < 1 || height < 1) return;  // minimized
  render_if_changed(width, height, progressive_ && now - last_move_ < settle_time);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  draw_image(width, height);
  draw_panels();
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (!window_capture_.empty()) write_window(width, height);
  glfwSwapBuffers(window_);
}

// Renders unless the last frame already shows these inputs at this size with
// this method (a person looking at a still view); a script renders every frame,
// so that `measure` times the method at rest.
void Viewer::render_if_changed(int width, int height, bool moving) {
  const float scale = moving ? moving_scale_ : 1.0f;
  const int w = std::max(1, static_cast<int>(std::lround(width * scale)));
  const int h = std::max(1, static_cast<int>(std::lround(height * scale)));
  Targets& target = moving ? *reduced_ : *full_;
  const std::uint64_t key = view_key(inputs_, w, h);
  idle_ = options_.interactive && key == rendered_key_ && method_generation_ == rendered_generation_ &&
          shown_ == &target;
  try {
    if (!idle_) {
      rendered_key_ = key;
      rendered_generation_ = method_generation_;
      render(w, h, target);
    }
    update_reference(width, height);
  } catch (const std::runtime_error& e) {
    report(e);
  }
}

// The method's frame into the viewer's textures at width × height, through the
// engine path: L_air and airlight's own L_surf·T(d), nothing read back.
void Viewer::render(int width, int height, Targets& target) {
  target.fit(width, height);
  FrameInputs inputs = inputs_;
  inputs.width = width;
  inputs.height = height;
  inputs.surface = true;
  EngineFrame engine;
  engine.target.airlight = target.airlight.id();
  engine.target.surface = target.surface.id();
  const auto start = std::chrono::steady_clock::now();
  shown_ = nullptr;  // until this frame is complete
  method_->render_frame(inputs, engine);
  glFinish();  // the frame's time is until its last pixel
  render_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  numbers_ = method_->numbers();  // the GPU is idle: this frame's, as render_s_
  shown_ = &target;
}

void Viewer::handle_mouse() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) return;
  // The split view's divider is grabbed within 6 pixels; elsewhere a drag turns the camera.
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_divider_ = false;
  if (error_view_ == ErrorView::split && ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
      std::abs(io.MousePos.x - divider_ * io.DisplaySize.x) < 6.0f)
    dragging_divider_ = true;
  if (dragging_divider_) {
    divider_ = std::clamp(io.MousePos.x / io.DisplaySize.x, 0.0f, 1.0f);
    return;
  }
  Camera& camera = inputs_.camera;
  const glm::vec2 d(io.MouseDelta.x, io.MouseDelta.y);
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) camera = orbit(camera, 0.3f * d.x, 0.3f * d.y);
  if (ImGui::IsMouseDown(ImGuiMouseButton_Right)) camera = look(camera, -0.2f * d.x, -0.2f * d.y);
  if (io.MouseWheel != 0.0f) camera = dolly(camera, std::pow(0.9f, io.MouseWheel));
}

void Viewer::handle_input(float dt) {
  const ImGuiIO& io = ImGui::GetIO();
  Camera& camera = inputs_.camera;
  handle_mouse();
  if (io.WantCaptureKeyboard) return;
  auto key = [&](int k) { return glfwGetKey(window_, k) == GLFW_PRESS ? 1.0f : 0.0f; };
  const glm::vec3 move(key(GLFW_KEY_D) - key(GLFW_KEY_A), key(GLFW_KEY_E) - key(GLFW_KEY_Q),
                       key(GLFW_KEY_W) - key(GLFW_KEY_S));
  // Metres per second: a tenth of the distance to the target, so small and large scenes both fly.
  const float speed = 0.5f * glm::distance(camera.position, camera.look_at) * (key(GLFW_KEY_LEFT_SHIFT) ? 4.0f : 1.0f);
  if (move != glm::vec3(0.0f)) camera = fly(camera, move * speed * std::min(dt, 0.1f));
}

void Viewer::screenshot(const std::filesystem::path& file) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  render(width, height, *full_);  // full size, whatever the last frame was
  FrameImages images;
  images.airlight = gpu::read_image(shown_->airlight, width, height);
  images.surface = gpu::read_image(shown_->surface, width, height);
  write_image(select_pass(images, pass_), file, tone_);
  status_ = "wrote " + file.string();
}

// ---- the error against the reference --------------------------------------------

// A reference of the view as it is now: started once the view rests at full
// size, cancelled when it moves or changes, compared when done.
void Viewer::update_reference(int width, int height) {
  if (error_view_ == ErrorView::off || shown_ != full_.get()) {
    reference_.reset();
    compared_.clear();
    return;
  }
  const std::uint64_t key = view_key(inputs_, width, height);
  if (!reference_ || key != reference_key_) {
    reference_.reset();  // cancels the old view's
    reference_ = std::make_unique<ReferenceJob>(posed_scene(scene_, inputs_), width, height);
    reference_key_ = key;
    compared_.clear();
  }
  if (!reference_->finished()) return;
  if (!reference_->error().empty()) throw Failure("reference: " + reference_->error());
  compare_with_reference(width, height);
}

// The method's full-size frame read back once per method, settings and pass.
std::string Viewer::comparison() const {
  return method_name_ + " " + settings_.describe() + " pass " + std::to_string(static_cast<int>(pass_));
}

void Viewer::compare_with_reference(int width, int height) {
  const std::string what = comparison();
  if (what == compared_) return;
  FrameImages frame;
  frame.airlight = gpu::read_image(full_->airlight, width, height);
  frame.surface = gpu::read_image(full_->surface, width, height);
  const Image method = select_pass(frame, pass_);
  const reference::Images& r = reference_->images();
  const Image& reference = pass_ == Pass::airlight ? r.airlight : pass_ == Pass::surface ? r.surface : r.composite;
  rel_rmse_ = compare_images(method, reference).rel_rmse;
  const app::HeatScale scale = app::heat_scale({{"reference", "", "", 0.0, 0.0, &reference},
                                                {method_name_, "", "", 0.0, 0.0, &method}});
  heat_scale_ = app::describe(scale);
  heat_ = upload(heat_map(method, reference, scale.top));
  reference_airlight_ = upload(r.airlight);
  reference_surface_ = upload(r.surface);
  compared_ = what;
}

void Viewer::draw_image(int width, int height) {
  if (!shown_) return;
  const bool compared = !compared_.empty();
  if (error_view_ == ErrorView::heat && compared) {
    display_->draw_display_values(heat_.id(), 0, 0, width, height);
    return;
  }
  display_->draw(shown_->airlight.id(), shown_->surface.id(), 0, 0, width, height, pass_, tone_);
  if (error_view_ != ErrorView::split || !compared) return;
  const int x = static_cast<int>(std::lround(divider_ * width));
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, 0, width - x, height);
  display_->draw(reference_airlight_.id(), reference_surface_.id(), 0, 0, width, height, pass_, tone_);
  glDisable(GL_SCISSOR_TEST);
  ImGui::GetBackgroundDrawList()->AddLine(ImVec2(static_cast<float>(x), 0.0f),
                                          ImVec2(static_cast<float>(x), static_cast<float>(height)),
                                          IM_COL32(255, 255, 255, 160));
}

double Viewer::wait_for_reference() {
  if (error_view_ == ErrorView::off) error_view_ = ErrorView::split;
  for (frame(); compared_ != comparison(); frame())
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // leave the worker the cores
  return rel_rmse_;
}

void Viewer::save_window(const std::filesystem::path& file) {
  window_capture_ = file;
  frame();
}

// The back buffer holds display values; decoded to linear, they come back
// through the PNG writer's clamp curve as they were (within 8-bit rounding).
void Viewer::write_window(int width, int height) {
  std::vector<unsigned char> rgb(3 * static_cast<size_t>(width) * height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, height - 1 - y)[c] = srgb_to_linear(rgb[3 * (static_cast<size_t>(y) * width + x) + c] / 255.0f);
  write_image(image, window_capture_, ToneMap{1.0f, ToneCurve::clamp});
  window_capture_.clear();
}

void Viewer::save_scene(const std::filesystem::path& file) const {
  airlight::save_scene(posed_scene(scene_, inputs_), file);
}

// Called from a catch block: a script stops at the first error (rethrown), a
// person sees it in the panel and keeps the last good image.
void Viewer::report(const std::exception& e) {
  if (!options_.interactive) throw;
  status_ = e.what();
}

}  // namespace airlight::view
