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
#include "view/setting_widgets.hpp"

#include "core/tonemap.hpp"
#include <airlight/method.hpp>
#include <airlight/scene.hpp>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
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
  void switch_method(const std::string& name);
  void set_setting(const std::string& label, const std::string& value);
  void set_pass(Pass pass) { pass_ = pass; }
  ToneMap& tone() { return tone_; }
  void reset_camera() { inputs_.camera = scene_.camera; }
  // The image shown at full size: PNG tone-mapped as the window shows it, EXR or PFM linear.
  void screenshot(const std::filesystem::path& file);
  // The scene as edited (camera, lights, medium) as airlight-scene/1 JSON.
  void save_scene(const std::filesystem::path& file) const;

private:
  struct Targets;
  void create_method(const std::string& name, const Settings& settings);
  void handle_input(float dt);
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
  std::unique_ptr<Display> display_;
  std::unique_ptr<Targets> full_, reduced_;
  const Targets* shown_ = nullptr;

  std::string method_name_;
  Settings settings_;
  std::vector<SettingWidget> widgets_;
  std::unique_ptr<Method> method_;
  Pass pass_ = Pass::composite;
  ToneMap tone_;

  // Progressive rendering: the reduced size while the camera moves.
  bool progressive_ = true;
  float moving_scale_ = 0.5f;
  std::chrono::steady_clock::time_point last_move_{};
  Camera last_camera_;

  int selected_light_ = 0;
  double frame_s_ = 0.0, render_s_ = 0.0;
  FrameNumbers numbers_;
  std::string status_;
  char screenshot_path_[256] = "airlight_view.png", scene_path_[256] = "airlight_view.json";
  std::chrono::steady_clock::time_point last_frame_;
};

}  // namespace airlight::view
