#include "plots/figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/metrics.h"
#include "plots/figures_internal.h"
#include "plots/figures_testing.h"

namespace icp {
namespace {

namespace fs = std::filesystem;
using testing::FigureFiles;
using testing::GnuplotMissing;
using testing::PixelsOfColour;
using testing::RunsOnly;
using testing::StderrOf;
using testing::TempDir;

// A synthetic car-track run: a box around a circular track whose width
// shrinks over the first steps, times spread around base_time_s.
RunRecord MakeRun(const std::string& algorithm, const std::string& problem, ParamMap problem_params,
                  std::uint64_t seed, int steps, double base_time_s, double half_width) {
  RunRecord r;
  r.spec.algorithm = algorithm;
  r.spec.problem = problem;
  r.spec.problem_params = std::move(problem_params);
  r.spec.seed = seed;
  for (int k = 0; k < steps; ++k) {
    StepRecord s;
    s.step = k;
    s.status = "fixpoint";
    const double tx = 100 * std::cos(k / 30.0), ty = 100 * std::sin(k / 30.0);
    const double h = half_width * (1 + 4.0 / (1 + k)) * (1 + 0.2 * std::sin(k / 7.0));
    const double skew = 0.5 * h * std::sin(k / 11.0);
    s.vars = {{"x", tx - h + skew, tx + h + skew, tx},
              {"y", ty - h - skew, ty + h - skew, ty},
              {"theta", -0.1, 0.1, 0}};
    s.contained = 1;
    s.area = 4 * h * h;
    s.centre_error = std::sqrt(2.0) * std::fabs(skew);
    s.solve_time_s = base_time_s * (1 + 0.5 * std::sin(k * 1.7) + ((k % 23) == 0 ? 3 : 0));
    r.steps.push_back(s);
  }
  r.metrics = ComputeMetrics(r.steps);
  return r;
}

std::vector<RunRecord> PaperLikeRuns() {
  std::vector<RunRecord> runs;
  const struct {
    const char* algorithm;
    double time_s;
    double half_width;
  } kAlgorithms[] = {{"hc4", 0.5e-3, 14}, {"bc3", 1e-3, 14}, {"bc4", 0.6e-3, 13.5},
                     {"3b-bc4", 1.4, 12}};
  for (const auto& a : kAlgorithms) {
    runs.push_back(MakeRun(a.algorithm, "car-track", {}, 2, 150, a.time_s, a.half_width));
    runs.push_back(MakeRun(a.algorithm, "car-track", {}, 1, 150, a.time_s, a.half_width));
  }
  for (const char* w : {"1", "5", "10", "40"}) {
    const double wv = std::stod(w);
    for (const char* algorithm : {"hc4", "bc4"}) {
      runs.push_back(MakeRun(algorithm, "car-track", {{"w", w}}, 1, 20, 0.025e-3 * wv,
                             14 * (1 + 2 / wv)));
    }
  }
  return runs;
}

std::string Head(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string head(n, '\0');
  in.read(head.data(), static_cast<std::streamsize>(n));
  return head;
}

std::vector<const RunRecord*> Pointers(const std::vector<RunRecord>& runs) {
  std::vector<const RunRecord*> out;
  for (const RunRecord& r : runs) out.push_back(&r);
  return out;
}

TEST(FiguresTest, WritesEveryKindAsPngAndPdfCallersFirst) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("figures_all");
  const std::vector<RunRecord> runs = PaperLikeRuns();
  const FigureMaker more = [](const std::vector<RunRecord>& runs, const std::string& out_dir,
                              PlotOutput* out) {
    std::vector<const RunRecord*> lap;
    for (const RunRecord& r : runs)
      if (r.spec.problem_params.empty() && r.spec.seed == 1) lap.push_back(&r);
    PlotSweepFigure({"sweep", "Against w", "none"}, "w", ParamSweep(runs, "car-track", "w"),
                    out_dir, out);
    PlotCorridorFigure({"corridors", "Corridors", "none"}, lap, out_dir, out);
    PlotAreaFigure({"area", "Area", "none"}, lap, out_dir, out);
  };
  const PlotOutput out = PlotRuns(runs, dir.string(), more);
  // hc4 and bc3 are made with the same boxes: drawn once, and said so.
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{
                "corridors: note: hc4 = bc3 (seed 1) draw the same values (equal corridors at "
                "every step) and are drawn once",
                "area: note: hc4 = bc3 (seed 1) draw the same values (at every step) and are drawn "
                "once"}));
  const std::vector<std::string> expected =
      FigureFiles(dir, {"sweep", "corridors", "area", "fig_timing", "fig_profile_time",
                        "fig_profile_area"});
  EXPECT_EQ(out.files, expected);
  for (const std::string& path : expected) {
    ASSERT_TRUE(fs::exists(path)) << path;
    EXPECT_GT(fs::file_size(path), 1000u) << path;
    EXPECT_EQ(Head(path, 4), path.ends_with(".png") ? "\x89PNG" : "%PDF") << path;
  }
  fs::remove_all(dir);
}

TEST(FiguresTest, EqualSeriesAreGroupedAndDecadesDetected) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<std::vector<double>>> rows = {
      {{1, 2}, {2, nan}}, {{1, 3}, {2, nan}}, {{1, 2 + 1e-12}, {2, nan}}, {{1, 2}}};
  EXPECT_EQ(EqualGroups(rows), (std::vector<std::vector<std::size_t>>{{0, 2}, {1}, {3}}));
  EXPECT_EQ(JoinedLabel({"hc4 (seed 1)", "x", "bc4 (seed 1)"}, {0, 2}), "hc4 = bc4 (seed 1)");
  EXPECT_EQ(JoinedLabel({"hc4 (seed 1)", "bc4 (seed 2)"}, {0, 1}), "hc4 (seed 1) = bc4 (seed 2)");
  EXPECT_TRUE(SpansDecades({1, 2, 5, 200}));
  EXPECT_FALSE(SpansDecades({16, 21}));
  EXPECT_FALSE(SpansDecades({0, 1, 200}));  // a log axis cannot draw 0
  EXPECT_EQ(TicsFor("x", 0, 1999, 5), "set xtics 500\n");
  EXPECT_EQ(Wrapped("aaa bbb ccc", 0.2), "aaa\nbbb\nccc");  // 0.2 in holds 2 characters a line
}

TEST(FiguresTest, GpsCorridorIsTheGpsBoxAboutTheTruth) {
  RunRecord r;
  StepRecord with_fix;
  with_fix.step = 0;
  with_fix.vars = {{"x", 0, 1, 10}, {"y", 0, 1, 20}};
  with_fix.properties = {{"gps_x_lo", 8.0}, {"gps_x_hi", 13.0}, {"gps_y_lo", 19.0}, {"gps_y_hi", 21.5}};
  StepRecord without = with_fix;
  without.step = 1;
  without.properties.clear();
  r.steps = {with_fix, without};
  const auto x = GpsCorridorRows(r, "x");
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(x[0], (std::vector<double>{0, -2, 3}));
  EXPECT_TRUE(std::isnan(x[1][1]) && std::isnan(x[1][2]));
  EXPECT_EQ(GpsCorridorRows(r, "y")[0], (std::vector<double>{0, -1, 1.5}));
}

TEST(FiguresTest, EmptyStoreWritesNothing) {
  const fs::path dir = TempDir("figures_empty");
  PlotOutput out;
  ASSERT_NO_THROW(out = PlotRuns({}, dir.string()));
  EXPECT_TRUE(out.files.empty());
  EXPECT_EQ(out.messages, (std::vector<std::string>{
                              "fig_timing: skipped: no ok run with per-step solve times",
                              "fig_profile_time: skipped: no ok run with a solve time",
                              "fig_profile_area: skipped: no ok run with an area"}));
  // Each kind given nothing says why, in the caller's words.
  PlotSweepFigure({"a", "", "no sweep"}, "w", {}, dir.string(), &out);
  PlotCorridorFigure({"b", "", "no lap"}, {}, dir.string(), &out);
  PlotAreaFigure({"c", "", "no area"}, {}, dir.string(), &out);
  PlotTimingFigure({"d", "", "no times"}, {}, dir.string(), &out);
  EXPECT_EQ(out.messages.back(), "d: skipped: no times");
  EXPECT_EQ(out.messages.size(), 7u);
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(FiguresTest, SkipsWhatTheStoreLacks) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("figures_partial");
  // No car-track: the timing box plot over the chain runs.
  std::vector<RunRecord> runs = {MakeRun("hc4", "chain", {{"w", "4"}}, 1, 30, 1e-5, 1),
                                 MakeRun("bc4", "chain", {{"w", "4"}}, 1, 30, 2e-5, 1)};
  // A failed run and a run with undefined areas and times change nothing.
  RunRecord failed = MakeRun("bc3", "car-track", {}, 1, 0, 0, 0);
  failed.status = RunStatus::kFailed;
  runs.push_back(failed);
  PlotOutput out = PlotRuns(runs, dir.string());
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig_timing", "fig_profile_time", "fig_profile_area"}));
  EXPECT_TRUE(out.messages.empty());
  // Runs without steps draw no corridor.
  PlotCorridorFigure({"corridors", "", "no steps"}, Pointers({failed}), dir.string(), &out);
  EXPECT_EQ(out.messages, (std::vector<std::string>{"corridors: skipped: no steps"}));
  fs::remove_all(dir);
}

// A line or band over the steps shows nothing for a run of one step: the
// figure says so instead of drawing an empty frame. Two steps draw.
TEST(FiguresTest, OneStepRunsSkipTheFiguresOverSteps) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("figures_one_step");
  fs::create_directories(dir);
  const std::vector<RunRecord> one = {MakeRun("hc4", "car-track", {}, 1, 1, 1e-5, 1)};
  PlotOutput out;
  PlotCorridorFigure({"corridors", "", "none"}, Pointers(one), dir.string(), &out);
  PlotAreaFigure({"area", "", "none"}, Pointers(one), dir.string(), &out);
  ASSERT_EQ(out.messages.size(), 2u);
  for (const std::string& m : out.messages)
    EXPECT_NE(m.find("skipped: no run it draws has two steps"), std::string::npos) << m;
  EXPECT_TRUE(out.files.empty());
  const std::vector<RunRecord> two = {MakeRun("hc4", "car-track", {}, 1, 2, 1e-5, 1)};
  PlotAreaFigure({"area", "", "none"}, Pointers(two), dir.string(), &out);
  EXPECT_EQ(out.files, FigureFiles(dir, {"area"}));
  fs::remove_all(dir);
}

// A figure a second plot skips loses the files a first plot drew of it:
// they would pass for the new store's figure.
TEST(FiguresTest, ASkippedFigureLeavesNoOldFile) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("figures_stale");
  const std::vector<RunRecord> runs = {MakeRun("hc4", "chain", {{"w", "4"}}, 1, 30, 1e-5, 1)};
  PlotRuns(runs, dir.string());
  ASSERT_TRUE(fs::exists(dir / "fig_timing.png"));
  std::ofstream(dir / "unrelated.png") << "kept";
  const PlotOutput out = PlotRuns({}, dir.string());
  EXPECT_TRUE(out.files.empty());
  for (const char* f : {"fig_timing.png", "fig_timing.pdf", "fig_profile_time.png", "fig_profile_area.pdf"})
    EXPECT_FALSE(fs::exists(dir / f)) << f;
  EXPECT_TRUE(fs::exists(dir / "unrelated.png"));
  fs::remove_all(dir);
}

TEST(FiguresTest, TimingShowsTheConfigurationWithTheMostAlgorithms) {
  std::vector<RunRecord> runs = PaperLikeRuns();  // 4 algorithms on the lap, 2 at each w
  // More CSPs, but fewer algorithms, and non-default parameters never count.
  runs.push_back(MakeRun("hc4", "car-track", {{"steps", "900"}}, 1, 900, 1e-5, 1));
  runs.push_back(MakeRun("bc4", "car-track", {{"steps", "900"}}, 1, 900, 1e-5, 1));
  runs.push_back(MakeRun("bc3", "car-track", {{"steps", "900"}}, 1, 900, 1e-5, 1));
  runs.back().spec.algorithm_params = {{"ratio", "0.1"}};
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  std::string setting;
  const std::vector<const GroupSummary*> chosen = TimingGroups(groups, &setting);
  EXPECT_EQ(setting, "car-track");
  ASSERT_EQ(chosen.size(), 4u);
  EXPECT_EQ(chosen[0]->algorithm, "hc4");
  EXPECT_EQ(chosen[3]->algorithm, "3b-bc4");
  // A tie in algorithms goes to the most CSPs.
  runs.push_back(MakeRun("bc3", "car-track", {{"steps", "900"}}, 1, 900, 1e-5, 1));
  runs.push_back(MakeRun("3b-bc4", "car-track", {{"steps", "900"}}, 1, 900, 1e-5, 1));
  TimingGroups(SummariseGroups(runs), &setting);
  EXPECT_EQ(setting, "car-track, steps=900");
  // More algorithms, but recorded with `record: runs` (no step rows to draw).
  for (const char* a : {"hc3", "hc4", "bc3", "bc4", "3b-hc4", "3b-bc4"}) {
    runs.push_back(MakeRun(a, "car-track", {{"steps", "50"}}, 1, 50, 1e-5, 1));
    runs.back().steps.clear();
  }
  TimingGroups(SummariseGroups(runs), &setting);
  EXPECT_EQ(setting, "car-track, steps=900");
  EXPECT_TRUE(TimingGroups({}, &setting).empty());
}

// A figure over steps given only runs stored with `record: runs` says so,
// naming their experiment, instead of its generic reason; one given some
// runs with steps draws those and says which it left out.
TEST(FiguresTest, RunsRecordedWithoutStepsAreNamedInEveryStepFigure) {
  const fs::path dir = TempDir("figures_runs_only");
  RunRecord with_steps = MakeRun("hc4", "car-track", {}, 1, 20, 1e-4, 1);
  with_steps.spec_file = "specs/t.yaml#lap";
  const RunRecord runs_only = RunsOnly(with_steps);
  const std::vector<const RunRecord*> only = {&runs_only};
  PlotOutput out;
  PlotCorridorFigure({"corridors", "", "none"}, only, dir.string(), &out);
  PlotAreaFigure({"area", "", "none"}, only, dir.string(), &out);
  PlotCentreErrorFigure({"error", "", "none"}, only, dir.string(), &out);
  PlotTrackFigure({"track", "", "none"}, {}, only, 5, dir.string(), &out);
  const GroupSummary group = Summarise(only);
  PlotTimingFigure({"timing", "", "none"}, {&group}, dir.string(), &out);
  const std::string why =
      ": skipped: it needs step rows, and 1 run was recorded with `record: runs` (experiment "
      "lap; run metrics only, no step rows; rerun with record: steps to draw them)";
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{"corridors" + why, "area" + why, "error" + why,
                                      "track" + why, "timing" + why}));
  EXPECT_TRUE(out.files.empty());
  // Two runs of two experiments.
  RunRecord other = runs_only;
  other.spec_file = "specs/t.yaml#other";
  other.spec.seed = 2;
  out = {};
  PlotAreaFigure({"area", "", "none"}, {&runs_only, &other}, dir.string(), &out);
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{
                "area: skipped: it needs step rows, and 2 runs were recorded with `record: runs` "
                "(experiments lap, other; run metrics only, no step rows; rerun with record: "
                "steps to draw them)"}));
  // A runs-only run beside one with steps: drawn, with a note.
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  fs::create_directories(dir);
  out = {};
  PlotAreaFigure({"area", "", "none"}, {&with_steps, &runs_only}, dir.string(), &out);
  EXPECT_EQ(out.files, FigureFiles(dir, {"area"}));
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{
                "area: drawn without 1 run recorded with `record: runs` (experiment lap; run "
                "metrics only, no step rows; rerun with record: steps to draw them)"}));
  fs::remove_all(dir);
}

// The sweep figure draws from the run metrics, but the window states' area is
// a step property: without steps its panel says whose runs it lacks.
TEST(FiguresTest, SweepNamesTheRunsItsWindowPanelLacks) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("figures_sweep_runs_only");
  fs::create_directories(dir);
  std::vector<RunRecord> runs;
  for (const char* w : {"1", "5"}) {
    runs.push_back(RunsOnly(MakeRun("hc4", "car-track", {{"w", w}}, 1, 20, 1e-5, 1)));
    runs.back().spec_file = "specs/t.yaml#window";
  }
  PlotOutput out;
  PlotSweepFigure({"sweep", "", "none"}, "w", ParamSweep(runs, "car-track", "w"), dir.string(),
                  &out);
  EXPECT_EQ(out.files, FigureFiles(dir, {"sweep"}));
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{
                "sweep: drawn from the run metrics; the mean area of the window states (a step "
                "property) lacks 2 runs recorded with `record: runs` (experiment window; run "
                "metrics only, no step rows; rerun with record: steps to draw them)"}));
  fs::remove_all(dir);
}

// Six seeds or more give each point of the sweep its 95 % interval, and the
// panel titles say so; the parameters every line shares go to the title.
TEST(FiguresTest, SweepPanelsClaimIntervalsOnlyWithSixSeeds) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("figures_sweep_seeds");
  fs::create_directories(dir);
  for (const int seeds : {3, 6}) {
    std::vector<RunRecord> runs;
    for (const auto& [a, time_s] : {std::pair{"hc4", 1e-5}, std::pair{"bc4", 2e-5}})
      for (const char* w : {"1", "5"})
        for (int seed = 1; seed <= seeds; ++seed) {
          runs.push_back(MakeRun(a, "car-track", {{"w", w}, {"steps", "20"}}, seed, 20,
                                 time_s * seed, 1));
          runs.back().spec_file = "specs/t.yaml#window";
        }
    PlotOutput out;
    PlotSweepFigure({"sweep", "", "none"}, "w", ParamSweep(runs, "car-track", "w"),
                    dir.string(), &out);
    EXPECT_EQ(out.files, FigureFiles(dir, {"sweep"}));
    const std::string title = seeds >= 6 ? " (median of seeds, 95 % CI)" : "";
    EXPECT_EQ(out.messages, (std::vector<std::string>{
                                "sweep: note: hc4 = bc4 draw the same values (in 'Mean x-y area "
                                "of the newest state" + title + "') and are drawn once"}))
        << seeds << " seeds";
  }
  fs::remove_all(dir);
}

// A degenerate accumulator (one cell, one row or column of cells, a
// zero-width side) draws its cells without a gnuplot warning: gnuplot's
// image needs 2 x 2 points and a range of non-zero width.
TEST(FiguresTest, DegenerateAccumulatorsDrawWithoutWarnings) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("figures_degenerate_accumulator");
  fs::create_directories(dir);
  const cv::Mat one(1, 1, CV_32S, cv::Scalar(5));
  cv::Mat row(1, 3, CV_32S, cv::Scalar(1)), column(3, 1, CV_32S, cv::Scalar(2));
  row.at<int>(0, 1) = 5;
  column.at<int>(2, 0) = 5;
  const struct {
    const char* name;
    cv::Mat counts;
    Interval x, y;
    int min_top_pixels;  // of the cell with the maximum count
  } kCases[] = {
      {"one", one, Interval(-10, 10), Interval(-10, 10), 40000},
      {"row", row, Interval(-10, 10), Interval(0, 5), 3000},
      {"column", column, Interval(-3, 3), Interval(-10, 10), 3000},
      {"point_x", one, Interval(2, 2), Interval(-10, 10), 40000},
      {"point", one, Interval(2, 2), Interval(-1, -1), 40000},
  };
  for (const auto& c : kCases) {
    PlotOutput out;
    const std::string err = StderrOf([&] {
      const std::vector<MarkerSet> truth = {{"truth", {{c.x.Mid(), c.y.Mid()}}, true}};
      PlotAccumulatorFigure({c.name, "Degenerate", "none"}, c.counts, c.x, c.y, truth,
                            dir.string(), &out);
    });
    EXPECT_EQ(err, "") << c.name;
    EXPECT_TRUE(out.messages.empty()) << c.name << ": " << out.messages.front();
    ASSERT_EQ(out.files, FigureFiles(dir, {c.name}));
    // The maximum's colour (the top of the palette, #fde725) fills its cell.
    EXPECT_GT(PixelsOfColour(out.files[0], 0xfd, 0xe7, 0x25), c.min_top_pixels) << c.name;
  }
  fs::remove_all(dir);
}

TEST(FiguresTest, PlotDirectoryNeedsAStore) {
  EXPECT_THROW(
      PlotDirectory("/nonexistent/icpbench-figures-test", TempDir("figures_none").string()),
      std::runtime_error);
}

}  // namespace
}  // namespace icp
