#include "experiments/paper004/paper004.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/paper000/paper000.h"
#include "experiments/registry.h"
#include "harness/metrics.h"
#include "harness/runner.h"
#include "plots/figures_testing.h"
#include "report/report_testing.h"

namespace icp {
namespace {

namespace fs = std::filesystem;
using testing::FigureFiles;
using testing::GnuplotMissing;
using testing::InExperiment;
using testing::MakeRun;
using testing::MarkdownRow;
using testing::RunsOnly;
using testing::TempDir;

constexpr int kSteps = 80;

// HC4 over a short car-track drive at window w, as experiment window plans it.
RunRecord WindowRun(int w, std::uint64_t seed = 1) {
  RunRecord r = ExecuteRun(RunSpec{"hc4", {}, "car-track",
                                   {{"w", std::to_string(w)}, {"steps", std::to_string(kSteps)}},
                                   seed, 0});
  EXPECT_EQ(r.status, RunStatus::kOk) << r.reason;
  return InExperiment(std::move(r), kPaper000Window);
}

std::string Md(const std::vector<RunRecord>& runs) { return Report(runs, "md", Paper004Tables); }

TEST(Paper004Test, RealTimeAndPostLocalizationSideBySide) {
  const std::vector<RunRecord> runs = {WindowRun(5), WindowRun(10)};
  const std::string md = Md(runs);
  const std::string row = MarkdownRow(md, "hc4 [steps=80]");
  ASSERT_FALSE(row.empty()) << md;
  // w = 5: the states 0..74 left a window (one spans w + 1 states); HC4 is
  // sound, so both are consistent at every step.
  const std::vector<StepRecord> post = PostLocalizedStates(runs[0].steps);
  ASSERT_EQ(post.size(), static_cast<std::size_t>(kSteps - 5));
  const RunMetrics pl = ComputeMetrics(post);
  const std::string expected = "| hc4 [steps=80] | 5 | 1 | 75 | 100 | 100 | " +
                               FormatNumber(runs[0].metrics.mean_area) + " | " +
                               FormatNumber(pl.mean_area) + " | " +
                               FormatRatio(pl.mean_area, runs[0].metrics.mean_area) + " |";
  EXPECT_EQ(row.substr(0, expected.size()), expected) << row;
}

TEST(Paper004Test, WithoutWindowRunsTheTableSaysWhichSpecMakesThem) {
  const std::string md = Md({InExperiment(MakeRun("hc4", {}, {}, 1, {1e-3}), "start")});
  EXPECT_NE(md.find("specs/default.yaml (experiment window) produces them"), std::string::npos) << md;
  EXPECT_EQ(md.find("| configuration | w |"), std::string::npos);
}

// The messages about the car track's figure (the visual system's figures
// have their own, experiments/paper004/visual_test.cc).
std::vector<std::string> CarTrackMessages(const PlotOutput& out) {
  std::vector<std::string> m;
  for (const std::string& s : out.messages)
    if (s.rfind("fig13_post_localization", 0) == 0) m.push_back(s);
  return m;
}

TEST(Paper004Test, TheFigureDrawsHc4NearestToThePapersWindow) {
  const std::vector<RunRecord> runs = {WindowRun(5), WindowRun(10, 2), WindowRun(10, 1)};
  const RunRecord* shown = Paper004FigureRun(runs);
  ASSERT_NE(shown, nullptr);
  EXPECT_EQ(shown->spec.problem_params.at("w"), "10");
  EXPECT_EQ(shown->spec.seed, 1u);
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("paper004");
  fs::create_directories(dir);
  PlotOutput out;
  Paper004Figures(runs, dir.string(), &out);
  EXPECT_TRUE(CarTrackMessages(out).empty()) << CarTrackMessages(out).front();
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig13_post_localization"}));
  PlotOutput none;
  Paper004Figures({}, dir.string(), &none);
  ASSERT_EQ(CarTrackMessages(none).size(), 1u);
  EXPECT_EQ(CarTrackMessages(none)[0].rfind("fig13_post_localization: skipped: ", 0), 0u);
  fs::remove_all(dir);
}

// Window runs recorded with `record: runs` keep no post-localized states:
// the figure says so instead of "no ok HC4 run".
TEST(Paper004Test, RunsRecordedWithoutStepsAreNamed) {
  const std::vector<RunRecord> runs = {RunsOnly(WindowRun(5)), RunsOnly(WindowRun(10))};
  PlotOutput out;
  Paper004Figures(runs, TempDir("paper004_runs_only").string(), &out);
  EXPECT_EQ(CarTrackMessages(out),
            (std::vector<std::string>{
                "fig13_post_localization: skipped: it needs step rows, and 2 runs were recorded "
                "with `record: runs` (experiment window; run metrics only, no step rows; rerun "
                "with record: steps to draw them)"}));
  EXPECT_TRUE(out.files.empty());
}

TEST(Paper004Test, IsRegistered) {
  bool found = false;
  for (const PaperInfo& p : Papers()) found = found || p.name == "paper004";
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace icp
