#include "scene/json_reader.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <set>
#include <vector>

namespace airlight::scene_json {
namespace {

// nlohmann prefixes its messages with "[json.exception.parse_error.101] ";
// the user needs only the part that says where and what.
std::string strip_exception_id(const std::string& what) {
  const auto end = what.find("] ");
  return (what.rfind("[json.exception.", 0) == 0 && end != std::string::npos)
             ? what.substr(end + 2)
             : what;
}

// A value the file gave, as messages quote it: exactly ("0.99999999999", "1e+300").
std::string value_text(double x) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

std::string list_text(std::span<const std::string> names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

// Where the parser is, as a key path ("medium.scattering", "lights[1]"), so that
// an error the lexer raises (a number overflowing to infinity) still names its key.
class ParsePath {
public:
  void enter(bool is_array) { frames_.push_back({is_array, "", 0}); }
  void leave() {
    frames_.pop_back();
    element_done();
  }
  void key(const std::string& name) { frames_.back().key = name; }
  // A value is complete: an array moves to its next index, an object forgets the key.
  void element_done() {
    if (frames_.empty()) return;
    if (frames_.back().is_array) ++frames_.back().index;
    else frames_.back().key.clear();
  }
  std::string text() const {
    std::string path;
    for (const auto& f : frames_) {
      // Appends one piece at a time: GCC 12 warns falsely (-Wrestrict) on a + b + c here.
      if (f.is_array) {
        path += '[';
        path += std::to_string(f.index);
        path += ']';
      } else if (!f.key.empty()) {
        if (!path.empty()) path += '.';
        path += f.key;
      }
    }
    return path;
  }

private:
  struct Scope {
    bool is_array;
    std::string key;
    int index;
  };
  std::vector<Scope> frames_;
};

Json parse_json_text(const std::string& text, const std::string& file) {
  // nlohmann keeps the last of duplicate keys silently; a stack of the keys
  // seen in each open object catches them instead.
  std::vector<std::set<std::string>> open_objects;
  ParsePath path;
  const Json::parser_callback_t track = [&](int, Json::parse_event_t event, Json& parsed) {
    using E = Json::parse_event_t;
    switch (event) {
      case E::object_start: open_objects.emplace_back(); path.enter(false); break;
      case E::object_end: open_objects.pop_back(); path.leave(); break;
      case E::array_start: path.enter(true); break;
      case E::array_end: path.leave(); break;
      case E::value: path.element_done(); break;
      case E::key:
        path.key(parsed.get<std::string>());
        if (!open_objects.back().insert(parsed.get<std::string>()).second)
          throw InputError(file, path.text(), "duplicate key");
        break;
    }
    return true;
  };
  try {
    return Json::parse(text, track);
  } catch (const Json::out_of_range& e) {
    // The lexer's "number overflow parsing '1e999'": a finite number beyond double range,
    // so beyond float range, as JsonNode::number says of one within double range.
    const std::string what = e.what();
    const auto open = what.find('\''), close = what.rfind('\'');
    if (e.id != 406 || open == std::string::npos || close <= open + 1) {
      throw InputError(file, path.text(), "malformed JSON: " + strip_exception_id(what));
    }
    const std::string number = what.substr(open + 1, close - open - 1);
    throw InputError(file, path.text(),
                     (number[0] == '-' ? "too small, at least " + number_text(-FLT_MAX)
                                       : "too large, at most " + number_text(FLT_MAX)) +
                         ", got " + number);
  } catch (const Json::exception& e) {
    throw InputError(file, path.text(), "malformed JSON: " + strip_exception_id(e.what()));
  }
}

bool Interval::contains(double x) const {
  const bool above = lo_open ? x > lo : x >= lo;
  const bool below = hi_open ? x < hi : x <= hi;
  return above && below;
}

std::string Interval::describe() const {
  const bool lo_inf = std::isinf(lo), hi_inf = std::isinf(hi);
  if (lo_inf && hi_inf) return "finite";
  if (hi_inf) return (lo_open ? "> " : ">= ") + number_text(lo);
  if (lo_inf) return (hi_open ? "< " : "<= ") + number_text(hi);
  return std::string("in ") + (lo_open ? "(" : "[") + number_text(lo) + ", " +
         number_text(hi) + (hi_open ? ")" : "]");
}

Interval any_number() { return {}; }
Interval at_least(double lo) { return {lo, INFINITY, false, false}; }
Interval greater_than(double lo) { return {lo, INFINITY, true, false}; }
Interval open(double lo, double hi) { return {lo, hi, true, true}; }
Interval closed(double lo, double hi) { return {lo, hi, false, false}; }
Interval left_open(double lo, double hi) { return {lo, hi, true, false}; }

void JsonNode::fail(const std::string& message) const { throw InputError(file(), key_, message); }

float JsonNode::number(const Interval& allowed) const {
  if (!value_->is_number()) fail(std::string("must be a number, not ") + value_->type_name());
  const double x = value_->get<double>();
  const std::string got = ", got " + value_text(x);
  if (!std::isfinite(x)) fail("must be a finite number" + got);  // a lexer overflow
  if (!allowed.contains(x)) fail("must be " + allowed.describe() + got);
  // Stored as a float: beyond its range is too large, and rounding must not
  // carry a value onto an open bound (g = 0.9999999999).
  if (x > FLT_MAX) fail("too large, at most " + number_text(FLT_MAX) + got);
  if (x < -FLT_MAX) fail("too small, at least " + number_text(-FLT_MAX) + got);
  const float f = static_cast<float>(x);
  if (!allowed.contains(f)) fail("must be " + allowed.describe() + got + ", which is " + value_text(f) + " as a float");
  return f;
}

int JsonNode::integer(int lo, int hi) const {
  const float x = number(closed(lo, hi));
  if (x != std::floor(x)) fail("must be a whole number, got " + value_text(value_->get<double>()));
  return static_cast<int>(x);
}

std::string JsonNode::string() const {
  if (!value_->is_string()) fail(std::string("must be a string, not ") + value_->type_name());
  return value_->get<std::string>();
}

bool JsonNode::boolean() const {
  if (!value_->is_boolean()) fail(std::string("must be true or false, not ") + value_->type_name());
  return value_->get<bool>();
}

std::vector<JsonNode> JsonNode::elements() const {
  if (!value_->is_array()) fail(std::string("must be an array, not ") + value_->type_name());
  std::vector<JsonNode> result;
  for (size_t i = 0; i < value_->size(); ++i) {
    result.emplace_back((*value_)[i], *file_, element_key(i));
  }
  return result;
}

std::vector<JsonNode> JsonNode::fixed_array(size_t size) const {
  if (!value_->is_array() || value_->size() != size) {
    fail("must be an array of " + std::to_string(size) + " numbers");
  }
  return elements();
}

glm::vec2 JsonNode::vec2(const Interval& allowed) const {
  const auto e = fixed_array(2);
  return {e[0].number(allowed), e[1].number(allowed)};
}

glm::vec3 JsonNode::vec3(const Interval& allowed) const {
  const auto e = fixed_array(3);
  return {e[0].number(allowed), e[1].number(allowed), e[2].number(allowed)};
}

glm::vec3 JsonNode::direction() const {
  const glm::vec3 v = vec3();
  // Lengths are compared in double: a float square of tiny components underflows.
  const double length = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
  if (!(length > 1e-20)) fail("must not be a zero vector");
  return glm::vec3(glm::dvec3(v) / length);
}

Color JsonNode::color(const Interval& allowed) const {
  if (value_->is_array()) return vec3(allowed);
  if (!value_->is_number()) fail("must be a number or an array of 3 numbers");
  return Color(number(allowed));
}

std::string JsonNode::member_key(std::string_view name) const {
  return key_.empty() ? std::string(name) : key_ + "." + std::string(name);
}

std::string JsonNode::element_key(size_t index) const {
  return key_ + "[" + std::to_string(index) + "]";
}

JsonObject::JsonObject(const JsonNode& node) : node_(node) {
  if (!node.json().is_object()) {
    node.fail(std::string("must be an object, not ") + node.json().type_name());
  }
}

bool JsonObject::has(std::string_view name) const { return node_.json().contains(name); }

void JsonObject::offer(std::string_view name) {
  if (std::find(offered_.begin(), offered_.end(), name) == offered_.end()) offered_.emplace_back(name);
}

JsonNode JsonObject::required(std::string_view name) {
  offer(name);
  if (!has(name)) fail(name, "is required");
  return JsonNode(node_.json().find(name).value(), node_.file(), node_.member_key(name));
}

void JsonObject::check_present(std::span<const std::string_view> names) {
  std::vector<std::string> missing;
  for (const std::string_view name : names) {
    offer(name);
    if (!has(name)) missing.emplace_back(name);
  }
  if (missing.size() == 1) fail(missing[0], "is required");
  if (!missing.empty()) node_.fail("missing required keys: " + list_text(missing));
}

std::optional<JsonNode> JsonObject::optional(std::string_view name) {
  offer(name);
  if (!has(name)) return std::nullopt;
  return required(name);
}

void JsonObject::finish() const {
  for (const auto& item : node_.json().items()) {
    if (std::find(offered_.begin(), offered_.end(), item.key()) == offered_.end()) {
      throw InputError(node_.file(), node_.member_key(item.key()),
                       "unknown key (known here: " + list_text(offered_) + ")");
    }
  }
}

void JsonObject::fail(std::string_view name, const std::string& message) const {
  throw InputError(node_.file(), node_.member_key(name), message);
}

float JsonObject::number_or(std::string_view name, const Interval& allowed, float fallback) {
  const auto node = optional(name);
  return node ? node->number(allowed) : fallback;
}

glm::vec3 JsonObject::vec3_or(std::string_view name, glm::vec3 fallback) {
  const auto node = optional(name);
  return node ? node->vec3() : fallback;
}

Color JsonObject::color_or(std::string_view name, const Interval& allowed, Color fallback) {
  const auto node = optional(name);
  return node ? node->color(allowed) : fallback;
}

int JsonObject::integer_or(std::string_view name, int lo, int hi, int fallback) {
  const auto node = optional(name);
  return node ? node->integer(lo, hi) : fallback;
}

bool JsonObject::boolean_or(std::string_view name, bool fallback) {
  const auto node = optional(name);
  return node ? node->boolean() : fallback;
}

}  // namespace airlight::scene_json
