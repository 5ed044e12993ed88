// `airlight random` end to end: its bad input, a scene file judged (a
// failure's reproduction), and a results file that a rerun resumes.
#include "app/command_test_support.hpp"

namespace airlight {
namespace {

using namespace test;

TEST(RandomCommand, SeedsOutOfOrderAreBadInput) {
  const Outcome o = run_airlight("random --seeds 5:5");
  expect_bad_input(o, "--seeds", "5:5", "an empty range");
  EXPECT_NE(o.err.find("expected FIRST:END, whole numbers with FIRST < END (seeds FIRST to END − 1)"),
            std::string::npos) << o.err;
  expect_bad_input(run_airlight("random --seeds 3"), "--seeds", "3", "no colon");
}

TEST(RandomCommand, TheReferenceIsNotJudged) {
  const Outcome o = run_airlight("random --methods raymarch,reference");
  expect_bad_input(o, "--methods", "reference", "the reference among the judged");
  EXPECT_NE(o.err.find("the reference is what methods are judged against"), std::string::npos) << o.err;
}

// A failure's reproduction: the scene file judged by one method, its rows on stdout.
TEST(RandomCommand, ASceneFileIsJudgedAtTheDefaultsAndInEveryTrial) {
  const Outcome o = run_airlight("random --builtin biri_sphere --methods analytic --size 16x12");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out.rfind("seed,structure,cases,method,trial,measure,value,bound,verdict,seconds,detail\n", 0), 0u);
  EXPECT_NE(o.out.find("biri_sphere,0,,analytic,defaults,rel_rmse,"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("biri_sphere,0,,analytic,exact,worst_pixel,"), std::string::npos) << o.out;
}

// Rows are appended a seed at a time; a rerun skips the seeds the file holds,
// and a line a killed run left unfinished is dropped and its seed run again.
TEST(RandomCommand, ARerunResumesFromTheResultsFile) {
  const fs::path results = work_dir() / "resume.csv";
  // Whether the seeds' judgements pass is not what this holds: the exit status
  // is the same on every run, as a resumed run counts the file's failures too.
  const std::string args = "random --seeds 0:2 --methods analytic --size 16x12 --failures " +
                           (work_dir() / "failures").string() + " --results " + results.string();
  const Outcome first = run_airlight(args);
  ASSERT_TRUE(first.status == 0 || first.status == 1) << first.err;
  const std::string rows = read_text(results);
  ASSERT_FALSE(rows.empty());

  const Outcome second = run_airlight(args);
  EXPECT_EQ(second.status, first.status) << second.err;
  EXPECT_NE(second.err.find("2 already in " + results.string()), std::string::npos) << second.err;
  EXPECT_EQ(read_text(results), rows);

  std::ofstream(results, std::ios::app) << "2,0,,analytic,defa";  // a killed run's last line
  const Outcome third = run_airlight("random --seeds 0:3 --methods analytic --size 16x12 --no-shrink --failures " +
                                     (work_dir() / "failures").string() + " --results " + results.string());
  ASSERT_TRUE(third.status == 0 || third.status == 1) << third.err;
  EXPECT_NE(third.err.find("2 already in"), std::string::npos) << third.err;
  const std::string after = read_text(results);
  EXPECT_EQ(after.rfind(rows, 0), 0u);
  EXPECT_EQ(after.find("defa\n"), std::string::npos);
  EXPECT_NE(after.find("\n2,"), std::string::npos);
}

// A known failure that passes fails the run, so the list cannot outlive its defects.
TEST(RandomCommand, AKnownFailureThatPassesFails) {
  const fs::path known = write_file("known.csv", "# seed,method,trial,reason\nbiri_sphere,analytic,defaults,test\n");
  const Outcome o = run_airlight("random --builtin biri_sphere --methods analytic --size 16x12 --no-shrink --failures " +
                                 (work_dir() / "failures").string() + " --known " + known.string());
  EXPECT_EQ(o.status, 1) << o.err;
  EXPECT_NE(o.err.find("analytic (defaults) fails: rel_rmse: listed in " + known.string() + " but passes: take its line out"),
            std::string::npos) << o.err;
}

TEST(RandomCommand, AKnownFailuresLineWithoutItsReasonIsBadInput) {
  const fs::path known = write_file("short.csv", "7,hybrid,defaults\n");
  const Outcome o = run_airlight("random --builtin biri_sphere --methods analytic --known " + known.string());
  expect_bad_input(o, known.string(), "line 1", "three fields");
  EXPECT_NE(o.err.find("expected seed,method,trial,reason"), std::string::npos) << o.err;
}

// `--results -` (README "Pipes"): the same rows on standard output, after the header.
TEST(RandomCommand, ResultsDashWritesTheSameCsvToStandardOutput) {
  const fs::path results = work_dir() / "piped.csv";
  const std::string args = "random --seeds 5:6 --methods analytic --size 16x12 --no-shrink --failures " +
                           (work_dir() / "failures").string() + " --results ";
  const Outcome file = run_airlight(args + results.string());
  ASSERT_TRUE(file.status == 0 || file.status == 1) << file.err;
  EXPECT_EQ(file.out, "");
  const Outcome piped = run_airlight(args + "-");
  EXPECT_EQ(piped.status, file.status) << piped.err;

  const Table written = read_csv(results), printed = parse_csv(piped.out);
  ASSERT_GE(printed.size(), 2u) << piped.out;
  EXPECT_EQ(printed[0][0], "seed");
  const auto varies = [](const std::string& name) { return name == "seconds"; };
  EXPECT_EQ(without_columns(printed, varies), without_columns(written, varies));
}

}  // namespace
}  // namespace airlight
