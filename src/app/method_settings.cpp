#include "app/method_settings.hpp"

#include <airlight/error.hpp>

namespace airlight::app {

Settings method_settings(const MethodInfo& method, const std::vector<std::string>& assignments) {
  Settings settings(method.settings);
  for (std::string a : assignments) {
    const auto dot = a.find('.'), eq = a.find('=');
    if (dot != std::string::npos && dot < eq) {
      if (a.substr(0, dot) != method.name)
        throw InputError("--set", a.substr(0, eq), "the setting names another method than '" + method.name + "'");
      a = a.substr(dot + 1);
    }
    settings.set(a, "--set");
  }
  return settings;
}

}  // namespace airlight::app
