#include "view/script.hpp"

#include "view/camera_control.hpp"

#include <airlight/error.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace airlight::view {
namespace {

// One line's words, read left to right; a missing or malformed word throws.
class Words {
public:
  explicit Words(const std::string& line) {
    std::istringstream in(line);
    for (std::string w; in >> w;) words_.push_back(w);
  }
  bool empty() const { return words_.empty() || words_[0][0] == '#'; }
  bool done() const { return next_ == words_.size(); }
  std::string word(const char* what) {
    if (done()) throw std::invalid_argument("missing " + std::string(what));
    return words_[next_++];
  }
  float number(const char* what) {
    const std::string w = word(what);
    size_t used = 0;
    float value = 0.0f;
    try {
      value = std::stof(w, &used);
    } catch (const std::exception&) {
    }
    if (used != w.size() || w.empty()) throw std::invalid_argument(std::string(what) + " must be a number, got '" + w + "'");
    return value;
  }
  // A whole number in [lo, hi] (checked before the cast, which would be undefined outside int).
  int count(const char* what, int lo, int hi) {
    const float x = number(what);
    if (!(x >= lo && x <= hi) || x != std::floor(x))
      throw std::invalid_argument(std::string(what) + " must be a whole number in [" + std::to_string(lo) + ", " +
                                  std::to_string(hi) + "]");
    return static_cast<int>(x);
  }
  glm::vec3 vec3(const char* what) {
    const float x = number(what), y = number(what), z = number(what);
    return {x, y, z};
  }
  void finish() {
    if (!done()) throw std::invalid_argument("unexpected '" + words_[next_] + "'");
  }

private:
  std::vector<std::string> words_;
  size_t next_ = 0;
};

void camera_command(Viewer& v, Words& w) {
  Camera& c = v.inputs().camera;
  const std::string what = w.word("camera move");
  if (what == "orbit") {
    const float yaw = w.number("yaw");
    c = orbit(c, yaw, w.number("pitch"));
  } else if (what == "look") {
    const float yaw = w.number("yaw");
    c = look(c, yaw, w.number("pitch"));
  } else if (what == "fly") {
    c = fly(c, w.vec3("offset"));
  } else if (what == "dolly") {
    c = dolly(c, w.number("factor"));
  } else if (what == "fov") {
    c.fov_y_deg = w.number("degrees");
  } else if (what == "reset") {
    v.reset_camera();
  } else {
    throw std::invalid_argument("camera takes orbit, look, fly, dolly, fov or reset, not '" + what + "'");
  }
}

void light_command(Viewer& v, Words& w) {
  auto& lights = v.inputs().lights;
  if (lights.empty()) throw std::invalid_argument("the scene has no lights");
  Light& light = lights[w.count("light index", 0, static_cast<int>(lights.size()) - 1)];
  const std::string what = w.word("light property");
  if (what == "position") light.position = w.vec3("position");
  else if (what == "direction") light.direction = glm::normalize(w.vec3("direction"));
  else if (what == "cone") light.cone_deg = w.number("cone");
  else if (what == "edge") light.edge_deg = w.number("edge");
  else if (what == "intensity") (light.type == LightType::directional ? light.irradiance : light.intensity) = w.vec3("intensity");
  else throw std::invalid_argument("light takes position, direction, cone, edge or intensity, not '" + what + "'");
}

void medium_command(Viewer& v, Words& w) {
  Medium& m = v.inputs().medium;
  const std::string what = w.word("medium property");
  if (what == "scattering") {
    m.sigma_s = w.vec3("scattering");
  } else if (what == "absorption") {
    m.sigma_a = w.vec3("absorption");
  } else if (what == "phase") {
    static const std::map<std::string, PhaseType> types{
        {"isotropic", PhaseType::isotropic}, {"rayleigh", PhaseType::rayleigh},
        {"henyey_greenstein", PhaseType::henyey_greenstein}, {"schlick", PhaseType::schlick},
        {"hazy", PhaseType::hazy}, {"murky", PhaseType::murky}};
    const std::string name = w.word("phase type");
    if (!types.count(name)) throw std::invalid_argument("unknown phase function '" + name + "'");
    PhaseLobe lobe{types.at(name), 0.0f, 1.0f};
    if (!w.done()) lobe.g = w.number("g");
    m.phase.lobes = {lobe};
  } else {
    throw std::invalid_argument("medium takes scattering, absorption or phase, not '" + what + "'");
  }
}

double frames_ms(Viewer& v, int n, bool orbiting) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    if (orbiting) v.inputs().camera = orbit(v.inputs().camera, 1.0f, 0.0f);
    v.frame();
  }
  return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / n;
}

std::string size_text(const Viewer& v) {
  const auto [width, height] = v.shown_size();
  return std::to_string(width) + "x" + std::to_string(height);
}

// Frame times as a person sees them: whole frames (method, display, panels,
// swap), with the size the method rendered at.
void measure(Viewer& v, int n) {
  frames_ms(v, 1, false);  // the first frame after a switch compiles programs
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // a camera moved before has settled
  const double rest = frames_ms(v, n, false);
  const std::string rest_size = size_text(v);
  const double moving = frames_ms(v, n, true);
  std::printf("%s: at rest %.1f ms/frame (%.1f fps) at %s, moving %.1f ms/frame (%.1f fps) at %s\n",
              v.method().c_str(), rest, 1e3 / rest, rest_size.c_str(), moving, 1e3 / moving, size_text(v).c_str());
  std::fflush(stdout);
}

Pass pass_named(const std::string& name) {
  if (name == "composite") return Pass::composite;
  if (name == "airlight") return Pass::airlight;
  if (name == "surface") return Pass::surface;
  throw std::invalid_argument("pass is composite, airlight or surface, not '" + name + "'");
}

Viewer::ErrorView error_view_named(const std::string& name) {
  if (name == "off") return Viewer::ErrorView::off;
  if (name == "split") return Viewer::ErrorView::split;
  if (name == "heat") return Viewer::ErrorView::heat;
  throw std::invalid_argument("error is off, split or heat, not '" + name + "'");
}

// Returns false at `quit`.
bool run_line(Viewer& v, Words& w) {
  const std::string command = w.word("command");
  if (command == "method") v.switch_method(w.word("method name"));
  else if (command == "set") {
    const std::string label = w.word("setting label");
    v.set_setting(label, w.word("value"));
  } else if (command == "pass") v.set_pass(pass_named(w.word("pass")));
  else if (command == "exposure") v.tone().exposure = w.number("exposure");
  else if (command == "tonemap") {
    const auto curve = tone_curve(w.word("curve"));
    if (!curve) throw std::invalid_argument("tonemap is agx, aces or clamp");
    v.tone().curve = *curve;
  } else if (command == "camera") camera_command(v, w);
  else if (command == "light") light_command(v, w);
  else if (command == "medium") medium_command(v, w);
  else if (command == "frame") {
    const int n = w.done() ? 1 : w.count("frame count", 1, 100000);
    for (int i = 0; i < n; ++i) v.frame();
  } else if (command == "measure") measure(v, w.count("frame count", 1, 100000));
  else if (command == "error") v.set_error_view(error_view_named(w.word("error view")));
  else if (command == "reference") {
    const double e = v.wait_for_reference();
    std::printf("%s: rRMSE %.6f against the reference\n", v.method().c_str(), e);
    std::fflush(stdout);
  } else if (command == "screenshot") v.screenshot(w.word("file"));
  else if (command == "window") v.save_window(w.word("file"));
  else if (command == "save") v.save_scene(w.word("file"));
  else if (command == "quit") {
    v.quit();
    return false;
  } else throw std::invalid_argument("unknown command '" + command + "'");
  w.finish();
  return true;
}

}  // namespace

void run_script(Viewer& viewer, const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "", "cannot read the script");
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    Words words(line);
    if (words.empty()) continue;
    try {
      if (!run_line(viewer, words)) return;
    } catch (const std::invalid_argument& e) {
      throw InputError(file.string(), "line " + std::to_string(number), e.what());
    }
  }
}

}  // namespace airlight::view
