#pragma once
// The method contract (DESIGN §3): a method is prepared once per scene, then
// renders frames; it writes L_air, and the surface term L_surf·T(d) comes from the
// shared frame (or, for the CPU reference, from the reference itself).
// Compositing L = L_surf·T + L_air is shared code (composite()).
#include <airlight/image.hpp>
#include <airlight/scene.hpp>
#include <airlight/settings.hpp>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace airlight {

enum class Pass { composite, airlight, surface };

struct PassTime {
  std::string pass;
  double seconds = 0.0;
};

struct Frame {
  Image airlight;                      // L_air, W/(m²·sr)
  Image surface;                       // L_surf·T(d)
  std::vector<PassTime> times;         // per pass, in the order run
  std::vector<std::pair<std::string, double>> stats;  // method-specific counters
};

class Method {
public:
  virtual ~Method() = default;
  virtual void prepare(const Scene& scene) = 0;
  virtual Frame render(int width, int height) = 0;
};

struct MethodInfo {
  std::string name;
  std::string source;       // the document it comes from
  std::string description;
  std::vector<SettingSpec> settings;
  std::function<std::unique_ptr<Method>(const Settings&)> create;
};

// Every registered method, in the order of DESIGN §3.
const std::vector<MethodInfo>& registered_methods();
// Throws InputError("--method", name) for an unknown method.
const MethodInfo& find_method(const std::string& name);

// L = L_surf·T + L_air, or one of its terms.
Image select_pass(const Frame& frame, Pass pass);

}  // namespace airlight
