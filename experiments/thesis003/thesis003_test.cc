#include "experiments/thesis003/thesis003.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/grid.h"
#include "experiments/thesis003/city_roads.h"
#include "experiments/thesis003/fig5_2.h"
#include "experiments/registry.h"
#include "plots/figures_testing.h"
#include "report/report_testing.h"

namespace icp {
namespace {

namespace fs = std::filesystem;
using testing::FigureFiles;
using testing::GnuplotMissing;
using testing::InExperiment;
using testing::MarkdownRow;
using testing::PixelsOfColour;
using testing::RunsOnly;
using testing::StderrOf;
using testing::TempDir;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr char kCityRoadsMissing[] =
    "fig4_17_city_roads: skipped: no ok HC4 run of experiment city-roads with roads=false and "
    "roads=true";
constexpr char kFig52Missing[] =
    "fig5_2_box_polynomials: skipped: no ok polynomial run of experiment fig5_2 with ";

// The report's Markdown from the table's title on (the generic table comes
// first).
std::string Md(const std::vector<RunRecord>& runs) {
  const std::string md = testing::WithoutProfiles(Report(runs, "md", Thesis003Tables));
  const std::size_t at = md.find("## Thesis 003: relaxed solvers");
  return at == std::string::npos ? "" : md.substr(at);
}

// A step of a planar problem: its box is [-a/2, a/2] x [-1, 1] (area a)
// unless empty; q and true_outliers as given (none when unset).
StepRecord MakeStep(int contained, double area, std::optional<int> q, std::optional<int> k,
                    double time_s, bool empty = false) {
  StepRecord s;
  s.status = empty ? "empty" : "fixpoint";
  s.contained = contained;
  if (empty) {
    s.vars = {{"x", kInf, -kInf, 0}, {"y", kInf, -kInf, 0}};
    s.area = std::numeric_limits<double>::quiet_NaN();
  } else {
    s.vars = {{"x", -area / 4, area / 4, 0}, {"y", -1, 1, 0}};
    s.area = area;
  }
  s.solve_time_s = time_s;
  if (q) s.properties.push_back({"q", static_cast<std::int64_t>(*q)});
  if (k) s.properties.push_back({"true_outliers", static_cast<std::int64_t>(*k)});
  return s;
}

RunRecord MakeRun(const std::string& algorithm, ParamMap algorithm_params,
                  const std::string& problem, ParamMap problem_params, std::uint64_t seed,
                  std::vector<StepRecord> steps, const std::string& experiment,
                  RunStatus status = RunStatus::kOk) {
  RunRecord r;
  r.spec = {algorithm, std::move(algorithm_params), problem, std::move(problem_params), seed};
  r.status = status;
  if (status != RunStatus::kOk) r.reason = "threw: boom";
  for (std::size_t i = 0; i < steps.size(); ++i) steps[i].step = static_cast<int>(i);
  r.steps = std::move(steps);
  r.metrics = ComputeMetrics(r.steps);
  return InExperiment(std::move(r), experiment);
}

// The lines-accumulator run of specs/relaxed.yaml at a small resolution.
RunRecord LinesAccumulatorRun(std::uint64_t seed, int cells = 100) {
  return MakeRun("accumulator", {{"cells", std::to_string(cells)}}, "line-intersection",
                 {{"lines", "20"}, {"outliers", "7"}}, seed, {}, kThesis003LinesAccumulator);
}
RunRecord Fig55Run(int cells = 100) {
  return MakeRun("accumulator", {{"cells", std::to_string(cells)}}, "beacon-ranges",
                 {{"scenario", "two-robots"}}, 1, {}, kThesis003Fig55);
}

// A polynomial run of experiment fig5_2 on Fig. 5.2's 20 lines.
RunRecord PolynomialRun(const std::string& approximation, int p, std::uint64_t seed = 1) {
  return MakeRun("polynomial", {{"approximation", approximation}, {"p", std::to_string(p)}},
                 "line-intersection", {{"lines", "20"}, {"outliers", "7"}}, seed, {},
                 kThesis003Fig52);
}

TEST(Thesis003Test, Fig52RunIsTheSmallestOkSeedOfItsApproximationAndP) {
  const std::vector<RunRecord> runs = {PolynomialRun("c3", 10, 2), PolynomialRun("c3", 10, 1),
                                       PolynomialRun("c3", 1), PolynomialRun("c1", 10)};
  EXPECT_EQ(Fig52PolynomialRun(runs, "c3", 10), &runs[1]);
  EXPECT_EQ(Fig52PolynomialRun(runs, "c3", 1), &runs[2]);
  EXPECT_EQ(Fig52PolynomialRun(runs, "c1", 30), nullptr);
}

// The white coefficient (degree n - q = 13) encloses the truth whatever p,
// narrows as p grows, and C*(3) at p = 10 is every 10th coefficient of
// C^(p*).
TEST(Thesis003Test, Fig52WhiteCoefficientHoldsTheTruthAndNarrowsWithP) {
  const RecomputedPolynomial a = RecomputePolynomial(PolynomialRun("c3", 1));
  const RecomputedPolynomial b = RecomputePolynomial(PolynomialRun("c3", 10), true);
  const RecomputedPolynomial d = RecomputePolynomial(PolynomialRun("c1", 30));
  EXPECT_EQ(a.white, 13);
  ASSERT_EQ(a.coefficients.size(), 21u);
  ASSERT_EQ(b.repeated.size(), 201u);
  EXPECT_EQ(a.lines.size(), 20u);
  ASSERT_EQ(a.truth.size(), 2u);
  for (const RecomputedPolynomial* r : {&a, &b, &d}) {
    const Box& white = r->coefficients[r->white];
    EXPECT_TRUE(white[0].Contains(r->truth[0]) && white[1].Contains(r->truth[1]));
  }
  for (int k = 0; k <= 20; ++k) EXPECT_EQ(b.coefficients[k], b.repeated[10 * k]) << k;
  EXPECT_LT(WidestSide(b.coefficients[13]), WidestSide(a.coefficients[13]));
  EXPECT_LT(WidestSide(d.coefficients[13]), WidestSide(a.coefficients[13]));
}

TEST(Thesis003Test, Fig52FigureIsDrawn) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("thesis003_fig5_2");
  fs::create_directories(dir);
  PlotOutput out;
  Fig52Figure({PolynomialRun("c3", 1), PolynomialRun("c3", 10), PolynomialRun("c1", 30)},
              dir.string(), &out);
  EXPECT_TRUE(out.messages.empty()) << ::testing::PrintToString(out.messages);
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig5_2_box_polynomials"}));
  fs::remove_all(dir);
}

TEST(Thesis003Test, CityRoadsFigureDrawsTheHc4RunsWithAndWithoutTheRoads) {
  const std::vector<StepRecord> steps = {MakeStep(1, 4, std::nullopt, std::nullopt, 1e-3),
                                         MakeStep(1, 8, std::nullopt, std::nullopt, 1e-3)};
  const std::vector<RunRecord> runs = {
      MakeRun("bc4", {}, "city-roads", {{"roads", "false"}}, 1, steps, kThesis003CityRoads),
      MakeRun("hc4", {}, "city-roads", {{"roads", "false"}}, 2, steps, kThesis003CityRoads),
      MakeRun("hc4", {}, "city-roads", {}, 1, steps, kThesis003CityRoads),
      MakeRun("hc4", {}, "city-roads", {{"roads", "false"}}, 1, steps, "other"),
  };
  EXPECT_EQ(CityRoadsRun(runs, false), &runs[1]);
  EXPECT_EQ(CityRoadsRun(runs, true), &runs[2]);
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("thesis003_city");
  fs::create_directories(dir);
  PlotOutput out;
  CityRoadsFigure(runs, dir.string(), &out);
  EXPECT_TRUE(out.messages.empty()) << ::testing::PrintToString(out.messages);
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig4_17_city_roads"}));
  PlotOutput none;
  CityRoadsFigure({runs[2]}, dir.string(), &none);
  EXPECT_EQ(none.messages,
            std::vector<std::string>{"fig4_17_city_roads: skipped: no ok HC4 run of experiment "
                                     "city-roads with roads=false"});
  fs::remove_all(dir);
}

TEST(Thesis003Test, TableFromHandMadeRuns) {
  const ParamMap lines3 = {{"lines", "20"}, {"outliers", "3"}};
  const std::vector<RunRecord> runs = {
      // Two seeds of q-relaxed: 3 steps, 2 hold the truth, q 3, 2, 4 for 3
      // true outliers each, times 1, 3, 2 ms.
      MakeRun("q-relaxed", {}, "line-intersection", lines3, 1,
              {MakeStep(1, 2, 3, 3, 1e-3), MakeStep(1, 4, 2, 3, 3e-3)}, kThesis003RelaxedLines),
      MakeRun("q-relaxed", {}, "line-intersection", lines3, 2, {MakeStep(0, 6, 4, 3, 2e-3)},
              kThesis003RelaxedLines),
      // A failed run counts in "runs" only.
      MakeRun("q-relaxed", {}, "line-intersection", lines3, 3, {}, kThesis003RelaxedLines,
              RunStatus::kFailed),
      // HC4: no q; one empty step.
      MakeRun(
          "hc4", {}, "beacon-ranges", {{"scenario", "random"}, {"outliers", "1"}}, 1,
          {MakeStep(0, 0, std::nullopt, 1, 0.5e-3, true), MakeStep(1, 1, std::nullopt, 0, 1.5e-3)},
          kThesis003RelaxedBeacons),
      // Other experiments' configurations have no row.
      MakeRun("polynomial", {}, "line-intersection", lines3, 1, {MakeStep(1, 2, 3, 3, 1e-3)},
              "start"),
  };
  const std::string md = Md(runs);
  EXPECT_EQ(MarkdownRow(md, "q-relaxed"),
            "| q-relaxed | line-intersection {lines=20,outliers=3} | 2 of 3 | 3 | 0.6667 | 4.5 | 3 | "
            "3 | 0.6667 | 0 | 2 |")
      << md;
  // Area and time: the median over the runs of each run's mean (areas 3 and
  // 6, times 2 and 2 ms), in the unit the column's values pick.
  EXPECT_NE(md.find("| mean area (m²) [95% CI] |"), std::string::npos);
  EXPECT_NE(md.find("| time per step (ms) [95% CI] |"), std::string::npos);
  EXPECT_EQ(MarkdownRow(md, "HC4"),
            "| HC4 | beacon-ranges {outliers=1,scenario=random} | 1 | 2 | 0.5 | 1 | — | 0.5 | — | "
            "0.5 | 1 |");
  EXPECT_EQ(MarkdownRow(md, "polynomial"), "");
  EXPECT_NE(md.find("failed (seed 3): threw: boom"), std::string::npos);
}

TEST(Thesis003Test, TableWithoutItsExperimentsSaysSo) {
  const std::string md = Md({MakeRun("q-relaxed", {}, "line-intersection", {}, 1,
                                     {MakeStep(1, 2, 3, 3, 1e-3)}, "other")});
  EXPECT_EQ(MarkdownRow(md, "q-relaxed"), "");
  EXPECT_NE(md.find("No run of experiment relaxed-lines or relaxed-beacons in the store."),
            std::string::npos)
      << md;
}

TEST(Thesis003Test, FigureRunIsTheSmallestOkSeedOfTheExperiment) {
  std::vector<RunRecord> runs = {
      LinesAccumulatorRun(3),
      LinesAccumulatorRun(2),
      MakeRun("accumulator", {}, "line-intersection", {}, 1, {}, kThesis003LinesAccumulator,
              RunStatus::kFailed),
      // The same parameters in another experiment, or another algorithm.
      MakeRun("accumulator", {{"cells", "100"}}, "line-intersection", {}, 1, {}, "relaxed-lines"),
      MakeRun("q-relaxed", {}, "line-intersection", {}, 1, {}, kThesis003LinesAccumulator),
  };
  EXPECT_EQ(Thesis003FigureRun(runs, kThesis003LinesAccumulator), &runs[1]);
  EXPECT_EQ(Thesis003FigureRun(runs, kThesis003Fig55), nullptr);
}

TEST(Thesis003Test, RecomputedLinesAccumulatorMaximumHoldsTheTruth) {
  const RecomputedAccumulator a = RecomputeAccumulator(LinesAccumulatorRun(1));
  ASSERT_EQ(a.counts.size(), 2u);  // one source and the sum
  const cv::Mat& sum = a.counts.back();
  EXPECT_EQ(sum.rows, 100);
  EXPECT_EQ(sum.cols, 100);
  EXPECT_EQ(a.measurements, std::vector<int>{20});
  EXPECT_EQ(a.outliers, std::vector<int>{7});
  ASSERT_EQ(a.truth.size(), 2u);
  const Grid grid(Box({a.x, a.y}), 0, 1, sum.cols, sum.rows);
  int row = -1, col = -1;
  ASSERT_TRUE(grid.CellOf(a.truth[0], a.truth[1], &row, &col));
  const AccumulatorMaximum m = FindMaximum(sum);
  EXPECT_EQ(m.count, 13);  // the 13 consistent lines
  EXPECT_EQ(sum.at<int>(row, col), m.count);
  EXPECT_EQ(m.regions, 1);
  EXPECT_LE(m.row0, row);
  EXPECT_LT(row, m.row1);
  EXPECT_LE(m.col0, col);
  EXPECT_LT(col, m.col1);
}

TEST(Thesis003Test, RecomputedTwoRobotsHaveSeveralMaximaAndTheirSumOne) {
  const RecomputedAccumulator a = RecomputeAccumulator(Fig55Run());
  ASSERT_EQ(a.counts.size(), 3u);
  EXPECT_EQ(a.measurements, (std::vector<int>{3, 4}));
  EXPECT_EQ(a.outliers, (std::vector<int>{1, 2}));
  ASSERT_EQ(a.beacons.size(), 2u);
  EXPECT_EQ(a.beacons[0].size(), 3u);
  EXPECT_EQ(a.beacons[1].size(), 4u);
  EXPECT_EQ(a.beacons[0][0], (std::pair<double, double>{-6, 5}));
  const AccumulatorMaximum ma = FindMaximum(a.counts[0]), mb = FindMaximum(a.counts[1]),
                           sum = FindMaximum(a.counts[2]);
  EXPECT_EQ(ma.count, 2);
  EXPECT_GE(ma.regions, 3);
  EXPECT_EQ(mb.count, 2);
  EXPECT_GE(mb.regions, 3);
  EXPECT_EQ(sum.count, 4);
  EXPECT_EQ(sum.regions, 1);
  const Grid grid(Box({a.x, a.y}), 0, 1, a.counts[2].cols, a.counts[2].rows);
  int row = -1, col = -1;
  ASSERT_TRUE(grid.CellOf(a.truth[0], a.truth[1], &row, &col));
  EXPECT_EQ(a.counts[2].at<int>(row, col), 4);
}

TEST(Thesis003Test, BlockMaxKeepsEachBlocksMaximum) {
  cv::Mat counts(5, 3, CV_32S, cv::Scalar(0));
  counts.at<int>(4, 2) = 9;
  counts.at<int>(0, 1) = 3;
  const cv::Mat small = BlockMax(counts, 2);  // blocks of 3 x 3
  ASSERT_EQ(small.rows, 2);
  ASSERT_EQ(small.cols, 1);
  EXPECT_EQ(small.at<int>(0, 0), 3);
  EXPECT_EQ(small.at<int>(1, 0), 9);
  EXPECT_EQ(BlockMax(counts, 5).rows, 5);
}

TEST(Thesis003Test, FiguresAreWritten) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("thesis003_all");
  fs::create_directories(dir);
  PlotOutput out;
  Thesis003Figures({LinesAccumulatorRun(2), LinesAccumulatorRun(1), Fig55Run()}, dir.string(), &out);
  // Chapter 6's figures have no run here (marina_test.cc draws them).
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{
                std::string(kFig52Missing) + "approximation=c3 p=1, approximation=c3 p=10, "
                                             "approximation=c1 p=30",
                "fig6_7_dead_reckoning: skipped: no ok run of experiment marina or marina-*",
                "fig6_8_marina_tracks: skipped: no ok run of experiment marina or marina-*",
                "fig6_9_particles: skipped: no ok run of experiment marina or marina-*",
                "fig6_errors: skipped: no ok run of experiment marina or marina-*",
                kCityRoadsMissing}));
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig_lines_accumulator", "fig5_5_robot_a",
                                         "fig5_6_robot_b", "fig5_7_sum"}));
  for (const std::string& f : out.files) EXPECT_GT(fs::file_size(f), 0u) << f;
  fs::remove_all(dir);
}

// accumulator cells=1 is in range: the lines' accumulator of its one cell is a readable
// image (gnuplot draws no image of fewer than 2 x 2 points), without a
// gnuplot warning. The run needs no steps (the figure recomputes it), so one
// recorded with `record: runs` draws too.
TEST(Thesis003Test, OneCellAccumulatorIsDrawnWithoutWarnings) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("thesis003_one_cell");
  fs::create_directories(dir);
  PlotOutput out;
  const std::string err =
      StderrOf([&] { Thesis003Figures({RunsOnly(LinesAccumulatorRun(1, 1))}, dir.string(), &out); });
  EXPECT_EQ(err, "");
  ASSERT_EQ(out.files.size(), 2u) << ::testing::PrintToString(out.messages);
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig_lines_accumulator"}));
  // All 20 lines cross the one cell: it is the maximum, the palette's top.
  EXPECT_GT(PixelsOfColour(out.files[0], 0xfd, 0xe7, 0x25), 40000);
  fs::remove_all(dir);
}

TEST(Thesis003Test, WithoutItsExperimentsTheFiguresSaySo) {
  const fs::path dir = TempDir("thesis003_none");
  PlotOutput out;
  Thesis003Figures({MakeRun("accumulator", {}, "line-intersection", {}, 1, {}, "relaxed-lines")},
                   dir.string(), &out);
  EXPECT_TRUE(out.files.empty());
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{
                std::string(kFig52Missing) + "approximation=c3 p=1, approximation=c3 p=10, "
                                             "approximation=c1 p=30",
                "fig_lines_accumulator: skipped: no ok accumulator run of experiment "
                "lines-accumulator",
                "fig5_5_robot_a: skipped: no ok accumulator run of experiment fig5_5",
                "fig5_6_robot_b: skipped: no ok accumulator run of experiment fig5_5",
                "fig5_7_sum: skipped: no ok accumulator run of experiment fig5_5",
                "fig6_7_dead_reckoning: skipped: no ok run of experiment marina or marina-*",
                "fig6_8_marina_tracks: skipped: no ok run of experiment marina or marina-*",
                "fig6_9_particles: skipped: no ok run of experiment marina or marina-*",
                "fig6_errors: skipped: no ok run of experiment marina or marina-*",
                kCityRoadsMissing}));
}

TEST(Thesis003Test, IsRegistered) {
  ASSERT_EQ(Papers().size(), 4u);  // paper000, paper002, thesis003, paper004
  EXPECT_EQ(Papers()[2].name, "thesis003");
  const std::vector<RunRecord> runs = {MakeRun("q-relaxed", {}, "line-intersection", {}, 1,
                                               {MakeStep(1, 2, 3, 3, 1e-3)},
                                               kThesis003RelaxedLines)};
  EXPECT_NE(Report(runs, "md", PaperTables).find("| q-relaxed | line-intersection |"),
            std::string::npos);
  // Through the plots' registry entry too.
  const fs::path dir = TempDir("thesis003_registered");
  const PlotOutput out = PlotRuns({}, dir.string(), PaperFigures);
  EXPECT_NE(std::find(out.messages.begin(), out.messages.end(),
                      "fig5_7_sum: skipped: no ok accumulator run of experiment fig5_5"),
            out.messages.end());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace icp
