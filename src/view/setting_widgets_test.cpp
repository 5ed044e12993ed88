#include "view/setting_widgets.hpp"

#include <airlight/error.hpp>
#include <airlight/method.hpp>

#include <gtest/gtest.h>

namespace airlight::view {
namespace {

// Every method's settings get a widget of their type, labelled by name, with the spec's range.
TEST(SettingWidgets, EveryMethodsSpecsBecomeWidgets) {
  using Kind = SettingWidget::Kind;
  for (const MethodInfo& m : registered_methods()) {
    const auto widgets = setting_widgets(m.settings);
    ASSERT_EQ(widgets.size(), m.settings.size()) << m.name;
    for (size_t i = 0; i < widgets.size(); ++i) {
      const SettingSpec& s = m.settings[i];
      const SettingWidget& w = widgets[i];
      EXPECT_EQ(w.label, s.name);
      const Kind expected = s.type == SettingSpec::Type::integer ? Kind::int_slider
                            : s.type == SettingSpec::Type::real  ? Kind::float_slider
                            : s.type == SettingSpec::Type::choice ? Kind::combo
                                                                  : Kind::checkbox;
      EXPECT_EQ(w.kind, expected) << m.name << "." << s.name;
      if (expected == Kind::int_slider || expected == Kind::float_slider) {
        EXPECT_EQ(w.min, s.min);
        EXPECT_EQ(w.max, s.max);
      }
      if (expected == Kind::combo) {
        EXPECT_EQ(w.choices, s.choices);
      }
    }
  }
}

TEST(SettingWidgets, SetByLabelAsTheWidgetWould) {
  const MethodInfo& m = find_method("raymarch");
  const auto widgets = setting_widgets(m.settings);
  Settings settings(m.settings);
  set_widget(widgets, settings, "steps", "16");
  EXPECT_EQ(settings.integer("steps"), 16);
  set_widget(widgets, settings, "sampling", "uniform");
  EXPECT_EQ(settings.choice("sampling"), "uniform");
  EXPECT_THROW(set_widget(widgets, settings, "no_such_widget", "1"), InputError);
  EXPECT_THROW(set_widget(widgets, settings, "steps", "0"), InputError);  // below the slider's range
}

TEST(SettingWidgets, WideRangesAreLogarithmic) {
  const auto widgets = setting_widgets({{"a", SettingSpec::Type::real, 1, 1e-3, 10, {}, ""},
                                        {"b", SettingSpec::Type::integer, 64, 64, 8192, {}, ""},
                                        {"c", SettingSpec::Type::real, 0, 0, 1e6, {}, ""}});
  EXPECT_TRUE(widgets[0].logarithmic);   // four decades
  EXPECT_FALSE(widgets[1].logarithmic);  // 128×: linear is fine
  EXPECT_FALSE(widgets[2].logarithmic);  // a range from 0 has no logarithm
}

}  // namespace
}  // namespace airlight::view
