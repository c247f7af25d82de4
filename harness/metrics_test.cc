#include "harness/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace icp {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

StepRecord Step(int step, std::string status, std::vector<VariableRecord> vars, int contained,
                double area, double centre_error, double solve_time_s) {
  StepRecord s;
  s.step = step;
  s.status = std::move(status);
  s.vars = std::move(vars);
  s.contained = contained;
  s.area = area;
  s.centre_error = centre_error;
  s.solve_time_s = solve_time_s;
  return s;
}

// Six steps whose aggregates are worked out by hand below; the times are
// binary fractions, so mean, median and p90 are exact.
std::vector<StepRecord> HandSteps() {
  return {
      Step(0, "contracted", {{"x", 0, 2, 1}, {"y", 0, 1, 0.5}}, 1, 2, 0.3, 0.25),
      Step(1, "fixpoint", {{"x", 1, 4, 2}, {"y", 0, 2, 1}}, 1, 6, 0.4, 0.5),
      Step(2, "empty", {{"x", kInf, -kInf, 3}, {"y", kInf, -kInf, 1}}, 0, kNaN, kNaN, 0.75),
      Step(3, "contracted", {{"x", 0, 1, 5}, {"y", 0, 1, 0.5}}, 0, 1, 1.2, 1),
      Step(4, "contracted", {{"x", 2, 3, kNaN}, {"y", 2, 3, kNaN}}, -1, 1, kNaN, 2.5),
      Step(5, "stopped", {{"x", 0, 5, kNaN}, {"y", 0, 1, kNaN}}, -1, 5, kNaN, 1),
  };
}

TEST(QuantileTest, InterpolatesBetweenOrderStatistics) {
  EXPECT_EQ(Quantile({4, 1, 3, 2}, 0), 1);
  EXPECT_EQ(Quantile({4, 1, 3, 2}, 1), 4);
  EXPECT_EQ(Quantile({4, 1, 3, 2}, 0.5), 2.5);
  EXPECT_EQ(Quantile({4, 1, 3, 2}, 0.25), 1.75);  // h = 0.75
  EXPECT_EQ(Quantile({7}, 0.9), 7);
  EXPECT_EQ(Quantile({1, kNaN, 3}, 0.5), 2);  // NaN entries are left out
}

TEST(QuantileTest, NaNWhereUndefined) {
  EXPECT_TRUE(std::isnan(Quantile({}, 0.5)));
  EXPECT_TRUE(std::isnan(Quantile({kNaN}, 0.5)));
  EXPECT_TRUE(std::isnan(Quantile({1, 2}, -0.1)));
  EXPECT_TRUE(std::isnan(Quantile({1, 2}, 1.5)));
  EXPECT_TRUE(std::isnan(Quantile({1, 2}, kNaN)));
}

TEST(QuantileTest, InfiniteValues) {
  EXPECT_EQ(Quantile({1, kInf}, 0.5), kInf);
  EXPECT_EQ(Quantile({-kInf, 1}, 0.5), -kInf);
  EXPECT_EQ(Quantile({1, 2, kInf}, 0.5), 2);
}

TEST(ComputeMetricsTest, HandComputedValues) {
  const RunMetrics m = ComputeMetrics(HandSteps());
  EXPECT_EQ(m.steps, 6);
  // Non-empty boxes: steps 0, 1, 3, 4, 5 -> (2 + 6 + 1 + 1 + 5) / 5.
  EXPECT_EQ(m.mean_area, 3);
  // Truth known at steps 0-3; inside at 0 and 1.
  EXPECT_EQ(m.consistency_rate, 0.5);
  EXPECT_DOUBLE_EQ(m.centre_rmse, std::sqrt((0.09 + 0.16 + 1.44) / 3));
  // Times sorted: 0.25 0.5 0.75 1 1 2.5; sum 6.
  EXPECT_EQ(m.time_mean_s, 1);
  EXPECT_EQ(m.time_median_s, 0.875);  // h = 2.5
  EXPECT_EQ(m.time_p90_s, 1.75);      // h = 4.5

  // Corridors over steps 0, 1, 3 (truth known, box non-empty).
  ASSERT_EQ(m.corridors.size(), 2u);
  const Corridor& x = m.corridors[0];
  EXPECT_EQ(x.var, "x");
  EXPECT_DOUBLE_EQ(x.mean_lower, (-1.0 - 1.0 - 5.0) / 3);
  EXPECT_DOUBLE_EQ(x.mean_upper, (1.0 + 2.0 - 4.0) / 3);
  EXPECT_EQ(x.min_lower, -5);
  EXPECT_EQ(x.max_upper, 2);
  const Corridor& y = m.corridors[1];
  EXPECT_EQ(y.var, "y");
  EXPECT_DOUBLE_EQ(y.mean_lower, (-0.5 - 1.0 - 0.5) / 3);
  EXPECT_DOUBLE_EQ(y.mean_upper, (0.5 + 1.0 + 0.5) / 3);
  EXPECT_EQ(y.min_lower, -1);
  EXPECT_EQ(y.max_upper, 1);
}

TEST(ComputeMetricsTest, BootstrapIntervalHoldsTheMeanAndIsReproducible) {
  const std::vector<StepRecord> steps = HandSteps();
  const RunMetrics a = ComputeMetrics(steps, 7);
  const RunMetrics b = ComputeMetrics(steps, 7);
  const RunMetrics c = ComputeMetrics(steps, 8);
  EXPECT_LE(a.time_mean_ci_lo_s, a.time_mean_s);
  EXPECT_GE(a.time_mean_ci_hi_s, a.time_mean_s);
  EXPECT_LT(a.time_mean_ci_lo_s, a.time_mean_ci_hi_s);
  // Means of resamples stay within the sample's range.
  EXPECT_GE(a.time_mean_ci_lo_s, 0.25);
  EXPECT_LE(a.time_mean_ci_hi_s, 2.5);
  EXPECT_EQ(a.time_mean_ci_lo_s, b.time_mean_ci_lo_s);
  EXPECT_EQ(a.time_mean_ci_hi_s, b.time_mean_ci_hi_s);
  EXPECT_TRUE(a.time_mean_ci_lo_s != c.time_mean_ci_lo_s ||
              a.time_mean_ci_hi_s != c.time_mean_ci_hi_s);
}

TEST(ComputeMetricsTest, BootstrapOfConstantTimesIsThePoint) {
  std::vector<StepRecord> steps;
  for (int i = 0; i < 10; ++i) steps.push_back(Step(i, "fixpoint", {}, -1, 1, kNaN, 0.5));
  const RunMetrics m = ComputeMetrics(steps);
  EXPECT_EQ(m.time_mean_ci_lo_s, 0.5);
  EXPECT_EQ(m.time_mean_ci_hi_s, 0.5);
  EXPECT_EQ(m.time_median_s, 0.5);
}

TEST(ComputeMetricsTest, NoStepsGivesNaN) {
  const RunMetrics m = ComputeMetrics({});
  EXPECT_EQ(m.steps, 0);
  EXPECT_TRUE(std::isnan(m.mean_area));
  EXPECT_TRUE(std::isnan(m.consistency_rate));
  EXPECT_TRUE(std::isnan(m.centre_rmse));
  EXPECT_TRUE(std::isnan(m.time_mean_s));
  EXPECT_TRUE(std::isnan(m.time_median_s));
  EXPECT_TRUE(std::isnan(m.time_p90_s));
  EXPECT_TRUE(std::isnan(m.time_mean_ci_lo_s));
  EXPECT_TRUE(std::isnan(m.time_mean_ci_hi_s));
  EXPECT_TRUE(m.corridors.empty());
}

TEST(ComputeMetricsTest, AllBoxesEmpty) {
  std::vector<StepRecord> steps;
  for (int i = 0; i < 3; ++i) {
    steps.push_back(Step(i, "empty", {{"x", kInf, -kInf, 1.0 * i}}, 0, 0, kNaN, 0.125));
  }
  const RunMetrics m = ComputeMetrics(steps);
  EXPECT_EQ(m.steps, 3);
  EXPECT_TRUE(std::isnan(m.mean_area));
  EXPECT_EQ(m.consistency_rate, 0);
  EXPECT_TRUE(std::isnan(m.centre_rmse));
  EXPECT_EQ(m.time_mean_s, 0.125);
  ASSERT_EQ(m.corridors.size(), 1u);
  EXPECT_EQ(m.corridors[0].var, "x");
  EXPECT_TRUE(std::isnan(m.corridors[0].mean_lower));
  EXPECT_TRUE(std::isnan(m.corridors[0].mean_upper));
  EXPECT_TRUE(std::isnan(m.corridors[0].min_lower));
  EXPECT_TRUE(std::isnan(m.corridors[0].max_upper));
}

TEST(ComputeMetricsTest, EmptyBoxWithKnownTruthNeverCountsAsContaining) {
  // contained says 1 (or unknown) but the box is empty: counted as 0.
  std::vector<StepRecord> steps = {
      Step(0, "contracted", {{"x", 0, 1, 0.5}}, 1, 1, 0, 1),
      Step(1, "empty", {{"x", kInf, -kInf, 0.5}}, 1, kNaN, kNaN, 1),
      Step(2, "contracted", {{"x", kInf, -kInf, 0.5}}, -1, kNaN, kNaN, 1),
      Step(3, "empty", {{"x", kInf, -kInf, kNaN}}, -1, kNaN, kNaN, 1),  // truth unknown
  };
  const RunMetrics m = ComputeMetrics(steps);
  EXPECT_DOUBLE_EQ(m.consistency_rate, 1.0 / 3);
  EXPECT_EQ(m.mean_area, 1);
}

TEST(ComputeMetricsTest, UnknownTruth) {
  std::vector<StepRecord> steps = {
      Step(0, "contracted", {{"x", 0, 1, kNaN}, {"y", 0, 4, kNaN}}, -1, 4, kNaN, 0.5),
      Step(1, "contracted", {{"x", 0, 2, kNaN}, {"y", 0, 4, kNaN}}, -1, 8, kNaN, 1.5),
  };
  const RunMetrics m = ComputeMetrics(steps);
  EXPECT_EQ(m.mean_area, 6);
  EXPECT_TRUE(std::isnan(m.consistency_rate));
  EXPECT_TRUE(std::isnan(m.centre_rmse));
  EXPECT_EQ(m.time_mean_s, 1);
  EXPECT_EQ(m.time_median_s, 1);
  ASSERT_EQ(m.corridors.size(), 2u);
  EXPECT_TRUE(std::isnan(m.corridors[1].mean_lower));
}

TEST(ComputeMetricsTest, NaNAreaIsLeftOutOfMeanArea) {
  std::vector<StepRecord> steps = {
      Step(0, "contracted", {{"theta", 0, 1, 0.5}}, 1, kNaN, 0.1, 1),
      Step(1, "contracted", {{"theta", 0, 1, 0.5}}, 1, 3, 0.1, 1),
  };
  const RunMetrics m = ComputeMetrics(steps);
  EXPECT_EQ(m.mean_area, 3);
  EXPECT_DOUBLE_EQ(m.centre_rmse, 0.1);
}

// A step of a planar state (x, y, periodic theta) whose truth is
// (step, 0, 6.2) and whose estimator reported post as its properties.
struct Step PlanarStep(int step) {
  struct Step s;
  s.views.step = step;
  s.views.space.names = {"x", "y", "theta"};
  s.views.space.x = 0;
  s.views.space.y = 1;
  s.views.space.periods = {0, 0, 2 * 3.141592653589793};
  s.truth = {static_cast<double>(step), 0, 6.2};
  return s;
}
Properties Post(int state, double x_lo, double x_hi, double theta_lo, double theta_hi) {
  return {{"post_step", std::int64_t{state}}, {"post_x_lo", x_lo}, {"post_x_hi", x_hi},
          {"post_y_lo", -1.0}, {"post_y_hi", 1.0}, {"post_theta_lo", theta_lo},
          {"post_theta_hi", theta_hi}};
}

TEST(PostStateJudgeTest, JudgesAStateAgainstItsOwnTruth) {
  PostStateJudge judge;
  Properties p0 = Post(0, -1, 1, 6, 6.5);
  judge.Judge(PlanarStep(0), &p0);
  EXPECT_EQ(NumberProperty(p0, "post_contained"), 1);
  EXPECT_EQ(NumberProperty(p0, "post_x_truth"), 0);
  EXPECT_EQ(NumberProperty(p0, "post_area"), 4);
  EXPECT_EQ(NumberProperty(p0, "post_centre_error"), 0);
  Properties p1 = Post(0, 0.5, 1, 6, 6.5);  // step 1 reports state 0 again: x = 0 is out
  judge.Judge(PlanarStep(1), &p1);
  EXPECT_EQ(NumberProperty(p1, "post_contained"), 0);
  EXPECT_EQ(NumberProperty(p1, "post_centre_error"), 0.75);
  // Step 2 reports state 1 (truth x = 1), its heading one turn away: 6.2 - 2 pi is in it.
  Properties p2 = Post(1, 0, 2, -0.2, 0);
  judge.Judge(PlanarStep(2), &p2);
  EXPECT_EQ(NumberProperty(p2, "post_contained"), 1);
  EXPECT_NEAR(*NumberProperty(p2, "post_theta_truth"), 6.2 - 2 * 3.141592653589793, 1e-12);
  Properties empty = Post(2, kInf, -kInf, kInf, -kInf);
  judge.Judge(PlanarStep(3), &empty);
  EXPECT_EQ(NumberProperty(empty, "post_contained"), 0);
  EXPECT_FALSE(NumberProperty(empty, "post_area"));
  Properties none;  // no post_step: nothing added
  judge.Judge(PlanarStep(4), &none);
  EXPECT_TRUE(none.empty());
}

// A step's truth is its newest state's (chain: one step, newest state w):
// the oldest state's box is not judged against it.
TEST(PostStateJudgeTest, AStepsTruthIsItsNewestStates) {
  PostStateJudge judge;
  struct Step step = PlanarStep(0);
  step.views.csp.emplace();
  step.views.csp->newest = 20;
  Properties p = Post(0, -1, 1, 6, 6.5);
  judge.Judge(step, &p);
  EXPECT_FALSE(NumberProperty(p, "post_contained"));  // state 0's truth is unknown
  Properties q = Post(20, -1, 1, 6, 6.5);
  judge.Judge(step, &q);
  EXPECT_EQ(NumberProperty(q, "post_contained"), 1);
}

TEST(PostLocalizedStatesTest, EachStateKeepsItsLastReport) {
  PostStateJudge judge;
  std::vector<StepRecord> steps;
  const Properties reports[] = {Post(0, -1, 1, 6, 6.5), Post(0, -0.5, 0.5, 6, 6.5),
                                Post(1, 0.5, 1.5, 6, 6.5), Post(2, 3, 4, 6, 6.5)};
  for (int k = 0; k < 4; ++k) {
    StepRecord r;
    r.step = k;
    r.status = "contracted";
    r.vars = {{"x", 0, 0, 0}, {"y", 0, 0, 0}, {"theta", 0, 0, 0}};
    r.properties = reports[k];
    judge.Judge(PlanarStep(k), &r.properties);
    steps.push_back(r);
  }
  const std::vector<StepRecord> states = PostLocalizedStates(steps);
  ASSERT_EQ(states.size(), 3u);
  EXPECT_EQ(states[0].step, 0);
  EXPECT_EQ(states[0].vars[0].lo, -0.5);  // step 1's report, not step 0's
  EXPECT_EQ(states[0].area, 2);
  EXPECT_EQ(states[2].contained, 0);      // x = 2 is not in [3, 4]
  const RunMetrics m = ComputeMetrics(states);
  EXPECT_DOUBLE_EQ(m.consistency_rate, 2.0 / 3);
  EXPECT_DOUBLE_EQ(m.mean_area, (2.0 + 2 + 2) / 3);
  EXPECT_TRUE(std::isnan(m.time_mean_s));
  EXPECT_TRUE(PostLocalizedStates(HandSteps()).empty());
}

// A set estimate must lie within the step's domains; a particle cloud, whose
// model may place states anywhere (a start off the map, a re-draw over the
// whole map), need not; neither may hold a NaN, which its hull would skip.
TEST(InvalidEstimateReasonTest, DomainsBindSetsNotParticleClouds) {
  Views views;
  views.space.names = {"x", "y"};
  views.measurement_set.emplace();
  views.measurement_set->prior = Box({Interval(0, 10), Interval(0, 10)});
  const Box outside({Interval(-5, 3), Interval(1, 2)});
  EXPECT_NE(InvalidEstimateReason(views, BoxEstimate(outside)).find("x = [-5, 3] is not inside its domain"),
            std::string::npos);
  EXPECT_NE(InvalidEstimateReason(views, PavingEstimate(2, {}, {outside})), "");
  cv::Mat particles = (cv::Mat_<double>(2, 2) << -5, 1, 3, 2);
  EXPECT_EQ(InvalidEstimateReason(views, ParticleEstimate(particles, {1, 1})), "");
  particles.at<double>(1, 1) = kNaN;
  EXPECT_EQ(InvalidEstimateReason(views, ParticleEstimate(particles, {1, 1})), "particle 1: y is NaN");
  const cv::Mat one = (cv::Mat_<double>(1, 2) << 1, 1);
  EXPECT_EQ(InvalidEstimateReason(views, ParticleEstimate(one, {kNaN})), "particle 0's weight is NaN or negative");
  const Box with_nan({Interval(1, 2), Interval(1, kNaN, Interval::kOrdered)});
  EXPECT_EQ(InvalidEstimateReason(views, PavingEstimate(2, {}, {Box({Interval(1, 2), Interval(1, 2)}), with_nan})),
            "the paving's boundary box 1: y has a NaN bound");
  EXPECT_EQ(InvalidEstimateReason(views, PavingEstimate(2, {Box({Interval(1, 2)})}, {})),
            "the paving's inner box 0 has 1 components, not 2");
}

}  // namespace
}  // namespace icp
