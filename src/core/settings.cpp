#include <airlight/error.hpp>
#include <airlight/settings.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace airlight {

Settings::Settings(std::vector<SettingSpec> specs) : specs_(std::move(specs)) {
  for (const auto& s : specs_) values_[s.name] = s.default_value;
}

const SettingSpec& Settings::spec(const std::string& name) const {
  for (const auto& s : specs_)
    if (s.name == name) return s;
  throw std::logic_error("undeclared setting '" + name + "'");  // a programming error, not input
}

namespace {

std::string known_keys(const std::vector<SettingSpec>& specs) {
  std::string keys;
  for (const auto& s : specs) keys += (keys.empty() ? "" : ", ") + s.name;
  return keys.empty() ? "none" : keys;
}

std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// An integer setting's values in whole digits (2000000, not 2e+06).
std::string value_text(const SettingSpec& s, double x) {
  return s.type == SettingSpec::Type::integer ? std::to_string(static_cast<long long>(x)) : number_text(x);
}

std::string range_text(const SettingSpec& s) { return "[" + value_text(s, s.min) + ", " + value_text(s, s.max) + "]"; }

std::string choices_text(const SettingSpec& s) {
  std::string all;
  for (const auto& c : s.choices) all += (all.empty() ? "" : ", ") + c;
  return all;
}

// The value of `text` for `s`, or a message saying what is wrong.
double parse_value(const SettingSpec& s, const std::string& text, std::string* error) {
  using Type = SettingSpec::Type;
  if (s.type == Type::boolean) {
    if (text == "true" || text == "1" || text == "on") return 1.0;
    if (text == "false" || text == "0" || text == "off") return 0.0;
    *error = "expected true or false, got '" + text + "'";
    return 0.0;
  }
  if (s.type == Type::choice) {
    const auto it = std::find(s.choices.begin(), s.choices.end(), text);
    if (it != s.choices.end()) return static_cast<double>(it - s.choices.begin());
    *error = "expected one of " + choices_text(s) + ", got '" + text + "'";
    return 0.0;
  }
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  // Beyond double range ("1e999") is a number, and out of any range a setting has.
  const bool beyond = ec == std::errc::result_out_of_range;
  const bool number = ec != std::errc::invalid_argument && end == text.data() + text.size() &&
                      (beyond || std::isfinite(value));
  if (!number || (!beyond && s.type == Type::integer && value != std::floor(value)))
    *error = std::string("expected ") + (s.type == Type::integer ? "an integer" : "a finite number") +
             ", got '" + text + "'";
  else if (beyond || value < s.min || value > s.max)
    *error = "must be in " + range_text(s) + ", got " + text;
  return value;
}

}  // namespace

std::string describe_values(const SettingSpec& s) {
  switch (s.type) {
    case SettingSpec::Type::real: return "number in " + range_text(s) + ", default " + number_text(s.default_value);
    case SettingSpec::Type::integer: return "integer in " + range_text(s) + ", default " + value_text(s, s.default_value);
    case SettingSpec::Type::boolean: return std::string("true or false, default ") + (s.default_value != 0.0 ? "true" : "false");
    case SettingSpec::Type::choice:
      return "one of: " + choices_text(s) + "; default " + s.choices.at(static_cast<size_t>(s.default_value));
  }
  return "";
}

void Settings::set(const std::string& assignment, const std::string& source) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos) throw InputError(source, assignment, "expected key=value");
  set(assignment.substr(0, eq), assignment.substr(eq + 1), source);
}

void Settings::set(const std::string& key, const std::string& value, const std::string& source) {
  const auto it = std::find_if(specs_.begin(), specs_.end(), [&](const auto& s) { return s.name == key; });
  if (it == specs_.end())
    throw InputError(source, key, "unknown setting (known: " + known_keys(specs_) + ")");
  std::string error;
  const double parsed = parse_value(*it, value, &error);
  if (!error.empty()) throw InputError(source, key, error);
  values_[key] = parsed;
}

double Settings::real(const std::string& name) const { return spec(name), values_.at(name); }
int Settings::integer(const std::string& name) const { return static_cast<int>(real(name)); }
bool Settings::boolean(const std::string& name) const { return real(name) != 0.0; }
int Settings::choice_index(const std::string& name) const {
  if (spec(name).type != SettingSpec::Type::choice) throw Failure("setting " + name + " is not a choice");
  return static_cast<int>(values_.at(name));
}

const std::string& Settings::choice(const std::string& name) const {
  return spec(name).choices.at(static_cast<size_t>(values_.at(name)));
}

nlohmann::json Settings::to_json() const {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& s : specs_) {
    switch (s.type) {
      case SettingSpec::Type::real: out[s.name] = real(s.name); break;
      case SettingSpec::Type::integer: out[s.name] = integer(s.name); break;
      case SettingSpec::Type::boolean: out[s.name] = boolean(s.name); break;
      case SettingSpec::Type::choice: out[s.name] = choice(s.name); break;
    }
  }
  return out;
}

std::string Settings::describe() const {
  std::string text;
  const nlohmann::json all = to_json();
  for (const auto& [key, value] : all.items())
    text += (text.empty() ? "" : " ") + key + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  return text;
}

}  // namespace airlight
