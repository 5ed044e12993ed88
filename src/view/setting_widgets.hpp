#pragma once
// A method's settings as widgets, generated from its typed SettingSpecs
// (docs/design.md §3) — nothing is written per method: an integer is an int
// slider over its range, a real a float slider (logarithmic when the range
// spans more than three decades), a choice a combo box, a boolean a checkbox.
// Each widget's label is the setting's name; the script sets a widget by it.
#include <airlight/settings.hpp>
#include <string>
#include <vector>

namespace airlight::view {

struct SettingWidget {
  enum class Kind { int_slider, float_slider, combo, checkbox };
  Kind kind = Kind::float_slider;
  std::string label;  // the setting's name
  double min = 0.0, max = 0.0;
  bool logarithmic = false;
  std::vector<std::string> choices;
  std::string help;  // the tooltip
};

std::vector<SettingWidget> setting_widgets(const std::vector<SettingSpec>& specs);

// Draws the widgets with ImGui, showing `settings`; returns true when the user
// changed one (the new value is in `settings`).
bool draw_setting_widgets(const std::vector<SettingWidget>& widgets, Settings& settings);

// What a widget does when the user gives it `value` (a number, a choice, true
// or false), found by its label. Throws InputError("set", label) for a label no
// widget has or a value the widget cannot take (outside its range, not a choice).
void set_widget(const std::vector<SettingWidget>& widgets, Settings& settings, const std::string& label,
                const std::string& value);

}  // namespace airlight::view
