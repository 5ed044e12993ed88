// What the fuzzers found (fuzz/regressions/<target>/<case>), replayed through the
// loaders and parsers the command uses: each case's outcome — empty when accepted,
// the error's text when refused — is the one its <case>.expected file holds.
#include "inputs.hpp"
#include "methods.hpp"

#include "core/test_paths.hpp"

#include <airlight/method.hpp>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace airlight::fuzz {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

TEST(FuzzRegressions, EachCaseHasItsOutcome) {
  const fs::path root = test::source_dir() / "fuzz" / "regressions";
  int cases = 0;
  for (const auto& dir : fs::directory_iterator(root)) {
    const Outcome outcome = target(dir.path().filename().string());
    ASSERT_NE(outcome, nullptr) << dir.path() << " names no fuzz target";
    for (const auto& entry : fs::directory_iterator(dir.path())) {
      if (entry.path().extension() == ".expected") continue;
      const fs::path expected = fs::path(entry.path()).concat(".expected");
      ASSERT_TRUE(fs::exists(expected)) << expected;
      EXPECT_EQ(outcome(read(entry.path())), read(expected)) << entry.path();
      ++cases;
    }
  }
  EXPECT_GT(cases, 0);
}

// The option parsers' fuzz target knows three methods without their GPU code: they
// must be the registered ones, setting for setting.
TEST(FuzzMethods, AreTheRegisteredOnes) {
  for (const MethodInfo& fuzzed : {reference_info(), raymarch_info(), planes_info()}) {
    const MethodInfo& registered = find_method(fuzzed.name);
    EXPECT_EQ(fuzzed.capabilities.ground_truth, registered.capabilities.ground_truth) << fuzzed.name;
    ASSERT_EQ(fuzzed.settings.size(), registered.settings.size()) << fuzzed.name;
    for (size_t i = 0; i < fuzzed.settings.size(); ++i) {
      const SettingSpec &a = fuzzed.settings[i], &b = registered.settings[i];
      EXPECT_EQ(a.name, b.name) << fuzzed.name;
      EXPECT_EQ(a.type, b.type) << fuzzed.name << "." << a.name;
      EXPECT_EQ(a.default_value, b.default_value) << fuzzed.name << "." << a.name;
      EXPECT_EQ(a.min, b.min) << fuzzed.name << "." << a.name;
      EXPECT_EQ(a.max, b.max) << fuzzed.name << "." << a.name;
      EXPECT_EQ(a.choices, b.choices) << fuzzed.name << "." << a.name;
    }
  }
}

}  // namespace
}  // namespace airlight::fuzz
