// Every method registers here with one line (DESIGN §3).
#include "methods/analytic/analytic_method.hpp"
#include "methods/interleaved/interleaved_method.hpp"
#include "methods/planes/planes_method.hpp"
#include "methods/raymarch/raymarch_method.hpp"
#include "methods/reference/reference_method.hpp"

#include <airlight/error.hpp>
#include <airlight/method.hpp>

namespace airlight {

const std::vector<MethodInfo>& registered_methods() {
  static const std::vector<MethodInfo> all{
      methods::reference_method(),
      methods::raymarch_method(),
      methods::interleaved_method(),
      methods::planes_method(),
      methods::analytic_method(),
  };
  return all;
}

const MethodInfo& find_method(const std::string& name) {
  for (const auto& m : registered_methods())
    if (m.name == name) return m;
  std::string known;
  for (const auto& m : registered_methods()) known += (known.empty() ? "" : ", ") + m.name;
  throw InputError("--method", name, "unknown method (known: " + known + ")");
}

Image select_pass(const Frame& frame, Pass pass) {
  if (pass == Pass::airlight) return frame.airlight;
  if (pass == Pass::surface) return frame.surface;
  Image composite = frame.surface;  // L = L_surf·T(d) + L_air (DESIGN §1)
  for (size_t i = 0; i < composite.pixels.size(); ++i) composite.pixels[i] += frame.airlight.pixels[i];
  return composite;
}

}  // namespace airlight
