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

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t end; (end = text.find(separator, start)) != std::string::npos; start = end + 1)
    parts.push_back(text.substr(start, end - start));
  parts.push_back(text.substr(start));
  return parts;
}

}  // namespace airlight::app
