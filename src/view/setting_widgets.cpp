#include "view/setting_widgets.hpp"

#include <airlight/error.hpp>

#include <algorithm>
#include <cstdio>
#include <imgui.h>

namespace airlight::view {
namespace {

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// Settings::set with the widget's name as the source, so a bad value names it.
void assign(Settings& settings, const SettingWidget& w, const std::string& value) {
  settings.set(w.label, value, "set");
}

bool draw(const SettingWidget& w, Settings& settings) {
  const char* label = w.label.c_str();
  bool changed = false;
  switch (w.kind) {
    case SettingWidget::Kind::int_slider: {
      int v = settings.integer(w.label);
      // ImGui's sliders take int and float ranges; the specs' fit (≤ 2^31).
      changed = ImGui::SliderInt(label, &v, static_cast<int>(w.min), static_cast<int>(w.max), "%d",
                                 ImGuiSliderFlags_AlwaysClamp | (w.logarithmic ? ImGuiSliderFlags_Logarithmic : 0));
      if (changed) assign(settings, w, std::to_string(v));
      break;
    }
    case SettingWidget::Kind::float_slider: {
      float v = static_cast<float>(settings.real(w.label));
      changed = ImGui::SliderFloat(label, &v, static_cast<float>(w.min), static_cast<float>(w.max), "%.4g",
                                   ImGuiSliderFlags_AlwaysClamp | (w.logarithmic ? ImGuiSliderFlags_Logarithmic : 0));
      if (changed) assign(settings, w, number_text(v));
      break;
    }
    case SettingWidget::Kind::combo: {
      const int current = settings.choice_index(w.label);
      if (ImGui::BeginCombo(label, w.choices[current].c_str())) {
        for (int i = 0; i < static_cast<int>(w.choices.size()); ++i)
          if (ImGui::Selectable(w.choices[i].c_str(), i == current) && i != current) {
            assign(settings, w, w.choices[i]);
            changed = true;
          }
        ImGui::EndCombo();
      }
      break;
    }
    case SettingWidget::Kind::checkbox: {
      bool v = settings.boolean(w.label);
      changed = ImGui::Checkbox(label, &v);
      if (changed) assign(settings, w, v ? "true" : "false");
      break;
    }
  }
  if (!w.help.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", w.help.c_str());
  return changed;
}

}  // namespace

std::vector<SettingWidget> setting_widgets(const std::vector<SettingSpec>& specs) {
  std::vector<SettingWidget> widgets;
  for (const SettingSpec& s : specs) {
    SettingWidget w;
    w.label = s.name;
    w.help = s.help;
    w.min = s.min;
    w.max = s.max;
    w.choices = s.choices;
    w.logarithmic = s.min > 0.0 && s.max / s.min > 1000.0;
    switch (s.type) {
      case SettingSpec::Type::integer: w.kind = SettingWidget::Kind::int_slider; break;
      case SettingSpec::Type::real: w.kind = SettingWidget::Kind::float_slider; break;
      case SettingSpec::Type::choice: w.kind = SettingWidget::Kind::combo; break;
      case SettingSpec::Type::boolean: w.kind = SettingWidget::Kind::checkbox; break;
    }
    widgets.push_back(std::move(w));
  }
  return widgets;
}

bool draw_setting_widgets(const std::vector<SettingWidget>& widgets, Settings& settings) {
  bool changed = false;
  for (const SettingWidget& w : widgets) changed |= draw(w, settings);
  return changed;
}

void set_widget(const std::vector<SettingWidget>& widgets, Settings& settings, const std::string& label,
                const std::string& value) {
  const auto it = std::find_if(widgets.begin(), widgets.end(), [&](const SettingWidget& w) { return w.label == label; });
  if (it == widgets.end()) {
    std::string known;
    for (const SettingWidget& w : widgets) known += (known.empty() ? "" : ", ") + w.label;
    throw InputError("set", label, "no widget has this label (the method's: " + known + ")");
  }
  assign(settings, *it, value);
}

}  // namespace airlight::view
