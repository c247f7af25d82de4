// The run loop is the same for every kind of estimate: test estimators that
// return a paving, a grid accumulator and particles run through `run`, are
// stored with their properties, reported and plotted with the shared
// metrics, beside HC4's boxes. And the sliding-window memory (`carry`) of
// the ICP adapter orders the boxes: none is never tighter than first, first
// never tighter than all, and all keep the truth.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "report/report.h"
#include "harness/results_store.h"
#include "harness/metrics.h"
#include "harness/runner.h"
#include "plots/figures.h"

namespace icp {
namespace {

const Property* Find(const Properties& properties, const std::string& name) {
  for (const Property& p : properties)
    if (p.name == name) return &p;
  return nullptr;
}

TEST(EstimatorsTest, EveryKindOfEstimateRunsIsStoredReportedAndPlotted) {
  const std::string dir = ::testing::TempDir() + "estimators_kinds";
  std::filesystem::remove_all(dir);
  Spec spec = ParseSpec(R"(
name: kinds
experiments:
  - name: table1
    algorithms: [hc4, test-paving, test-accumulator, test-particles]
    problems:
      - {name: car-track, params: {steps: 40, w: 20}}
)", "kinds.yaml");
  RunnerOptions options;
  options.out_dir = dir;
  options.jobs = 2;
  std::ostringstream progress;
  const SweepSummary summary = RunSweep(spec, options, progress, false);
  ASSERT_EQ(summary.ok, 4) << progress.str();

  std::map<std::string, RunRecord> runs;
  for (RunRecord& r : ResultsStore(StorePath(dir)).LoadRuns(true)) runs[r.spec.algorithm] = r;
  const std::map<std::string, std::pair<std::string, std::string>> kinds = {
      {"hc4", {"box", "revise_calls"}},
      {"test-paving", {"paving", "boundary_boxes"}},
      {"test-accumulator", {"accumulator", "max_count"}},
      {"test-particles", {"particles", "effective_sample_size"}}};
  for (const auto& [name, kind] : kinds) {
    SCOPED_TRACE(name);
    const RunRecord& r = runs.at(name);
    ASSERT_EQ(r.steps.size(), 40u);
    for (const StepRecord& s : r.steps) {
      EXPECT_EQ(s.estimate, kind.first);
      EXPECT_NE(Find(s.properties, kind.second), nullptr) << s.step;
      EXPECT_NE(Find(s.properties, "revise_calls"), nullptr) << s.step;  // HC4 inside
      ASSERT_EQ(s.vars.size(), 3u);
    }
    EXPECT_NE(Find(r.properties, "revise_calls"), nullptr);
    EXPECT_GT(r.metrics.mean_area, 0);
  }
  // Sets built from HC4's box: they hold the truth and are no smaller.
  const double hc4_area = runs.at("hc4").metrics.mean_area;
  for (const char* name : {"hc4", "test-paving", "test-accumulator"}) {
    EXPECT_EQ(runs.at(name).metrics.consistency_rate, 1.0) << name;
    EXPECT_GE(runs.at(name).metrics.mean_area, hc4_area) << name;
  }
  EXPECT_GT(runs.at("test-accumulator").metrics.mean_area, hc4_area);
  EXPECT_LE(runs.at("test-particles").metrics.mean_area, hc4_area);
  const auto* ess = Find(runs.at("test-particles").steps[0].properties, "effective_sample_size");
  EXPECT_NEAR(std::get<double>(ess->value), 200, 1e-9);  // equal weights

  const std::string report = ReportDirectory(dir, "md");
  for (const auto& [name, kind] : kinds) EXPECT_NE(report.find(name), std::string::npos) << name;
  std::vector<std::string> messages;
  const std::vector<std::string> files = PlotDirectory(dir, dir + "/figures", &messages);
  EXPECT_FALSE(files.empty());
  for (const std::string& f : files) EXPECT_GT(std::filesystem::file_size(f), 0u) << f;
}

// Newest-state boxes of HC4 over a car-track drive with the given carry.
std::vector<StepRecord> Drive(const std::string& carry) {
  RunRecord r = ExecuteRun(RunSpec{"hc4", {{"carry", carry}}, "car-track",
                                   {{"steps", "200"}, {"w", "5"}}, 3, 0});
  EXPECT_EQ(r.status, RunStatus::kOk) << r.reason;
  return r.steps;
}

TEST(EstimatorsTest, CarryNoneFirstAllAreOrderedAndKeepTheTruth) {
  const std::vector<StepRecord> none = Drive("none"), first = Drive("first"), all = Drive("all");
  ASSERT_EQ(none.size(), 200u);
  ASSERT_EQ(first.size(), 200u);
  ASSERT_EQ(all.size(), 200u);
  double width_none = 0, width_first = 0, width_all = 0;
  for (std::size_t k = 0; k < 200; ++k) {
    SCOPED_TRACE("step " + std::to_string(k));
    ASSERT_EQ(none[k].contained, 1);
    ASSERT_EQ(first[k].contained, 1);
    ASSERT_EQ(all[k].contained, 1);
    for (std::size_t c = 0; c < 3; ++c) {
      const double wn = none[k].vars[c].hi - none[k].vars[c].lo;
      const double wf = first[k].vars[c].hi - first[k].vars[c].lo;
      const double wa = all[k].vars[c].hi - all[k].vars[c].lo;
      EXPECT_GE(wn, wf) << none[k].vars[c].name;
      EXPECT_GE(wf, wa) << first[k].vars[c].name;
      width_none += wn;
      width_first += wf;
      width_all += wa;
    }
  }
  // The memory helps (HC4 gains nothing here from carrying more than the
  // oldest state: the window's constraints already pass it on).
  EXPECT_GT(width_none, width_first);
  EXPECT_GE(width_first, width_all);
}

// Post-localization (paper 004 §4.2): every state that left the window has
// a box that holds its truth, and, when every shared state is carried, one
// inside the box it had when it was the newest (later windows only narrow
// it); it is on the whole narrower than the real-time box.
TEST(EstimatorsTest, PostLocalizedStatesKeepTheirTruthAndNarrowTheRealTimeBoxes) {
  const std::vector<StepRecord> steps = Drive("all");
  const std::vector<StepRecord> post = PostLocalizedStates(steps);
  // States 0..194 were the oldest of some window (w = 5 spans 6 states).
  ASSERT_EQ(post.size(), 200u - 5);
  double width_real_time = 0, width_post = 0;
  for (std::size_t j = 0; j < post.size(); ++j) {
    SCOPED_TRACE("state " + std::to_string(j));
    ASSERT_EQ(post[j].step, static_cast<int>(j));
    EXPECT_EQ(post[j].contained, 1);
    const StepRecord& real_time = steps[j];
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_GE(post[j].vars[c].lo, real_time.vars[c].lo) << post[j].vars[c].name;
      EXPECT_LE(post[j].vars[c].hi, real_time.vars[c].hi) << post[j].vars[c].name;
      if (c < 2) {
        width_real_time += real_time.vars[c].hi - real_time.vars[c].lo;
        width_post += post[j].vars[c].hi - post[j].vars[c].lo;
      }
    }
  }
  EXPECT_LT(width_post, width_real_time);
  EXPECT_EQ(ComputeMetrics(post).consistency_rate, 1.0);
}

}  // namespace
}  // namespace icp
