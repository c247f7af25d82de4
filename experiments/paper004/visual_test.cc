#include "experiments/paper004/visual.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "harness/runner.h"
#include "plots/figures_testing.h"

namespace icp {
namespace {

namespace fs = std::filesystem;
using testing::FigureFiles;
using testing::GnuplotMissing;
using testing::TempDir;

RunRecord Teach(const std::string& algorithm, const std::string& w, std::uint64_t seed) {
  return ExecuteRun(RunSpec{algorithm, {}, "visual-landmarks", {{"w", w}}, seed, 0});
}

// Table 2 and Fig. 9 from real teach runs: LIC and DIGO at Xi = 10 with eta
// paired by seed, the paper's rows beside; DIGO's sweep in Fig. 9's table.
TEST(Paper004VisualTest, TablesFromTeachRuns) {
  std::vector<RunRecord> runs;
  for (std::uint64_t seed : {1u, 2u}) {
    runs.push_back(Teach("digo", "1", seed));
    runs.push_back(Teach("digo", "10", seed));
    runs.push_back(Teach("lic", "10", seed));
  }
  for (const RunRecord& r : runs) ASSERT_EQ(r.status, RunStatus::kOk) << r.reason;
  const std::vector<TextTable> tables = Paper004VisualTables(runs);
  ASSERT_EQ(tables.size(), 3u);
  const TextTable& table2 = tables[0];
  ASSERT_EQ(table2.rows.size(), 6u);
  EXPECT_EQ(table2.rows[0][0], "LIC");
  EXPECT_EQ(table2.rows[1][0], "DIGO");
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_GT(std::stod(table2.rows[2][2 + axis]), 0) << "eta on axis " << axis;  // DIGO narrower
    EXPECT_LT(std::stod(table2.rows[1][2 + axis]), std::stod(table2.rows[0][2 + axis]));
  }
  EXPECT_EQ(table2.rows[3][2], "0.117");
  const TextTable& fig9 = tables[1];
  ASSERT_EQ(fig9.rows.size(), 3u);  // DIGO at 1 and 10, LIC
  EXPECT_EQ(fig9.rows[0][1], "1");
  EXPECT_EQ(fig9.rows[2][0], "LIC (no window)");
  EXPECT_EQ(fig9.rows[0].back(), "100");  // every landmark box held its landmark
  EXPECT_TRUE(tables[2].rows.empty());    // no repeat runs
  EXPECT_NE(tables[2].notes.front().find("specs/repeat.yaml"), std::string::npos);

  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("paper004_visual");
  fs::create_directories(dir);
  PlotOutput out;
  Paper004VisualFigures(runs, dir.string(), &out);
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig9_window", "fig8_landmark_boxes"}));
  ASSERT_EQ(out.messages.size(), 1u);
  EXPECT_EQ(out.messages[0].rfind("fig12_13_repeat: skipped: ", 0), 0u);
  fs::remove_all(dir);
}

// Repeat runs at two windows: real time and post-localized, consistent.
TEST(Paper004VisualTest, RepeatTableFromRepeatRuns) {
  std::vector<RunRecord> runs;
  for (const char* w : {"3", "8"})
    runs.push_back(ExecuteRun(RunSpec{"digo", {}, "visual-landmarks",
                                      {{"phase", "repeat"}, {"route", "loop"}, {"speed", "1"},
                                       {"steps", "40"}, {"landmarks", "30"}, {"w", w}},
                                      1, 0}));
  const std::vector<PostLocalizationPoint> points = Paper004RepeatPostLocalization(runs);
  ASSERT_EQ(points.size(), 2u);
  for (const PostLocalizationPoint& p : points) {
    EXPECT_EQ(p.real_time.consistency_rate, 1);
    EXPECT_EQ(p.post.consistency_rate, 1);
    EXPECT_GT(p.post.steps, 0);
  }
  const TextTable repeat = Paper004VisualTables(runs)[2];
  ASSERT_EQ(repeat.rows.size(), 2u);
  EXPECT_EQ(repeat.rows[0][0], "DIGO");
  EXPECT_EQ(repeat.rows[0][4], "100");
}

}  // namespace
}  // namespace icp
