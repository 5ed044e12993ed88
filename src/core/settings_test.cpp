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

void expect_rejected(const std::string& assignment, const std::string& key, const std::string& message) {
  Settings s = example();
  try {
    s.set(assignment, "--set");
    FAIL() << assignment;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--set");
    EXPECT_EQ(e.key(), key);
    EXPECT_EQ(e.message(), message);
  }
}

TEST(Settings, BadAssignmentsNameTheKey) {
  expect_rejected("stepz=3", "stepz", "unknown setting (known: steps, tolerance, jitter, noise)");
  expect_rejected("steps", "steps", "expected key=value");
  expect_rejected("steps=1.5", "steps", "expected an integer, got '1.5'");
  expect_rejected("steps=0", "steps", "must be in [1, 4096], got 0");
  expect_rejected("steps=1e999", "steps", "must be in [1, 4096], got 1e999");
  expect_rejected("tolerance=1", "tolerance", "must be in [1e-07, 0.1], got 1");
  expect_rejected("tolerance=nan", "tolerance", "expected a finite number, got 'nan'");
  expect_rejected("tolerance=inf", "tolerance", "expected a finite number, got 'inf'");
  expect_rejected("tolerance=", "tolerance", "expected a finite number, got ''");
  expect_rejected("tolerance=0.1x", "tolerance", "expected a finite number, got '0.1x'");
  expect_rejected("jitter=maybe", "jitter", "expected true or false, got 'maybe'");
  expect_rejected("noise=pink", "noise", "expected one of white, blue, got 'pink'");
}

TEST(Settings, DescribeValuesGivesTheRangeAndTheDefault) {
  const Settings settings = example();
  const auto& specs = settings.specs();
  EXPECT_EQ(describe_values(specs[0]), "integer in [1, 4096], default 64");
  EXPECT_EQ(describe_values(specs[1]), "number in [1e-07, 0.1], default 0.001");
  EXPECT_EQ(describe_values(specs[2]), "true or false, default false");
  EXPECT_EQ(describe_values(specs[3]), "one of: white, blue; default blue");
  // Counts of a million and more in whole digits, as they are typed.
  const SettingSpec count{"max_edges", SettingSpec::Type::integer, 1e6, 1, 1e9, {}, "edges"};
  EXPECT_EQ(describe_values(count), "integer in [1, 1000000000], default 1000000");
}

}  // namespace
}  // namespace airlight
