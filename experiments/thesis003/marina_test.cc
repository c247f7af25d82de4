#include "experiments/thesis003/marina.h"
#include "experiments/thesis003/marina_figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "harness/metrics.h"
#include "plots/figures_testing.h"
#include "report/report_testing.h"

namespace icp {
namespace {

using testing::FigureFiles;
using testing::GnuplotMissing;
using testing::InExperiment;
using testing::MarkdownRow;
using testing::RunsOnly;
using testing::TempDir;

// A marina step: the truth at (t, 0), the estimate's box [t - 1, t + 1] x
// [-1, 1] shifted by error on x (so its centre error is |error| and it holds
// the truth when |error| <= 1), the given solve time.
StepRecord MarinaStep(int t, double error, double time_s, const std::string& estimate = "box") {
  StepRecord s;
  s.step = t;
  s.status = "fixpoint";
  s.estimate = estimate;
  s.vars = {{"x", t + error - 1, t + error + 1, static_cast<double>(t)}, {"y", -1, 1, 0}};
  s.contained = std::abs(error) <= 1 ? 1 : 0;
  s.area = 4;
  s.centre_error = std::abs(error);
  s.solve_time_s = time_s;
  return s;
}

RunRecord MarinaRun(const std::string& algorithm, const std::string& start, std::uint64_t seed,
                    std::vector<StepRecord> steps, Properties properties,
                    const std::string& experiment = kThesis003Marina) {
  RunRecord r;
  r.spec = {algorithm, {}, "marina-sonar", {{"start", start}}, seed};
  r.steps = std::move(steps);
  r.metrics = ComputeMetrics(r.steps);
  r.properties = std::move(properties);
  return InExperiment(std::move(r), experiment);
}

// The report's Markdown from the table's title on (the generic table comes
// first).
std::string Md(const std::vector<RunRecord>& runs) {
  const std::string md = Report(runs, "md", [](const std::vector<RunRecord>& r) {
    return std::vector<TextTable>{MarinaTable(r)};
  });
  const std::size_t at = md.find("## Thesis 003 ch. 6");
  if (at == std::string::npos) return "";
  const std::size_t next = md.find("\n## ", at);
  return md.substr(at, next == std::string::npos ? std::string::npos : next - at);
}

TEST(MarinaTableTest, PoolsSeedsAndReportsErrorsRestartsAndTimes) {
  // q-relaxed, two seeds: errors 0, 0.5, 2 (one step misses the truth) and
  // 1; 1 and 3 restarts; 10 ms and 30 ms steps.
  const std::vector<RunRecord> runs = {
      MarinaRun("q-relaxed", "known", 1,
                {MarinaStep(0, 0, 0.01), MarinaStep(1, 0.5, 0.01), MarinaStep(2, 2, 0.03)},
                {{"resets", std::int64_t{1}}}),
      MarinaRun("q-relaxed", "known", 2, {MarinaStep(0, 1, 0.03)}, {{"resets", std::int64_t{3}}}),
      MarinaRun("particle-filter", "known", 1, {MarinaStep(0, 3, 0.002, "particles")},
                {{"reinitialisations", std::int64_t{0}}}),
      // Not of the marina experiments: left out.
      MarinaRun("hc4", "known", 1, {MarinaStep(0, 0, 1)}, {}, "table1"),
  };
  const std::string md = Md(runs);
  // Consistency 3 of 4 steps; the runs' RMSEs sqrt(4.25 / 3) and 1, their
  // median the mean of the two;
  // median error 0.75; restarts (1 + 3) / 2; median step 20 ms; solve time
  // per run (0.05 + 0.03) / 2 s.
  EXPECT_EQ(MarkdownRow(md, "q-relaxed"),
            "| q-relaxed | marina-sonar {start=known} | 2 | 4 | 0.75 | " +
                FormatNumber((std::sqrt(4.25 / 3) + 1) / 2) + " | 0.75 | 2 | 20 | 0.04 | — | — | — | — |")
      << md;
  const std::string filter = DisplayOf("particle-filter").label;
  EXPECT_EQ(MarkdownRow(md, filter),
            "| " + filter +
                " | marina-sonar {start=known} | 1 | 1 | 0 | 3 | 3 | 0 | 2 | 0.002 | — | — | — | — |")
      << md;
  EXPECT_EQ(MarkdownRow(md, "HC4"), "");
  // The thesis' figures stand beside them.
  EXPECT_EQ(MarkdownRow(md, "published: set membership, C/C++"),
            "| published: set membership, C/C++ | the Girona marina data set, 600 m | — | — | — | — "
            "| — | — | — | 4200 | — | — | — | — |");
  EXPECT_NE(MarkdownRow(md, "published: particle filter, 600 particles, Matlab"), "");
}

TEST(MarinaTableTest, SaysWhichSpecMakesItsRunsWhenThereAreNone) {
  EXPECT_NE(Md({}).find("specs/marina.yaml"), std::string::npos);
}

TEST(MarinaFiguresTest, DrawOneSeedOfBothMethodsPreferringTheFullDriveAKnownStartAndTheJudgedConfiguration) {
  const std::vector<RunRecord> runs = {
      MarinaRun("q-relaxed", "unknown", 1, {MarinaStep(0, 0, 0.01)}, {}),
      MarinaRun("q-relaxed", "known", 3, {MarinaStep(0, 0, 0.01)}, {}),
      MarinaRun("particle-filter", "known", 3, {MarinaStep(0, 0, 0.01, "particles")}, {}),
      MarinaRun("particle-filter", "known", 4, {MarinaStep(0, 0, 0.01, "particles")}, {}),
      MarinaRun("q-relaxed", "known", 1, {MarinaStep(0, 0, 0.01)}, {}, kThesis003MarinaDrive),
  };
  const std::vector<const RunRecord*> drawn = MarinaFigureRuns(runs);
  ASSERT_EQ(drawn.size(), 2u);
  EXPECT_EQ(drawn[0]->spec.algorithm, "q-relaxed");
  EXPECT_EQ(drawn[1]->spec.algorithm, "particle-filter");
  for (const RunRecord* r : drawn) EXPECT_EQ(r->spec.seed, 3u);
  // Of two configurations of one algorithm, the guaranteed one, however
  // worse its error; without it, the first stored.
  std::vector<RunRecord> two = {
      MarinaRun("q-relaxed", "known", 1, {MarinaStep(0, 0.5, 0.01)}, {}),
      MarinaRun("q-relaxed", "known", 1, {MarinaStep(0, 2, 0.01)}, {}),
  };
  two[1].spec.algorithm_params = {{"auto_q", "false"}, {"q", "13"}};
  std::vector<const RunRecord*> chosen = MarinaFigureRuns(two);
  ASSERT_EQ(chosen.size(), 1u);
  EXPECT_EQ(chosen[0], &two[1]);
  two[1].spec.algorithm_params = {{"mode", "pave"}};
  chosen = MarinaFigureRuns(two);
  ASSERT_EQ(chosen.size(), 1u);
  EXPECT_EQ(chosen[0], &two[0]);
  // Only the short drive: it is drawn.
  EXPECT_EQ(MarinaFigureRuns({runs.back()}).size(), 1u);
  EXPECT_TRUE(MarinaFigureRuns({}).empty());
}

TEST(MarinaFiguresTest, WritesTheFourFiguresOrSaysWhyNot) {
  PlotOutput none;
  MarinaFigures({}, TempDir("marina_figures_none").string(), &none);
  const std::string no_run = ": skipped: no ok run of experiment marina or marina-*";
  EXPECT_EQ(none.messages,
            (std::vector<std::string>{"fig6_7_dead_reckoning" + no_run,
                                      "fig6_8_marina_tracks" + no_run,
                                      "fig6_9_particles" + no_run, "fig6_errors" + no_run}));
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const std::vector<RunRecord> runs = {
      MarinaRun("q-relaxed", "known", 1, {MarinaStep(0, 0.2, 0.01), MarinaStep(1, 0.5, 0.01)}, {}),
      MarinaRun("particle-filter", "known", 1,
                {MarinaStep(0, 0.2, 0.01, "particles"), MarinaStep(1, 0.1, 0.01, "particles")}, {}),
  };
  const std::filesystem::path dir = TempDir("marina_figures");
  std::filesystem::create_directories(dir);
  PlotOutput out;
  MarinaFigures(runs, dir.string(), &out);
  EXPECT_EQ(out.files, FigureFiles(dir, {"fig6_7_dead_reckoning", "fig6_8_marina_tracks",
                                         "fig6_9_particles", "fig6_errors"}))
      << ::testing::PrintToString(out.messages);
}

// A store of marina runs recorded with `record: runs` has ok runs but no
// steps to draw: the figures say so, not that there is no run.
TEST(MarinaFiguresTest, RunsRecordedWithoutStepsAreNamed) {
  const std::vector<RunRecord> runs = {
      RunsOnly(MarinaRun("q-relaxed", "known", 1, {MarinaStep(0, 0, 0.01)}, {})),
      RunsOnly(MarinaRun("particle-filter", "known", 1, {MarinaStep(0, 0, 0.01, "particles")},
                         {})),
  };
  PlotOutput out;
  MarinaFigures(runs, TempDir("marina_figures_runs_only").string(), &out);
  const std::string why =
      ": skipped: it needs step rows, and 2 runs were recorded with `record: runs` (experiment "
      "marina; run metrics only, no step rows; rerun with record: steps to draw them)";
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{"fig6_7_dead_reckoning" + why, "fig6_8_marina_tracks" + why,
                                      "fig6_9_particles" + why, "fig6_errors" + why}));
  EXPECT_TRUE(out.files.empty());
  // An algorithm whose only run has no steps is left out with a note.
  if (GnuplotMissing()) GTEST_SKIP() << "gnuplot not installed";
  const std::vector<RunRecord> mixed = {
      MarinaRun("q-relaxed", "known", 1, {MarinaStep(0, 0.2, 0.01), MarinaStep(1, 0.5, 0.01)}, {}),
      runs[1]};
  const std::filesystem::path dir = TempDir("marina_figures_mixed");
  std::filesystem::create_directories(dir);
  out = {};
  MarinaFigures(mixed, dir.string(), &out);
  // The set-membership figures draw; the particles need the filter's steps.
  EXPECT_EQ(out.files,
            FigureFiles(dir, {"fig6_7_dead_reckoning", "fig6_8_marina_tracks", "fig6_errors"}));
  const std::string one =
      "1 run recorded with `record: runs` (experiment marina; run metrics only, no step rows; "
      "rerun with record: steps to draw them)";
  EXPECT_EQ(out.messages,
            (std::vector<std::string>{"fig6_9_particles: skipped: it needs step rows, and 1 run "
                                      "was recorded with `record: runs` (experiment marina; run "
                                      "metrics only, no step rows; rerun with record: steps to "
                                      "draw them)",
                                      "fig6_errors: drawn without " + one}));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace icp
