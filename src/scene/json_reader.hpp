#pragma once
// Typed, strict access to parsed JSON for the scene loader. Every failure
// throws InputError(file, key, message) where key is the path of the offending
// value, e.g. "lights[1].cone_deg" or "camera.position[2]".
#include "core/number_text.hpp"

#include <airlight/scene.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace airlight::scene_json {

using Json = nlohmann::json;

// Parses JSON text; syntax errors and duplicate keys throw InputError(file, ...).
Json parse_json_text(const std::string& text, const std::string& file);

using airlight::number_text;

// An interval of allowed numbers; bounds may be open or closed, or infinite.
struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  bool contains(double x) const;
  std::string describe() const;  // "in (0, 180]", "> 0", ">= 0", ...
};
Interval any_number();
Interval at_least(double lo);             // [lo, inf)
Interval greater_than(double lo);         // (lo, inf)
Interval open(double lo, double hi);      // (lo, hi)
Interval closed(double lo, double hi);    // [lo, hi]
Interval left_open(double lo, double hi); // (lo, hi]

// One JSON value and where it sits in the file.
class JsonNode {
public:
  JsonNode(const Json& value, const std::string& file, std::string key)
      : value_(&value), file_(&file), key_(std::move(key)) {}

  const Json& json() const { return *value_; }
  const std::string& file() const { return *file_; }
  const std::string& key() const { return key_; }
  [[noreturn]] void fail(const std::string& message) const;

  float number(const Interval& allowed = any_number()) const;  // finite as a float
  int integer(int lo, int hi) const;
  std::string string() const;
  bool boolean() const;
  glm::vec2 vec2(const Interval& allowed = any_number()) const;
  glm::vec3 vec3(const Interval& allowed = any_number()) const;
  glm::vec3 direction() const;                        // non-zero, returned normalized
  Color color(const Interval& allowed) const;         // a number or an RGB triple
  std::vector<JsonNode> elements() const;             // an array's elements

  // The child paths: "a" + ".b" (or "b" at the root) and "a[3]".
  std::string member_key(std::string_view name) const;
  std::string element_key(size_t index) const;

private:
  std::vector<JsonNode> fixed_array(size_t size) const;

  const Json* value_;
  const std::string* file_;
  std::string key_;
};

// A JSON object whose members are each asked for by name; finish() rejects any
// member nobody asked for, so misspelt keys are errors, not silently ignored.
// The names asked for by required() and optional() (present or not) are the
// keys valid at that place, which the unknown-key message lists; has() only
// looks, so a key it tests is not thereby valid.
class JsonObject {
public:
  explicit JsonObject(const JsonNode& node);

  const JsonNode& node() const { return node_; }
  bool has(std::string_view name) const;
  JsonNode required(std::string_view name);
  // Several required members, all the missing ones named in one message.
  template <size_t N>
  std::array<JsonNode, N> required_all(const std::string_view (&names)[N]) {
    check_present(names);
    return [&]<size_t... I>(std::index_sequence<I...>) {
      return std::array<JsonNode, N>{required(names[I])...};
    }(std::make_index_sequence<N>{});
  }
  std::optional<JsonNode> optional(std::string_view name);
  void finish() const;
  // Fails at the member `name`, present or not (for conditions between members).
  [[noreturn]] void fail(std::string_view name, const std::string& message) const;

  // Shorthands for the common "optional value with a default" reads.
  float number_or(std::string_view name, const Interval& allowed, float fallback);
  glm::vec3 vec3_or(std::string_view name, glm::vec3 fallback);
  Color color_or(std::string_view name, const Interval& allowed, Color fallback);
  int integer_or(std::string_view name, int lo, int hi, int fallback);
  bool boolean_or(std::string_view name, bool fallback);

private:
  void offer(std::string_view name);
  void check_present(std::span<const std::string_view> names);

  JsonNode node_;
  std::vector<std::string> offered_;  // in the order asked, for the message
};

}  // namespace airlight::scene_json
