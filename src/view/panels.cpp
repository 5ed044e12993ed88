// The viewer's panels (Dear ImGui): each edits the state the next frame renders.
#include "view/viewer.hpp"

#include <imgui.h>

#include <algorithm>
#include <glm/geometric.hpp>

namespace airlight::view {
namespace {

const char* const pass_names[] = {"composite", "airlight", "surface"};
const char* const curve_names[] = {"agx", "aces", "clamp"};
const char* const phase_names[] = {"isotropic", "rayleigh", "henyey_greenstein", "schlick", "hazy", "murky"};
const char* const light_type_names[] = {"point", "spot", "directional"};

// A direction edited component by component, made unit again (a zero vector is refused).
void edit_direction(const char* label, glm::vec3& direction) {
  glm::vec3 d = direction;
  if (ImGui::DragFloat3(label, &d.x, 0.01f, -1.0f, 1.0f) && glm::length(d) > 1e-3f) direction = glm::normalize(d);
}

bool edit_color(const char* label, glm::vec3& color, float speed) {
  return ImGui::DragFloat3(label, &color.x, speed, 0.0f, 1e9f, "%.4g", ImGuiSliderFlags_AlwaysClamp);
}

}  // namespace

void Viewer::draw_panels() {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("airlight");
  try {
    if (ImGui::CollapsingHeader("Method", ImGuiTreeNodeFlags_DefaultOpen)) method_panel();
    if (ImGui::CollapsingHeader("Numbers", ImGuiTreeNodeFlags_DefaultOpen)) numbers_panel();
    if (ImGui::CollapsingHeader("Camera")) camera_panel();
    if (ImGui::CollapsingHeader("Lights")) light_panel();
    if (ImGui::CollapsingHeader("Medium")) medium_panel();
    if (ImGui::CollapsingHeader("Capture")) capture_panel();
  } catch (const std::runtime_error& e) {
    report(e);
  }
  if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
  ImGui::End();
}

void Viewer::method_panel() {
  if (ImGui::BeginCombo("method", method_name_.c_str())) {
    for (const std::string& name : viewer_methods())
      if (ImGui::Selectable(name.c_str(), name == method_name_) && name != method_name_) switch_method(name);
    ImGui::EndCombo();
  }
  Settings edited = settings_;
  if (draw_setting_widgets(widgets_, edited)) create_method(method_name_, edited);
  int pass = static_cast<int>(pass_);
  if (ImGui::Combo("pass", &pass, pass_names, 3)) pass_ = static_cast<Pass>(pass);
  ImGui::SliderFloat("exposure", &tone_.exposure, 1e-3f, 1e3f, "%.3g", ImGuiSliderFlags_Logarithmic);
  int curve = static_cast<int>(tone_.curve);
  if (ImGui::Combo("tone curve", &curve, curve_names, 3)) tone_.curve = static_cast<ToneCurve>(curve);
  ImGui::Checkbox("reduced size while moving", &progressive_);
  ImGui::SliderFloat("moving scale", &moving_scale_, 0.125f, 1.0f, "%.3f");
}

void Viewer::numbers_panel() {
  const auto [width, height] = shown_size();
  const auto method_frame = static_cast<long long>(numbers_.frame);
  if (idle_)
    ImGui::Text("idle: the view is unchanged (last: method frame %lld, %.1f ms at %dx%d)", method_frame,
                1e3 * render_s_, width, height);
  else
    ImGui::Text("frame %lld: %.1f ms (%.1f fps); method frame %lld: %.1f ms at %dx%d",
                static_cast<long long>(frames_), 1e3 * frame_s_, frame_s_ > 0 ? 1.0 / frame_s_ : 0.0, method_frame,
                1e3 * render_s_, width, height);
  ImGui::Text("passes of method frame %lld:", method_frame);
  for (const PassTime& t : numbers_.times) ImGui::Text("  %-10s %8.2f ms", t.pass.c_str(), 1e3 * t.seconds);
  for (const auto& [name, value] : numbers_.stats) ImGui::Text("  %s %.6g", name.c_str(), value);
  error_panel();
}

void Viewer::camera_panel() {
  ImGui::TextWrapped("left drag: orbit; right drag: look; W/A/S/D/Q/E: fly (shift: faster); wheel: dolly");
  Camera& c = inputs_.camera;
  ImGui::SliderFloat("field of view", &c.fov_y_deg, 5.0f, 120.0f, "%.1f deg");
  ImGui::DragFloat3("position", &c.position.x, 0.05f);
  glm::vec3 target = c.look_at;
  if (ImGui::DragFloat3("look at", &target.x, 0.05f) && target != c.position) c.look_at = target;
  if (ImGui::Button("reset to the scene's camera")) reset_camera();
}

void Viewer::light_panel() {
  auto& lights = inputs_.lights;
  if (lights.empty()) {
    ImGui::Text("the scene has no lights");
    return;
  }
  selected_light_ = std::clamp(selected_light_, 0, static_cast<int>(lights.size()) - 1);
  for (int i = 0; i < static_cast<int>(lights.size()); ++i) {
    const std::string name = std::to_string(i) + ": " + light_type_names[static_cast<int>(lights[i].type)];
    if (ImGui::Selectable(name.c_str(), i == selected_light_)) selected_light_ = i;
  }
  Light& light = lights[selected_light_];
  if (light.type != LightType::directional) ImGui::DragFloat3("light position", &light.position.x, 0.05f);
  if (light.type != LightType::point) edit_direction("light direction", light.direction);
  if (light.type == LightType::spot) {
    ImGui::SliderFloat("cone", &light.cone_deg, 0.5f, 180.0f, "%.1f deg");
    ImGui::SliderFloat("edge", &light.edge_deg, 0.0f, light.cone_deg, "%.1f deg");
  }
  if (light.type == LightType::directional)
    edit_color("irradiance", light.irradiance, 0.05f);
  else
    edit_color("intensity", light.intensity, 1.0f);
}

void Viewer::medium_panel() {
  Medium& m = inputs_.medium;
  edit_color("scattering", m.sigma_s, 0.001f);
  edit_color("absorption", m.sigma_a, 0.001f);
  for (size_t i = 0; i < m.phase.lobes.size(); ++i) {
    PhaseLobe& lobe = m.phase.lobes[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::Text("phase lobe %zu, weight %.3g", i, lobe.weight);
    int type = static_cast<int>(lobe.type);
    if (ImGui::Combo("phase", &type, phase_names, 6)) lobe.type = static_cast<PhaseType>(type);
    if (lobe.type == PhaseType::henyey_greenstein || lobe.type == PhaseType::schlick)
      ImGui::SliderFloat("g", &lobe.g, -0.99f, 0.99f);
    ImGui::PopID();
  }
}

void Viewer::capture_panel() {
  ImGui::InputText("image", screenshot_path_, sizeof screenshot_path_);
  if (ImGui::Button("screenshot (.png tone-mapped, .exr linear)")) screenshot(screenshot_path_);
  ImGui::InputText("scene", scene_path_, sizeof scene_path_);
  if (ImGui::Button("save scene (.json)")) {
    save_scene(scene_path_);
    status_ = std::string("saved ") + scene_path_;
  }
}

void Viewer::error_panel() {
  int view = static_cast<int>(error_view_);
  if (ImGui::Combo("error view", &view, "off\0reference right of the divider\0heat map |method - reference|\0"))
    error_view_ = static_cast<ErrorView>(view);
  if (error_view_ == ErrorView::off) return;
  if (!reference_) {
    ImGui::Text("the reference starts when the view rests");
  } else if (!reference_->finished()) {
    ImGui::ProgressBar(reference_->progress(), ImVec2(-1.0f, 0.0f), "reference (CPU, in the background)");
  } else if (!compared_.empty()) {
    ImGui::Text("rRMSE %.4f (%s), reference %.1f s", rel_rmse_, pass_names[static_cast<int>(pass_)],
                reference_->seconds());
    if (error_view_ == ErrorView::heat) ImGui::TextWrapped("heat map: %s", heat_scale_.c_str());
  }
  if (error_view_ == ErrorView::split) ImGui::SliderFloat("divider", &divider_, 0.0f, 1.0f);
}

}  // namespace airlight::view
