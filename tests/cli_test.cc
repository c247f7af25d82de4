// The command-line contract (docs/cli.md): JSON fields, bounds that
// round-trip and enclose, null for infinite bounds, exit code 2 on bad input.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/minibex_parser.h"
#include "harness/results_store.h"
#include "tests/cli_helpers.h"

namespace {

using icp::testing::Result;
using icp::testing::WriteFile;

// Runs icpbench with args (stderr folded into the output).
Result Icpbench(const std::string& args) { return icp::testing::RunCommand(ICPBENCH_BINARY, args); }

std::string Example(const std::string& name) { return std::string(ICPBENCH_EXAMPLES) + "/" + name; }

TEST(CliTest, SolveJsonFollowsTheContract) {
  Result r = Icpbench("solve " + Example("paper002_sum.bch") + " --algorithm hc4 --format json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["algorithm"], "hc4");
  EXPECT_EQ(j["status"], "nonempty");
  EXPECT_EQ(j["box"]["x1"][0].get<double>(), 3.0);
  EXPECT_EQ(j["box"]["x1"][1].get<double>(), 4.0);
  EXPECT_EQ(j["box"]["x3"][1].get<double>(), 6.0);
  EXPECT_GE(j["time_s"].get<double>(), 0.0);
  EXPECT_EQ(j.size(), 4u);
}

// Five lines through (1, 2) and two that miss it: a relaxed CSP with two
// outliers, each constraint one measurement.
std::string RelaxedLinesFile() {
  return WriteFile("lines.bch",
                   "Variables x in [-10, 10]; y in [-10, 10];\n"
                   "Constraints\n"
                   "  x + y = 3; x - y = -1; 2*x + y = 4; x + 3*y = 7; x = 1;\n"
                   "  x + y = 8; y = -5;\n"
                   "end\n");
}

TEST(CliTest, RelaxedSolversAddQAndTheEstimate) {
  const std::string file = RelaxedLinesFile();
  for (const std::string algorithm : {"q-relaxed", "polynomial", "accumulator"}) {
    Result r = Icpbench("solve " + file + " --algorithm " + algorithm + " --format json");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["algorithm"], algorithm);
    EXPECT_EQ(j["status"], "nonempty");
    EXPECT_LE(j["box"]["x"][0].get<double>(), 1.0) << algorithm;
    EXPECT_GE(j["box"]["x"][1].get<double>(), 1.0) << algorithm;
    EXPECT_LE(j["box"]["y"][0].get<double>(), 2.0) << algorithm;
    EXPECT_GE(j["box"]["y"][1].get<double>(), 2.0) << algorithm;
    EXPECT_EQ(j["q"], 2) << algorithm;  // the fewest outliers any point has
    EXPECT_GE(j["time_s"].get<double>(), 0.0);
    EXPECT_EQ(j["estimate"]["kind"], algorithm == "accumulator" ? "accumulator" : "box");
    if (algorithm == "accumulator") {
      EXPECT_EQ(j["estimate"]["max_count"], 5);
    }
    if (algorithm == "polynomial") {
      ASSERT_EQ(j["by_q"].size(), 8u);
      for (int q = 0; q <= 7; ++q) EXPECT_EQ(j["by_q"][q]["q"], q);
      EXPECT_EQ(j["by_q"][0]["status"], "empty");
      EXPECT_TRUE(j["by_q"][0]["box"].empty());
      EXPECT_EQ(j["by_q"][2]["status"], "nonempty");
      EXPECT_EQ(j["by_q"][2]["box"], j["box"]);
    } else {
      EXPECT_FALSE(j.contains("by_q"));
    }
  }
}

TEST(CliTest, RelaxedSolversWithTooSmallAQAreEmpty) {
  Result r = Icpbench("solve " + RelaxedLinesFile() +
                      " --algorithm q-relaxed --param q=1 --param auto_q=false --format json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "empty");
  EXPECT_TRUE(j["box"].empty());
  EXPECT_EQ(j["q"], 1);
  r = Icpbench("solve " + RelaxedLinesFile() +
               " --algorithm q-relaxed --param mode=pave --param epsilon=0.01 --format json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["estimate"]["kind"], "paving");
  EXPECT_GE(j["estimate"]["boxes"].get<int>(), 1);
  EXPECT_EQ(j["q"], 2);
  r = Icpbench("solve " + RelaxedLinesFile() + " --algorithm accumulator --param q=-1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("accumulator.q = -1"), std::string::npos) << r.out;
}

TEST(CliTest, BoundsRoundTripAndEncloseTheSolution) {
  // x^2 = 2: the printed bounds, read back as doubles, still hold sqrt(2)
  // and are the very doubles the solver produced.
  std::string file = WriteFile("sqrt2.bch", "Variables x in [0, 10]; Constraints x^2 = 2; end");
  Result r = Icpbench("solve " + file + " --format json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  double lo = j["box"]["x"][0], hi = j["box"]["x"][1];
  EXPECT_LT(lo * lo, 2.0);  // lo < sqrt(2): lo^2 rounds below 2 for the tight bound
  EXPECT_GT(hi * hi, 2.0);
  EXPECT_LE(hi - lo, 4.5e-16);
}

TEST(CliTest, VectorComponentsAreNamedZeroBasedAndInfiniteBoundsAreNull) {
  std::string file = WriteFile("vec.bch",
                               "Variables v[2] in [-oo, +oo]; w in [0, +oo];"
                               " Constraints v(1) = 1; v[1] >= 0; end");
  Result r = Icpbench("solve " + file + " --format json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["box"]["v[0]"][0].get<double>(), 1.0);
  EXPECT_EQ(j["box"]["v[1]"][0].get<double>(), 0.0);
  EXPECT_TRUE(j["box"]["v[1]"][1].is_null());
  EXPECT_TRUE(j["box"]["w"][1].is_null());
  EXPECT_EQ(j["box"]["w"][0].get<double>(), 0.0);
}

TEST(CliTest, EmptyResultHasStatusEmptyAndNoBox) {
  std::string file = WriteFile("empty.bch", "Variables x in [0, 1]; Constraints x = 2; end");
  Result r = Icpbench("solve " + file + " --format json --algorithm bc4");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "empty");
  EXPECT_TRUE(j["box"].empty());
}

TEST(CliTest, RepeatReportsTheMedianAndTheSameBox) {
  Result once = Icpbench("solve " + Example("car_window.bch") + " --format json");
  Result many = Icpbench("solve " + Example("car_window.bch") + " --format json --repeat 5");
  ASSERT_EQ(many.exit_code, 0) << many.out;
  EXPECT_EQ(nlohmann::json::parse(once.out)["box"], nlohmann::json::parse(many.out)["box"]);
}

TEST(CliTest, SolveTimeoutStopsASlowSolverWithASoundBox) {
  // polynomial c2 is cubic in the measurements (500 lines: a minute) and
  // solve had no time limit. 300 lines through (1, 2), 60 of them missing it.
  std::string text = "Variables x in [-10, 10]; y in [-10, 10];\nConstraints\n";
  for (int i = 0; i < 300; ++i) {
    const double a = 3.14159 * i / 300, c = std::cos(a) + 2 * std::sin(a) + (i % 5 == 0 ? 3 : 0);
    text += "  (" + std::to_string(std::cos(a)) + "*x + " + std::to_string(std::sin(a)) + "*y - " +
            std::to_string(c) + ")^2 <= 0.0025;\n";
  }
  const std::string file = WriteFile("slow_lines.bch", text + "end\n");
  const auto start = std::chrono::steady_clock::now();
  Result r = Icpbench("solve " + file +
                      " --algorithm polynomial --param approximation=c2 --timeout 0.5"
                      " --format json");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_LT(seconds, 30);
  auto j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["stopped"].get<std::string>().find("time limit"), std::string::npos) << r.out;
  EXPECT_LE(j["box"]["x"][0].get<double>(), 1.0);
  EXPECT_GE(j["box"]["x"][1].get<double>(), 1.0);
  EXPECT_LE(j["box"]["y"][0].get<double>(), 2.0);
  EXPECT_GE(j["box"]["y"][1].get<double>(), 2.0);
  // A contraction that is not stopped says nothing of it.
  EXPECT_FALSE(nlohmann::json::parse(Icpbench("solve " + Example("paper002_sum.bch") +
                                              " --timeout 60 --format json")
                                         .out)
                   .contains("stopped"));
  for (const std::string bad : {"0", "-1", "nan"}) {
    r = Icpbench("solve " + Example("paper002_sum.bch") + " --timeout " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.out.find("--timeout " + bad + ": must be a number of seconds > 0"),
              std::string::npos)
        << r.out;
  }
  EXPECT_EQ(Icpbench("solve " + Example("paper002_sum.bch") + " --timeout inf").exit_code, 0);
}

TEST(CliTest, AnAccumulatorOverAPointDomainKeepsThePoint) {
  // x in [1, 1] gave the grid a zero cell width and solve a segfault.
  const std::string file = WriteFile("point.bch",
                                     "Variables x in [1, 1]; y in [0, 2];\n"
                                     "Constraints x + y = 2; x - y = 0; x = 3;\nend\n");
  Result r = Icpbench("solve " + file + " --algorithm accumulator --format json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["q"], 1);
  EXPECT_EQ(j["box"]["x"][0].get<double>(), 1.0);
  EXPECT_EQ(j["box"]["x"][1].get<double>(), 1.0);
  EXPECT_LE(j["box"]["y"][0].get<double>(), 1.0);
  EXPECT_GE(j["box"]["y"][1].get<double>(), 1.0);
}

TEST(CliTest, EveryAlgorithmSolvesTheExamples) {
  auto list = nlohmann::json::parse(Icpbench("list algorithms --format json").out);
  ASSERT_GE(list.size(), 6u);
  bool refused = false;
  for (const auto& a : list) {
    if (a.contains("test_only")) continue;
    if (a["needs"] == "probabilistic" || a["needs"] == "landmark-observations") {
      // A Minibex file offers no probabilistic or landmark-observation
      // view: solve says so.
      Result r = Icpbench("solve " + Example("paper000_3b.bch") + " --algorithm " +
                          a["name"].get<std::string>());
      EXPECT_EQ(r.exit_code, 2) << r.out;
      EXPECT_NE(r.out.find("icpbench run"), std::string::npos) << r.out;
      refused = true;
      continue;
    }
    Result r = Icpbench("solve " + Example("paper000_3b.bch") + " --format json --algorithm " +
                     a["name"].get<std::string>());
    ASSERT_EQ(r.exit_code, 0) << r.out;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_LE(j["box"]["x"][0].get<double>(), 0.0);
    EXPECT_GE(j["box"]["x"][1].get<double>(), 0.0);
  }
  EXPECT_TRUE(refused);  // particle-filter, landmark-tracking, dead-reckoning
}

TEST(CliTest, ListShowsNamesDescriptionsAndParameters) {
  auto list = nlohmann::json::parse(Icpbench("list algorithms --format json").out);
  bool found = false;
  for (const auto& a : list) {
    if (a["name"] != "hc4") continue;
    found = true;
    EXPECT_FALSE(a["description"].get<std::string>().empty());
    EXPECT_EQ(a["params"][0]["name"], "ratio");
    EXPECT_EQ(a["params"][0]["type"], "double");
    EXPECT_EQ(a["needs"], "csp");
    bool carry = false;
    for (const auto& p : a["params"]) carry |= p["name"] == "carry" && p["default"] == "first";
    EXPECT_TRUE(carry);
  }
  EXPECT_TRUE(found);
  for (const auto& a : list) EXPECT_TRUE(a.contains("needs")) << a["name"];
  auto problems = nlohmann::json::parse(Icpbench("list problems --format json").out);
  EXPECT_GE(problems.size(), 1u);
  for (const auto& p : problems) {
    ASSERT_TRUE(p["offers"].is_array()) << p["name"];
    if (p["name"] == "car-track") {
      EXPECT_EQ(p["offers"], nlohmann::json::array({"csp", "probabilistic"}));
    }
  }
  EXPECT_EQ(Icpbench("list algorithms").exit_code, 0);
}

TEST(CliTest, BadInputExitsWithTwoAndAClearMessage) {
  const std::string sum = Example("paper002_sum.bch");
  Result r = Icpbench("solve " + sum + " --algorithm nope");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown algorithm 'nope'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hc4"), std::string::npos) << r.out;  // lists the known ones

  r = Icpbench("solve " + sum + " --param speed=1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown parameter 'speed'"), std::string::npos) << r.out;

  r = Icpbench("solve " + sum + " --param ratio=-1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("hc4.ratio = -1"), std::string::npos) << r.out;

  r = Icpbench("solve " + sum + " --param ratio");
  EXPECT_EQ(r.exit_code, 2);

  r = Icpbench("solve /nonexistent/file.bch");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("/nonexistent/file.bch"), std::string::npos) << r.out;

  std::string bad = WriteFile("bad.bch", "Variables\n  x in [0, 1];\nConstraints\n  x + = 1;\nend\n");
  r = Icpbench("solve " + bad);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find(":4:"), std::string::npos) << r.out;  // line of the error

  EXPECT_EQ(Icpbench("solve " + sum + " --repeat 0").exit_code, 2);
  EXPECT_EQ(Icpbench("solve " + sum + " --format xml").exit_code, 2);
  EXPECT_EQ(Icpbench("list everything").exit_code, 2);
  r = Icpbench("frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown command 'frobnicate' (commands: solve, list, run"), std::string::npos)
      << r.out;

  // A test plugin is said to be one, not a view the file lacks.
  r = Icpbench("solve " + sum + " --algorithm fault");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("no contractor for one CSP"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("a harness test plugin"), std::string::npos) << r.out;
}

// Runs icpbench with only the given Slurm array variables set (any the test
// itself runs under are removed).
Result IcpbenchInArray(const std::string& vars, const std::string& args) {
  return icp::testing::RunCommand(
      "env -u SLURM_ARRAY_TASK_ID -u SLURM_ARRAY_TASK_COUNT -u SLURM_ARRAY_TASK_MIN "
      "-u SLURM_ARRAY_TASK_MAX " +
          vars + " " + ICPBENCH_BINARY,
      args);
}

// Key -> (status, the metrics but the times) of every run in dir's store.
std::map<std::string, std::string> RunsOf(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const icp::RunRecord& r :
       icp::ResultsStore::OpenReadOnly(icp::StorePath(dir))->LoadRuns(false)) {
    const icp::RunMetrics& m = r.metrics;
    std::ostringstream text;
    text.precision(17);
    text << icp::ToString(r.status) << " " << m.steps << " " << m.mean_area << " "
         << m.consistency_rate << " " << m.centre_rmse;
    for (const icp::Corridor& c : m.corridors)
      text << " " << c.var << " " << c.mean_lower << " " << c.mean_upper << " " << c.min_lower
           << " " << c.max_upper;
    out[r.spec.Key()] = text.str();
  }
  return out;
}

// --shard auto reads the shard of a Slurm array task (both forms of the
// variables); the shards' stores merged equal a one-shot run.
TEST(CliTest, ShardAutoTakesTheSlurmArrayTaskAndMergesToTheWholeSweep) {
  const std::string dir = ::testing::TempDir() + "cli_shard_auto";
  std::filesystem::remove_all(dir);
  const std::string spec =
      WriteFile("cli_shard_auto.yaml",
                "seeds: [1, 2, 3, 4, 5]\n"
                "algorithms: [hc4, bc4]\n"
                "problems: [chain, {name: car-track, params: {steps: 3, w: 2}}]\n");
  Result r = Icpbench("run " + spec + " --out " + dir + "/all --jobs 2");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::map<std::string, std::string> all = RunsOf(dir + "/all");
  ASSERT_EQ(all.size(), 20u);
  // --array=0-2 (COUNT) and --array=1-3 (MIN/MAX).
  std::string count_shards, range_shards;
  for (int task = 0; task < 3; ++task) {
    const std::string out = dir + "/count" + std::to_string(task);
    r = IcpbenchInArray("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " SLURM_ARRAY_TASK_COUNT=3",
                        "run " + spec + " --out " + out + " --jobs 2 --shard auto");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("shard " + std::to_string(task) + "/3"), std::string::npos) << r.out;
    count_shards += " " + out;
    const std::string range = dir + "/range" + std::to_string(task);
    r = IcpbenchInArray("SLURM_ARRAY_TASK_ID=" + std::to_string(task + 1) +
                            " SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=3",
                        "run " + spec + " --out " + range + " --jobs 2 --shard auto");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find((task < 2 ? "7" : "6") + std::string(" planned")), std::string::npos)
        << r.out;
    range_shards += " " + range;
    EXPECT_EQ(RunsOf(out), RunsOf(range));  // shard TASK_ID - MIN
  }
  ASSERT_EQ(Icpbench("merge " + dir + "/merged_count" + count_shards).exit_code, 0);
  r = Icpbench("merge " + dir + "/merged_range" + range_shards);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("conflicting"), std::string::npos) << r.out;  // no run in two shards
  EXPECT_EQ(RunsOf(dir + "/merged_count"), all);
  EXPECT_EQ(RunsOf(dir + "/merged_range"), all);
  std::filesystem::remove_all(dir);
}

TEST(CliTest, ShardAutoWithoutConsistentSlurmVariablesExitsWithTwo) {
  const std::string dir = ::testing::TempDir() + "cli_shard_auto_bad";
  std::filesystem::remove_all(dir);
  const std::string spec =
      WriteFile("cli_shard_auto_bad.yaml", "algorithms: [hc4]\nproblems: [chain]\n");
  const std::pair<std::string, std::string> cases[] = {
      {"", "SLURM_ARRAY_TASK_ID is not set"},
      {"SLURM_ARRAY_TASK_ID=1", "neither SLURM_ARRAY_TASK_COUNT"},
      {"SLURM_ARRAY_TASK_ID=one SLURM_ARRAY_TASK_COUNT=2",
       "SLURM_ARRAY_TASK_ID='one' is not a non-negative integer"},
      {"SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_COUNT=2", "is not below SLURM_ARRAY_TASK_COUNT=2"},
      {"SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=3",
       "outside [SLURM_ARRAY_TASK_MIN, SLURM_ARRAY_TASK_MAX] = [1, 3]"},
      {"SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_MAX=3",
       "SLURM_ARRAY_TASK_MAX is set but SLURM_ARRAY_TASK_MIN is not"},
      {"SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=8 "
       "SLURM_ARRAY_TASK_COUNT=5",
       "disagrees"},
  };
  for (const auto& [vars, message] : cases) {
    Result r = IcpbenchInArray(vars, "run " + spec + " --out " + dir + " --shard auto");
    EXPECT_EQ(r.exit_code, 2) << vars << ": " << r.out;
    EXPECT_NE(r.out.find(message), std::string::npos) << vars << ": " << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "/results.sqlite"));
}

// record: runs: report's table still works from the run metrics, and report
// and plot say what they leave out.
TEST(CliTest, ReportAndPlotSayWhatARunsOnlyStoreLacks) {
  const std::string dir = ::testing::TempDir() + "cli_record_runs";
  std::filesystem::remove_all(dir);
  const std::string spec = WriteFile("cli_record_runs.yaml",
                                     "record: runs\nseeds: [1, 2]\nalgorithms: [hc4]\n"
                                     "problems: [{name: car-track, params: {steps: 4, w: 2}}]\n");
  Result r = Icpbench("run " + spec + " --out " + dir + " --jobs 2");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = Icpbench("report " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("2 ok runs were recorded with `record: runs`"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| hc4 "), std::string::npos) << r.out;  // the table's row
  r = Icpbench("report " + dir + " --format csv");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("hc4,"), std::string::npos) << r.out;
  r = Icpbench("plot " + dir + " --out " + dir + "/figures");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("fig_timing: skipped: it needs step rows, and 2 runs were recorded with "
                       "`record: runs`"),
            std::string::npos)
      << r.out;
  std::filesystem::remove_all(dir);
}

// Resume, merge and report over stores (docs/cli.md, docs/store.md): a rerun retries the failed run unless --no-retry; merge and
// report refuse a missing or zero-byte store with exit 2 and write nothing.
// What run keeps but tables would miss, and what it cannot do, it says.
TEST(CliTest, RunSaysWhatItKeepsUnderAnotherExperimentAndRefusesAnEmptyOut) {
  const std::string dir = ::testing::TempDir() + "cli_renamed";
  std::filesystem::remove_all(dir);
  const std::string pilot = WriteFile(
      "cli_pilot.yaml", "experiments:\n  - {name: pilot, algorithms: [hc4], problems: [chain]}\n");
  const std::string renamed = WriteFile(
      "cli_renamed.yaml", "experiments:\n  - {name: table1, algorithms: [hc4], problems: [chain]}\n");
  ASSERT_EQ(Icpbench("run " + pilot + " --out " + dir).exit_code, 0);
  Result r = Icpbench("run " + renamed + " --out " + dir);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("1 of the runs already stored is filed under another experiment (e.g. "
                       "'pilot', planned here in 'table1')"),
            std::string::npos)
      << r.out;
  r = Icpbench("run " + renamed + " --out " + dir + " --force");
  EXPECT_EQ(r.out.find("filed under another"), std::string::npos) << r.out;
  r = Icpbench("run " + renamed + " --out " + dir);
  EXPECT_EQ(r.out.find("filed under another"), std::string::npos) << r.out;  // now table1's

  r = Icpbench("run " + renamed + " --out ''");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("--out is empty"), std::string::npos) << r.out;
  r = Icpbench("run " + renamed + " --out " + dir + "/shard --shard 1/2");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("shard 1/2 holds none of the 1 runs"), std::string::npos) << r.out;
  std::filesystem::remove_all(dir);
}

TEST(CliTest, RetryMergeAndReportOverStores) {
  const std::string dir = ::testing::TempDir() + "cli_stores";
  std::filesystem::remove_all(dir);
  const std::string spec = WriteFile("cli_stores.yaml",
                                     "algorithms: [hc4, {name: fault, params: {mode: throw}}]\n"
                                     "problems: [chain]\n");
  Result r = Icpbench("run " + spec + " --out " + dir + "/a --jobs 1");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("1 ok, 1 failed"), std::string::npos) << r.out;
  r = Icpbench("run " + spec + " --out " + dir + "/a --jobs 1 --no-retry");
  EXPECT_NE(r.out.find("2 already stored, 0 ok, 0 failed"), std::string::npos) << r.out;
  r = Icpbench("run " + spec + " --out " + dir + "/a --jobs 1");
  EXPECT_NE(r.out.find("1 already stored, 0 ok, 1 failed"), std::string::npos) << r.out;

  r = Icpbench("merge " + dir + "/out " + dir + "/a " + dir + "/missing");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(dir + "/missing/results.sqlite"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out/results.sqlite"));
  r = Icpbench("merge " + dir + "/out " + dir + "/a " + dir + "/a");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("conflicting"), std::string::npos) << r.out;  // the same runs twice
  EXPECT_NE(r.out.find("2 runs in"), std::string::npos) << r.out;

  std::filesystem::create_directories(dir + "/empty");
  std::ofstream(dir + "/empty/results.sqlite").close();
  for (const std::string& command : {"report " + dir + "/empty", "plot " + dir + "/empty",
                                     "merge " + dir + "/out2 " + dir + "/empty"}) {
    r = Icpbench(command);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.out;
    EXPECT_NE(r.out.find("empty file"), std::string::npos) << command << ": " << r.out;
  }
  EXPECT_EQ(std::filesystem::file_size(dir + "/empty/results.sqlite"), 0u);
  EXPECT_FALSE(std::filesystem::exists(dir + "/out2"));
  std::filesystem::remove_all(dir);
}

}  // namespace
