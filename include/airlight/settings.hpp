#pragma once
// Typed settings of a method: each declared by name with a type, a default and a
// range (docs/design.md §3), set from "key=value" text or JSON, reported as JSON.
#include <airlight/export.hpp>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace airlight {

struct AIRLIGHT_API SettingSpec {
  enum class Type { real, integer, boolean, choice };
  std::string name;
  Type type = Type::real;
  double default_value = 0.0;  // for choice: the index into `choices`
  double min = 0.0, max = 0.0;  // inclusive range for real and integer
  std::vector<std::string> choices;
  std::string help;
};

// The values a setting takes and its default: "integer in [1, 4096], default 64",
// "one of: white, blue; default blue", "true or false, default false".
AIRLIGHT_API std::string describe_values(const SettingSpec& spec);

class AIRLIGHT_API Settings {
public:
  Settings() = default;
  explicit Settings(std::vector<SettingSpec> specs);

  // "key=value"; `source` names where the caller got it, for messages (the
  // command: its option; an engine: its own config file or key).
  // Throws InputError(source, key) for an unknown key or a bad value.
  void set(const std::string& assignment, const std::string& source);
  void set(const std::string& key, const std::string& value, const std::string& source);

  double real(const std::string& name) const;
  int integer(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& choice(const std::string& name) const;
  // A choice as the enum whose enumerators are the spec's choices in order.
  template <typename Enum>
  Enum option(const std::string& name) const {
    return static_cast<Enum>(choice_index(name));
  }
  int choice_index(const std::string& name) const;

  const std::vector<SettingSpec>& specs() const { return specs_; }
  nlohmann::json to_json() const;
  std::string describe() const;  // "key=value key=value", for labels and logs

private:
  const SettingSpec& spec(const std::string& name) const;
  std::vector<SettingSpec> specs_;
  std::map<std::string, double> values_;
};

}  // namespace airlight
