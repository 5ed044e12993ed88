#include <airlight/error.hpp>
#include <airlight/settings.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace airlight {
namespace {

Settings example() {
  using T = SettingSpec::Type;
  return Settings({{"steps", T::integer, 64, 1, 4096, {}, "samples per ray"},
                   {"tolerance", T::real, 1e-3, 1e-7, 0.1, {}, "relative accuracy"},
                   {"jitter", T::boolean, 0, 0, 1, {}, "jitter the start"},
                   {"noise", T::choice, 1, 0, 0, {"white", "blue"}, "noise kind"}});
}

TEST(Settings, DefaultsAndAssignments) {
  Settings s = example();
  EXPECT_EQ(s.integer("steps"), 64);
  EXPECT_EQ(s.choice("noise"), "blue");
  s.set("steps=128", "--set");
  s.set("jitter=true", "--set");
  s.set("noise", "white", "--set");
  s.set("tolerance=2.5e-4", "--set");
  EXPECT_EQ(s.integer("steps"), 128);
  EXPECT_TRUE(s.boolean("jitter"));
  EXPECT_EQ(s.choice("noise"), "white");
  EXPECT_DOUBLE_EQ(s.real("tolerance"), 2.5e-4);
  EXPECT_EQ(s.to_json()["steps"], 128);
  EXPECT_EQ(s.describe(), "jitter=true noise=white steps=128 tolerance=0.00025");
}

void expect_rejected(const std::string& assignment, const std::string& key, const std::string& fragment) {
  Settings s = example();
  try {
    s.set(assignment, "--set");
    FAIL() << assignment;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--set");
    EXPECT_EQ(e.key(), key);
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Settings, BadAssignmentsNameTheKey) {
  expect_rejected("stepz=3", "stepz", "unknown setting (known: steps, tolerance, jitter, noise)");
  expect_rejected("steps", "steps", "expected key=value");
  expect_rejected("steps=1.5", "steps", "expected an integer");
  expect_rejected("steps=0", "steps", "outside [1, 4096]");
  expect_rejected("tolerance=nan", "tolerance", "a finite number");
  expect_rejected("tolerance=", "tolerance", "a finite number");
  expect_rejected("jitter=maybe", "jitter", "expected true or false");
  expect_rejected("noise=pink", "noise", "expected one of white, blue");
}

}  // namespace
}  // namespace airlight
