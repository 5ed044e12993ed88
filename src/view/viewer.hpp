#pragma once
// `airlight view` (docs/design.md §5): a GLFW window with an OpenGL 4.5 core
// context in which a GPU method renders every frame through the engine path
// (use_current_gl_context, render_frame into the viewer's textures: nothing is
// read back per frame), tone-mapped to the window, with Dear ImGui panels that
// edit the camera, the lights, the medium, the method and its settings. Every
// edit is a FrameInputs change for the next frame; only a new method or new
// settings re-create and re-prepare it. The script (view/script.hpp) drives the
// same operations the panels do.
#include "gpu/gl.hpp"
#include "view/display.hpp"
#include "view/reference_job.hpp"
#include "view/setting_widgets.hpp"

#include "core/tonemap.hpp"
#include <airlight/method.hpp>
#include <airlight/scene.hpp>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace airlight::view {

struct ViewOptions {
  Scene scene;
  std::string method = "raymarch";
  std::vector<std::string> assignments;  // "key=value" for the first method
  int width = 1024, height = 768;
  bool interactive = true;  // false: a script drives it, errors end it
};

// The methods the viewer can switch to: every registered GPU method (the CPU
// reference only renders in the background).
std::vector<std::string> viewer_methods();

class Viewer {
public:
  // Opens the window and prepares the method. Throws Failure saying how to run
  // under Xvfb when there is no display.
  explicit Viewer(ViewOptions options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  bool open() const;  // until the window is closed or quit()
  void quit();
  // One frame: input, the method's render at the internal size, the display, the panels.
  void frame();

  // What the panels and the script change.
  FrameInputs& inputs() { return inputs_; }
  const std::string& method() const { return method_name_; }
  // The size the shown frame was rendered at (reduced while the camera moves).
  std::pair<int, int> shown_size() const;
  void switch_method(const std::string& name);
  void set_setting(const std::string& label, const std::string& value);
  void set_pass(Pass pass) { pass_ = pass; }
  ToneMap& tone() { return tone_; }
  void reset_camera() { inputs_.camera = scene_.camera; }
  // The image shown at full size: PNG tone-mapped as the window shows it, EXR or PFM linear.
  void screenshot(const std::filesystem::path& file);
  // The next frame as the window shows it, panels included, as PNG.
  void save_window(const std::filesystem::path& file);
  // The scene as edited (camera, lights, medium) as airlight-scene/1 JSON.
  void save_scene(const std::filesystem::path& file) const;

  // The error against the reference (rendered in the background once the view
  // rests): the reference right of a divider, or a heat map of |method − reference|.
  enum class ErrorView { off, split, heat };
  void set_error_view(ErrorView view) { error_view_ = view; }
  // Draws frames until the reference of this view is done; the shown pass's rRMSE against it.
  double wait_for_reference();

private:
  struct Targets;
  void create_method(const std::string& name, const Settings& settings);
  void handle_input(float dt);
  void handle_mouse();
  void update_reference(int width, int height);
  std::string comparison() const;  // what the error is of: method, settings, pass
  void compare_with_reference(int width, int height);
  void draw_image(int width, int height);
  void error_panel();
  void write_window(int width, int height);
  void render_if_changed(int width, int height, bool moving);
  void render(int width, int height, Targets& target);
  void draw_panels();
  void camera_panel();
  void light_panel();
  void medium_panel();
  void method_panel();
  void numbers_panel();
  void capture_panel();
  void report(const std::exception& e);

  ViewOptions options_;
  Scene scene_;  // as loaded: what methods are prepared with and the camera resets to
  FrameInputs inputs_;
  GLFWwindow* window_ = nullptr;
  GLFWwindow* worker_window_ = nullptr;  // its context links programs ahead (open_worker_window)
  std::unique_ptr<Display> display_;
  std::unique_ptr<Targets> full_, reduced_;
  const Targets* shown_ = nullptr;

  std::string method_name_;
  Settings settings_;
  std::vector<SettingWidget> widgets_;
  std::unique_ptr<Method> method_;
  int method_generation_ = 0;  // counts re-creations: new method or settings
  Pass pass_ = Pass::composite;
  ToneMap tone_;

  // Progressive rendering: the reduced size while the camera moves.
  bool progressive_ = true;
  float moving_scale_ = 0.5f;
  std::chrono::steady_clock::time_point last_move_{};
  Camera last_camera_;
  // What the shown frame was rendered from; idle_: this frame rendered nothing.
  std::uint64_t rendered_key_ = 0;
  int rendered_generation_ = -1;
  bool idle_ = false;

  ErrorView error_view_ = ErrorView::off;
  std::unique_ptr<ReferenceJob> reference_;
  std::uint64_t reference_key_ = 0;
  gpu::Texture reference_airlight_, reference_surface_, heat_;
  std::string compared_;  // the method, settings and pass the error shows; empty: not compared yet
  double rel_rmse_ = 0.0;
  std::string heat_scale_;
  float divider_ = 0.5f;
  bool dragging_divider_ = false;

  int selected_light_ = 0;
  std::int64_t frames_ = 0;  // the window's frames shown, which frame_s_ ends
  double frame_s_ = 0.0, render_s_ = 0.0;
  FrameNumbers numbers_;  // its `frame` is the method's (FrameNumbers), which render_s_ timed too
  std::string status_;
  std::filesystem::path window_capture_;  // written by the next frame before it is swapped
  char screenshot_path_[256] = "airlight_view.png", scene_path_[256] = "airlight_view.json";
  std::chrono::steady_clock::time_point last_frame_;
};

}  // namespace airlight::view
