// The marina figures draw the stored runs: their boxes, truth and means are
// the stored steps', and what they re-run (the dead reckoning, the particle
// cloud) reproduces the stored run from its definition.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "experiments/thesis003/marina.h"
#include "experiments/thesis003/marina_figures.h"
#include "harness/metrics.h"
#include "harness/runner.h"
#include "report/report_testing.h"

namespace icp {
namespace {

using testing::InExperiment;

constexpr int kSteps = 60;

// A stored run of the default suite's marina experiment, shortened.
RunRecord Stored(const std::string& algorithm, const ParamMap& params, const std::string& start) {
  RunSpec spec{algorithm, params, "marina-sonar",
               {{"steps", std::to_string(kSteps)}, {"start", start}}, 2};
  RunRecord r = ExecuteRun(spec);
  EXPECT_EQ(r.status, RunStatus::kOk) << r.reason;
  return InExperiment(std::move(r), kThesis003MarinaDrive);
}

const std::vector<RunRecord>& Runs() {
  static const std::vector<RunRecord> runs = {
      Stored("q-relaxed", {{"mode", "pave"}, {"epsilon", "2"}}, "area"),
      Stored("particle-filter", {{"inject", "0"}}, "area"),
  };
  return runs;
}

const MapLayer& Layer(const MapPanel& p, const std::string& title_start) {
  for (const MapLayer& l : p.layers)
    if (l.title.rfind(title_start, 0) == 0) return l;
  ADD_FAILURE() << "no layer " << title_start;
  return p.layers.at(0);
}

TEST(MarinaReplayTest, SetMembershipPanelDrawsTheStoredBoxesAndTruth) {
  const std::vector<const RunRecord*> drawn = MarinaFigureRuns(Runs(), "area");
  ASSERT_EQ(drawn.size(), 2u);
  const RunRecord& run = *drawn[0];
  ASSERT_EQ(run.spec.algorithm, "q-relaxed");
  ASSERT_EQ(run.steps.size(), static_cast<std::size_t>(kSteps));
  const MapFrame map = MarinaMapFrame(run.spec.problem_params);
  const MapPanel panel = SetMembershipPanel(run, 10, map);
  const MapLayer& boxes = Layer(panel, "set-membership box");
  ASSERT_EQ(boxes.rows.size(), static_cast<std::size_t>(kSteps / 10));
  for (std::size_t i = 0; i < boxes.rows.size(); ++i) {
    const StepRecord& s = run.steps[10 * i];
    EXPECT_EQ(boxes.rows[i], (std::vector<double>{s.vars[0].lo, s.vars[0].hi, s.vars[1].lo,
                                                  s.vars[1].hi}));
    // The frame shows every box.
    EXPECT_LE(panel.frame.x.lo(), s.vars[0].lo);
    EXPECT_GE(panel.frame.x.hi(), s.vars[0].hi);
    EXPECT_LE(panel.frame.y.lo(), s.vars[1].lo);
    EXPECT_GE(panel.frame.y.hi(), s.vars[1].hi);
  }
  // The first box is the 10,368 m² prior contracted by the sonar: inside it.
  EXPECT_LE((boxes.rows[0][1] - boxes.rows[0][0]) * (boxes.rows[0][3] - boxes.rows[0][2]),
            10368 + 1e-6);
  const std::vector<std::vector<double>> truth = Layer(panel, "truth").rows;
  ASSERT_EQ(truth.size(), run.steps.size());
  for (std::size_t k = 0; k < truth.size(); ++k)
    EXPECT_EQ(truth[k], (std::vector<double>{run.steps[k].vars[0].truth,
                                             run.steps[k].vars[1].truth}));
}

TEST(MarinaReplayTest, DeadReckoningReDrivesTheStoredRunsProblem) {
  const RunRecord& run = Runs()[0];
  const std::vector<Box> reckoned = MarinaDeadReckoning(run);
  ASSERT_EQ(reckoned.size(), run.steps.size());
  // From the area prior, carried by the motion's intervals: the truth stays in.
  EXPECT_NEAR(reckoned[0][0].Width() * reckoned[0][1].Width(), 10368, 1e-6);
  for (std::size_t k = 0; k < reckoned.size(); ++k) {
    const std::vector<double> truth = {run.steps[k].vars[0].truth, run.steps[k].vars[1].truth};
    EXPECT_TRUE(reckoned[k].Contains(truth)) << "step " << k;
    if (k > 0) {
      EXPECT_GE(reckoned[k][0].Width(), reckoned[k - 1][0].Width());
    }
  }
  const MapPanel panel =
      DeadReckoningPanel(run, reckoned, MarinaMapFrame(run.spec.problem_params));
  EXPECT_EQ(Layer(panel, "truth").rows, TruthTrack(run));
  EXPECT_EQ(Layer(panel, "dead reckoning (box centre)").rows.size(), reckoned.size());
}

TEST(MarinaReplayTest, ParticleReplayReproducesTheStoredMeans) {
  const RunRecord& run = Runs()[1];
  ASSERT_EQ(run.spec.algorithm, "particle-filter");
  const ParticleReplay replay = ReplayParticles(run, 10, 60);
  ASSERT_EQ(replay.means.size(), run.steps.size());
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    const std::optional<double> x = NumberProperty(run.steps[k].properties, "mean_x");
    const std::optional<double> y = NumberProperty(run.steps[k].properties, "mean_y");
    ASSERT_TRUE(x && y) << "step " << k;
    EXPECT_NEAR(replay.means[k][0], *x, 1e-9) << "step " << k;
    EXPECT_NEAR(replay.means[k][1], *y, 1e-9) << "step " << k;
  }
  // The thesis' cloud: 600 particles over the 10,368 m² prior.
  EXPECT_EQ(replay.first_cloud.size(), 600u);
  EXPECT_NEAR(replay.prior[0].Width() * replay.prior[1].Width(), 10368, 1e-6);
  for (const std::vector<double>& p : replay.first_cloud) EXPECT_TRUE(replay.prior.Contains(p));
  EXPECT_EQ(replay.later.size(), static_cast<std::size_t>((kSteps - 1) / 10 * 60));
  // The panel's mean track is the stored one.
  const MapPanel panel = ParticlePanel(run, replay, MarinaMapFrame(run.spec.problem_params));
  const MapLayer& mean = Layer(panel, "weighted mean");
  ASSERT_EQ(mean.rows.size(), run.steps.size());
  EXPECT_EQ(mean.rows[5][0], *NumberProperty(run.steps[5].properties, "mean_x"));
}

}  // namespace
}  // namespace icp
