#include "experiments/paper000/paper000.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/registry.h"
#include "report/report_testing.h"
#include "plots/figures_testing.h"

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

std::string Md(const std::vector<RunRecord>& runs) {
  return testing::WithoutProfiles(Report(runs, "md", Paper000Tables));
}

RunRecord Table1(RunRecord run) { return InExperiment(std::move(run), kPaper000Table1); }
RunRecord Window(RunRecord run) { return InExperiment(std::move(run), kPaper000Window); }

TEST(Paper000Test, EmptyStoreGivesThePublishedValuesAndDashes) {
  const std::string md = Md({});
  EXPECT_EQ(MarkdownRow(md, "HC4"), "| HC4 | 0.52 | — | — | 1 | — | — | — | — |");
  EXPECT_EQ(MarkdownRow(md, "3B-BC4"), "| 3B-BC4 | 1400 | — | — | 2692 | — | — | — | — |");
  EXPECT_NE(md.find("No car-track configuration was run at several w."), std::string::npos);
  EXPECT_EQ(md.find("| configuration |"), std::string::npos);
}

TEST(Paper000Test, PublishedVersusMeasured) {
  const std::vector<RunRecord> runs = {
      // HC4: 0.4 ms per CSP over 4 CSPs of two seeds.
      Table1(MakeRun("hc4", {}, {}, 1, {0.4e-3, 0.4e-3})),
      Table1(MakeRun("hc4", {}, {}, 2, {0.4e-3, 0.4e-3})),
      Table1(MakeRun("bc3", {}, {}, 1, {0.8e-3})),
      Table1(MakeRun("3b-bc4", {}, {}, 1, {1.2})),
  };
  const std::string md = Md(runs);
  // The measured column's unit from its values (median 0.8 ms: µs); fewer
  // than 6 runs give medians without an interval.
  EXPECT_NE(md.find("| algorithm | published (ms) | measured (µs) [95% CI] |"), std::string::npos) << md;
  EXPECT_EQ(MarkdownRow(md, "HC4"), "| HC4 | 0.52 | 400 | 1.3 | 1 | 1 | 2 | 4 | default |") << md;
  EXPECT_EQ(MarkdownRow(md, "BC3"), "| BC3 | 1.02 | 800 | 1.275 | 1.962 | 2 | 1 | 1 | default |");
  EXPECT_EQ(MarkdownRow(md, "BC4"), "| BC4 | 0.58 | — | — | 1.115 | — | — | — | — |");
  EXPECT_EQ(MarkdownRow(md, "3B-BC4"),
            "| 3B-BC4 | 1400 | 1200000 | 1.167 | 2692 | 3000 | 1 | 1 | default |");
  // The same rows in LaTeX.
  const std::string tex = Report(runs, "tex", Paper000Tables);
  EXPECT_NE(tex.find("HC4 & 0.52 & 400 & 1.3 & 1 & 1 & 2 & 4 & default \\\\"),
            std::string::npos)
      << tex;
  EXPECT_NE(tex.find("BC4 & 0.58 & --- & --- & 1.115 & --- & --- & --- & --- \\\\"),
            std::string::npos);
}

TEST(Paper000Test, SixSeedsGiveMediansWithIntervalsAndPairedRatios) {
  std::vector<RunRecord> runs;
  const double ms[] = {0.40, 0.41, 0.42, 0.44, 0.45, 0.46};
  for (int seed = 1; seed <= 6; ++seed) {
    runs.push_back(Table1(MakeRun("hc4", {}, {}, seed, {ms[seed - 1] * 1e-3})));
    runs.push_back(Table1(MakeRun("bc4", {}, {}, seed, {2 * ms[seed - 1] * 1e-3})));
  }
  const std::string md = Md(runs);
  // Median 430 µs, interval [min, max] (96.9 % for 6 runs) rounded outward
  // to the tens its half-width supports; the speed-up 0.52 ms over both ends;
  // BC4 over HC4 seed by seed: 2 on every instance, so 2 without spread.
  EXPECT_EQ(MarkdownRow(md, "HC4"),
            "| HC4 | 0.52 | 430 [400, 460] | 1.21 [1.13, 1.30] | 1 | 1 | 6 | 6 | default |")
      << md;
  EXPECT_EQ(MarkdownRow(md, "BC4"),
            "| BC4 | 0.58 | 860 [800, 920] | 0.67 [0.63, 0.73] | 1.115 | 2 | 6 | 6 | default |")
      << md;
}

TEST(Paper000Test, Table1IsChosenByExperimentNameNotByParameters) {
  // The paper's parameters in another experiment, or in a store without
  // experiment names, are not Table 1.
  RunRecord untagged = MakeRun("hc4", {}, {}, 1, {1e-3});
  untagged.spec_file = "specs/old.yaml";
  const std::string elsewhere =
      Md({InExperiment(MakeRun("hc4", {}, {}, 1, {1e-3}), "start"), untagged});
  EXPECT_EQ(MarkdownRow(elsewhere, "HC4"), "| HC4 | 0.52 | — | — | 1 | — | — | — | — |");
  // Any parameters in experiment table1 are: the label shows the algorithm's,
  // the last column the problem's.
  const std::string md = Md({Table1(MakeRun("hc4", {{"ratio", "0.1"}},
                                            {{"w", "10"}, {"outage_length", "50"}}, 1, {7e-3}))});
  EXPECT_EQ(MarkdownRow(md, "HC4 {ratio=0.1}"),
            "| HC4 {ratio=0.1} | 0.52 | 7 | 0.07429 | 1 | — | 1 | 1 | outage_length=50,w=10 |")
      << md;
  EXPECT_EQ(MarkdownRow(md, "HC4"), "");
  // A configuration of table1 pools all its runs, as the generic table does.
  const std::string pooled = Md({Table1(MakeRun("hc4", {}, {}, 1, {1e-3})),
                                 InExperiment(MakeRun("hc4", {}, {}, 2, {3e-3}), "start")});
  EXPECT_EQ(MarkdownRow(pooled, "HC4"), "| HC4 | 0.52 | 2 | 0.26 | 1 | 1 | 2 | 2 | default |");
}

TEST(Paper000Test, EveryConfigurationOfTable1HasARow) {
  const std::string md = Md({
      Table1(MakeRun("hc4", {}, {}, 1, {1e-3})),
      Table1(MakeRun("hc4", {}, {{"w", "10"}}, 1, {2e-3})),
      Table1(MakeRun("bc4", {}, {{"w", "10"}}, 1, {4e-3})),
      Table1(MakeRun("hc3", {}, {}, 1, {5e-3})),  // not in the paper
  });
  // measured / HC4: HC4 at default parameters on the same problem configuration.
  EXPECT_EQ(MarkdownRow(md, "BC4"), "| BC4 | 0.58 | 4 | 0.145 | 1.115 | 2 | 1 | 1 | w=10 |")
      << md;
  EXPECT_EQ(MarkdownRow(md, "HC3"), "| HC3 | — | 5 | — | — | 5 | 1 | 1 | default |");
  // Rows in display order; an algorithm's configurations in group order.
  const std::size_t hc3 = md.find("| HC3 |"), hc4 = md.find("| HC4 | 0.52 | 1 |"),
                    hc4_w10 = md.find("| HC4 | 0.52 | 2 |"), bc3 = md.find("| BC3 |");
  ASSERT_NE(hc4_w10, std::string::npos) << md;
  EXPECT_LT(hc3, hc4);
  EXPECT_LT(hc4, hc4_w10);
  EXPECT_LT(hc4_w10, bc3);
}

TEST(Paper000Test, FailedOnlyConfigurationIsNotMeasured) {
  const std::string md =
      Md({Table1(MakeRun("bc3", {}, {}, 1, {}, RunStatus::kFailed, "threw: bad | input"))});
  EXPECT_EQ(MarkdownRow(md, "BC3"), "| BC3 | 1.02 | — | — | 1.962 | — | — | — | — |");
  EXPECT_NE(md.find("- bc3 on car-track: failed (seed 1): threw: bad | input"), std::string::npos);
}

// Points as "label@w".
std::vector<std::string> Names(const std::vector<SweepPoint>& points) {
  std::vector<std::string> out;
  for (const SweepPoint& p : points) out.push_back(p.label + "@" + FormatNumber(p.value));
  return out;
}

TEST(Paper000Test, Fig2ShowsTheConfigurationsOfExperimentWindow) {
  const ParamMap outage = {{"outage_length", "50"}};
  const std::vector<RunRecord> runs = {
      Window(MakeRun("hc4", {}, {{"w", "5"}}, 1, {1e-3})),
      Window(MakeRun("hc4", {}, {{"w", "10"}}, 1, {2e-3})),
      // Stored under table1, which planned it first: still the w = 20 point.
      Table1(MakeRun("hc4", {}, {}, 1, {4e-3})),
      // The paper's parameters in another experiment: in the table, not in Fig. 2.
      InExperiment(MakeRun("bc4", {}, {{"w", "5"}}, 1, {1e-3}), "other"),
      InExperiment(MakeRun("bc4", {}, {{"w", "10"}}, 1, {1e-3}), "other"),
      // Other parameters in experiment window: in Fig. 2.
      Window(MakeRun("bc4", {{"ratio", "0.1"}}, {{"w", "5"}}, 1, {1e-3})),
      Window(MakeRun("bc4", {{"ratio", "0.1"}}, {{"w", "10"}}, 1, {1e-3})),
      InExperiment(MakeRun("3b-bc4", {}, {{"w", "5"}, {"outage_length", "50"}}, 1, {1e-3}),
                   "outage"),
      InExperiment(MakeRun("3b-bc4", {}, {{"outage_length", "50"}}, 1, {1e-3}), "outage"),
  };
  const std::vector<SweepPoint> sweep = Paper000WindowSweep(runs);
  EXPECT_EQ(Names(sweep),
            (std::vector<std::string>{"hc4@5", "hc4@10", "hc4@20", "bc4@5", "bc4@10",
                                      "bc4 {ratio=0.1}@5", "bc4 {ratio=0.1}@10",
                                      "3b-bc4 [outage_length=50]@5",
                                      "3b-bc4 [outage_length=50]@20"}));
  EXPECT_EQ(Names(Paper000Fig2Points(sweep)),
            (std::vector<std::string>{"hc4@5", "hc4@10", "hc4@20", "bc4 {ratio=0.1}@5",
                                      "bc4 {ratio=0.1}@10"}));
  // The table lists every sweep, ms per CSP.
  const std::string md = Md(runs);
  EXPECT_NE(md.find("| hc4 | 20 | 1 | 1 | 4 | — | 4 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 3b-bc4 [outage_length=50] | 5 | 1 | 1 | 4 | — | 1 |"), std::string::npos);
}

TEST(Paper000Test, LapRunsAreTheSmallestSeedOfEachTable1Configuration) {
  const std::vector<RunRecord> runs = {
      Table1(MakeRun("3b-bc4", {}, {}, 2, {1e-3})),
      Table1(MakeRun("3b-bc4", {}, {}, 1, {1e-3})),
      Table1(MakeRun("hc4", {}, {}, 3, {1e-3})),
      InExperiment(MakeRun("bc4", {}, {}, 1, {1e-3}), "start"),
  };
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  const std::vector<const RunRecord*> lap = Paper000LapRuns(groups);
  ASSERT_EQ(lap.size(), 2u);
  EXPECT_EQ(lap[0], &runs[2]);
  EXPECT_EQ(lap[1], &runs[1]);
}

TEST(Paper000Test, FiguresOfTheDefaultSpecsExperiments) {
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path dir = TempDir("paper000_all");
  std::vector<RunRecord> runs;
  for (const char* algorithm : {"hc4", "bc3", "bc4", "3b-bc4"}) {
    runs.push_back(Table1(MakeRun(algorithm, {}, {}, 1, std::vector<double>(30, 1e-4))));
  }
  for (const char* w : {"1", "5", "50"}) {
    for (const char* algorithm : {"hc4", "bc4"}) {
      runs.push_back(Window(MakeRun(algorithm, {}, {{"w", w}}, 1, std::vector<double>(30, 1e-5))));
    }
  }
  // Paper 000's figures alone: the other papers skip theirs with messages.
  const PlotOutput out = PlotRuns(runs, dir.string(), Paper000Figures);
  // Nothing skipped; the runs made alike here are noted as drawn once.
  for (const std::string& m : out.messages)
    EXPECT_NE(m.find(": note: "), std::string::npos) << m;
  EXPECT_EQ(out.files,
            FigureFiles(dir, {"fig2_window", "fig3_corridors", "fig4_area", "fig_timing",
                              "fig_profile_time", "fig_profile_area"}));
  fs::remove_all(dir);
}

TEST(Paper000Test, WithoutItsExperimentsTheFiguresSaySo) {
  const fs::path dir = TempDir("paper000_none");
  PlotOutput out;
  Paper000Figures({InExperiment(MakeRun("hc4", {}, {}, 1, {1e-3}), "start")}, dir.string(), &out);
  EXPECT_TRUE(out.files.empty());
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{
                "fig2_window: skipped: no car-track configuration of experiment window with ok "
                "runs at two or more w",
                "fig3_corridors: skipped: no ok run of experiment table1 with steps and truth",
                "fig4_area: skipped: no ok run of experiment table1 with areas"}));
  fs::remove_all(dir);
}

// Runs recorded with `record: runs` have no steps to draw: the lap's figures
// say so instead of "no ok run"; the window sweep draws from their metrics
// and says what its window-state panel lacks.
TEST(Paper000Test, RunsRecordedWithoutStepsAreNamed) {
  const fs::path dir = TempDir("paper000_runs_only");
  fs::create_directories(dir);
  std::vector<RunRecord> runs = {RunsOnly(Table1(MakeRun("hc4", {}, {}, 1, {1e-3, 1e-3}))),
                                 RunsOnly(Table1(MakeRun("bc4", {}, {}, 1, {1e-3, 1e-3})))};
  PlotOutput out;
  Paper000Figures(runs, dir.string(), &out);
  const std::string why =
      ": skipped: it needs step rows, and 2 runs were recorded with `record: runs` (experiment "
      "table1; run metrics only, no step rows; rerun with record: steps to draw them)";
  ASSERT_EQ(out.messages.size(), 3u);
  EXPECT_EQ(out.messages[1], "fig3_corridors" + why);
  EXPECT_EQ(out.messages[2], "fig4_area" + why);
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  // HC4 with steps: drawn without BC4, with a note.
  runs[0] = Table1(MakeRun("hc4", {}, {}, 1, {1e-3, 1e-3}));
  for (const char* w : {"1", "5"})
    runs.push_back(RunsOnly(Window(MakeRun("hc4", {}, {{"w", w}}, 1, {1e-5, 1e-5}))));
  out = {};
  Paper000Figures(runs, dir.string(), &out);
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig2_window", "fig3_corridors", "fig4_area"}));
  const std::string note =
      ": drawn without 1 run recorded with `record: runs` (experiment table1; run metrics "
      "only, no step rows; rerun with record: steps to draw them)";
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{
                "fig2_window: drawn from the run metrics; the mean area of the window states (a "
                "step property) lacks 2 runs recorded with `record: runs` (experiment window; "
                "run metrics only, no step rows; rerun with record: steps to draw them)",
                "fig3_corridors" + note, "fig4_area" + note}));
  fs::remove_all(dir);
}

TEST(Paper000Test, IsRegistered) {
  ASSERT_FALSE(Papers().empty());
  EXPECT_EQ(Papers()[0].name, "paper000");
  const std::vector<RunRecord> runs = {Table1(MakeRun("hc4", {}, {}, 1, {1e-3}))};
  // Its tables come first; the other papers' follow.
  const std::string md = Md(runs);
  EXPECT_EQ(Report(runs, "md", PaperTables).substr(0, md.size()), md);
}

}  // namespace
}  // namespace icp
