#include "problems/beacon_ranges/beacon_ranges.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "problems/measurement_checks.h"
#include "problems/registry.h"

namespace icp {
namespace {

std::unique_ptr<Problem> Make(const ParamMap& params, std::uint64_t seed) {
  return FindProblem("beacon-ranges").make(params, seed);
}

std::vector<Step> AllSteps(Problem& problem) {
  std::vector<Step> steps;
  Step step;
  while (problem.Next(&step)) steps.push_back(step);
  return steps;
}

// Every inlier keeps the truth, every outlier rejects it.
void ExpectOutliersAreTheOnesMissingTheTruth(const Step& step) {
  const MeasurementSetView& set = *step.views.measurement_set;
  ASSERT_EQ(set.outliers.size(), set.measurements.size());
  for (std::size_t i = 0; i < set.measurements.size(); ++i) {
    SCOPED_TRACE(step.views.csp->csp.ConstraintToString(static_cast<int>(i)));
    if (set.outliers[i]) {
      EXPECT_TRUE(RejectsTruth(*set.measurements[i], step.truth));
    } else {
      EXPECT_TRUE(KeepsTruth(*set.measurements[i], step.truth));
    }
  }
}

int Count(const std::vector<bool>& flags) {
  int n = 0;
  for (bool f : flags) n += f;
  return n;
}

TEST(BeaconRangesTest, SquaredBoundsEncloseTheRealSquares) {
  const Interval b = SquaredRangeBounds(0.3, 0.1);
  EXPECT_LE(b.lo(), 0.04);
  EXPECT_GE(b.hi(), 0.16);
  EXPECT_EQ(SquaredRangeBounds(0.05, 0.1).lo(), 0);
}

TEST(BeaconRangesTest, TwoRobotsSceneHasItsSourcesAndOutliers) {
  auto problem = Make({}, 1);
  EXPECT_EQ(problem->NumSteps(), 1);
  Step step;
  ASSERT_TRUE(problem->Next(&step));
  EXPECT_FALSE(problem->Next(&step));
  const MeasurementSetView& set = *step.views.measurement_set;
  EXPECT_EQ(set.sources, (std::vector<int>{0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(Count(std::vector<bool>(set.outliers.begin(), set.outliers.begin() + 3)), 1);
  EXPECT_EQ(Count(std::vector<bool>(set.outliers.begin() + 3, set.outliers.end())), 2);
  EXPECT_FALSE(set.predict);
  EXPECT_EQ(set.prior, Box({Interval(-10, 10), Interval(-10, 10)}));
  EXPECT_EQ(step.truth, (std::vector<double>{1.5, -0.5}));
  EXPECT_EQ(step.csp_truth, step.truth);
  EXPECT_EQ(step.views.csp->csp.constraints().size(), 7u);
  EXPECT_EQ(step.views.csp->states, (std::vector<StateRef>{{0, 0}, {0, 1}}));
  ExpectOutliersAreTheOnesMissingTheTruth(step);
}

// Representatives of points more than `separation` apart: a lower bound on
// the number of separate places the points cover.
std::vector<std::vector<double>> Places(const std::vector<std::vector<double>>& points,
                                        double separation) {
  std::vector<std::vector<double>> places;
  for (const auto& p : points) {
    bool near = false;
    for (const auto& q : places) near = near || std::hypot(p[0] - q[0], p[1] - q[1]) <= separation;
    if (!near) places.push_back(p);
  }
  return places;
}

// Figs. 5.5-5.7, point by point: each constraint evaluated exactly (plain
// doubles) on a grid of points of the search box, plus the truth.
TEST(BeaconRangesTest, TwoRobotsAccumulatorsHaveManyMaximaAloneAndOneTogether) {
  const BeaconScene scene = ReadBeaconScene(TwoRobotsScenePath());
  std::vector<Interval> bounds;
  for (const RangeMeasurement& r : scene.ranges)
    bounds.push_back(SquaredRangeBounds(r.range, r.error));
  std::vector<std::vector<double>> points = {scene.truth};
  const double h = 0.02;
  for (int i = 0; i <= 1000; ++i)
    for (int j = 0; j <= 1000; ++j) points.push_back({-10 + i * h, -10 + j * h});

  std::vector<std::vector<double>> a_best, b_best, both_best;
  int a_max = 0, b_max = 0, both_max = 0;
  for (const auto& p : points) {
    int count[2] = {0, 0};
    for (std::size_t k = 0; k < scene.ranges.size(); ++k) {
      const RangeMeasurement& r = scene.ranges[k];
      const double dx = p[0] - r.beacon_x, dy = p[1] - r.beacon_y;
      count[r.source] += bounds[k].Contains(dx * dx + dy * dy);
    }
    a_max = std::max(a_max, count[0]);
    b_max = std::max(b_max, count[1]);
    both_max = std::max(both_max, count[0] + count[1]);
    if (count[0] == 2) a_best.push_back(p);
    if (count[1] == 2) b_best.push_back(p);
    if (count[0] + count[1] == 4) both_best.push_back(p);
  }
  EXPECT_EQ(a_max, 2);
  EXPECT_EQ(b_max, 2);
  EXPECT_EQ(both_max, 4);
  EXPECT_GE(Places(a_best, 2).size(), 3u);
  EXPECT_GE(Places(b_best, 2).size(), 3u);
  ASSERT_FALSE(both_best.empty());
  for (const auto& p : both_best)
    EXPECT_LT(std::hypot(p[0] - scene.truth[0], p[1] - scene.truth[1]), 0.3)
        << p[0] << ", " << p[1];
}

TEST(BeaconRangesTest, RandomScenarioMissesTheTruthWithItsOutliersOnly) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    SCOPED_TRACE(seed);
    auto problem = Make({{"scenario", "random"}}, seed);
    const std::vector<Step> steps = AllSteps(*problem);
    ASSERT_EQ(steps.size(), 1u);
    const Step& step = steps[0];
    EXPECT_EQ(step.views.measurement_set->measurements.size(), 6u);
    EXPECT_EQ(Count(step.views.measurement_set->outliers), 2);
    EXPECT_TRUE(step.views.measurement_set->sources.empty());
    for (double t : step.truth) EXPECT_LE(std::abs(t), 5);
    ExpectOutliersAreTheOnesMissingTheTruth(step);
  }
}

TEST(BeaconRangesTest, RandomOutliersMissByMoreThanTheRangeError) {
  // A box of half-width 0.2 around the truth moves a distance by at most
  // 0.29: still clear of every outlier's annulus (missed by >= 1 - 0.1).
  auto problem = Make({{"scenario", "random"}, {"beacons", "12"}, {"outliers", "8"}}, 4);
  const Step step = AllSteps(*problem)[0];
  const MeasurementSetView& set = *step.views.measurement_set;
  for (std::size_t i = 0; i < set.measurements.size(); ++i) {
    Box box = BoxAround(step.truth, 0.2);
    ContractContext context;
    set.measurements[i]->Contract(box, context);
    EXPECT_EQ(box.IsEmpty(), static_cast<bool>(set.outliers[i])) << i;
  }
}

TEST(BeaconRangesTest, SameSeedSameRangesOtherSeedOtherRanges) {
  for (const char* scenario : {"random", "moving"}) {
    SCOPED_TRACE(scenario);
    const ParamMap params = {{"scenario", scenario}, {"steps", "5"}};
    auto a = Make(params, 7), b = Make(params, 7), c = Make(params, 8);
    const auto sa = AllSteps(*a), sb = AllSteps(*b), sc = AllSteps(*c);
    ASSERT_EQ(sa.size(), sb.size());
    ASSERT_EQ(sa.size(), sc.size());
    for (std::size_t k = 0; k < sa.size(); ++k) {
      EXPECT_EQ(Constraints(sa[k]), Constraints(sb[k]));
      EXPECT_EQ(sa[k].truth, sb[k].truth);
      EXPECT_EQ(sa[k].views.measurement_set->outliers, sb[k].views.measurement_set->outliers);
      EXPECT_NE(Constraints(sa[k]), Constraints(sc[k]));
    }
  }
}

TEST(BeaconRangesTest, MovingRobotStaysInsideThePredictionOfItsPreviousPosition) {
  for (std::uint64_t seed = 0; seed < 5; ++seed) {
    SCOPED_TRACE(seed);
    auto problem = Make({{"scenario", "moving"}, {"steps", "40"}, {"odometry_error", "0.05"}}, seed);
    EXPECT_EQ(problem->NumSteps(), 40);
    const std::vector<Step> steps = AllSteps(*problem);
    ASSERT_EQ(steps.size(), 40u);
    Step extra;
    EXPECT_FALSE(problem->Next(&extra));
    EXPECT_FALSE(steps[0].views.measurement_set->predict);
    for (int t = 0; t < 40; ++t) {
      SCOPED_TRACE(t);
      const Step& step = steps[t];
      EXPECT_EQ(step.views.step, t);
      EXPECT_EQ(step.views.csp->states, (std::vector<StateRef>{{t, 0}, {t, 1}}));
      EXPECT_EQ(step.views.csp->newest, t);
      EXPECT_EQ(step.views.csp->csp.constraints().size(), 6u);
      EXPECT_EQ(Count(step.views.measurement_set->outliers), 2);
      EXPECT_NEAR(std::hypot(step.truth[0], step.truth[1]), 5, 1e-9);
      ExpectOutliersAreTheOnesMissingTheTruth(step);
      if (t == 0) continue;
      EXPECT_NEAR(std::hypot(step.truth[0] - steps[t - 1].truth[0],
                             step.truth[1] - steps[t - 1].truth[1]), 1, 0.01);
      const auto& predict = step.views.measurement_set->predict;
      ASSERT_TRUE(predict);
      const Box predicted = predict(BoxAround(steps[t - 1].truth, 1e-9));
      EXPECT_TRUE(predicted.Contains(step.truth));
      EXPECT_LE(predicted.MaxWidth(), 4 * 0.05 + 1e-6);
      EXPECT_TRUE(predict(BoxAround(steps[t - 1].truth, 0)).Contains(step.truth));
    }
  }
}

TEST(BeaconRangesTest, OutlierSetsChangeFromStepToStep) {
  auto problem = Make({{"scenario", "moving"}, {"steps", "20"}}, 3);
  const std::vector<Step> steps = AllSteps(*problem);
  bool changed = false;
  for (std::size_t t = 1; t < steps.size(); ++t)
    changed = changed ||
              steps[t].views.measurement_set->outliers != steps[0].views.measurement_set->outliers;
  EXPECT_TRUE(changed);
}

TEST(BeaconRangesTest, RegistryRejectsBadParameters) {
  const ProblemInfo& info = FindProblem("beacon-ranges");
  EXPECT_THROW(Make({{"scenario", "three-robots"}}, 1), ParamError);
  EXPECT_THROW(Make({{"scenario", "random"}, {"outliers", "6"}}, 1), ParamError);
  EXPECT_THROW(Make({{"beacons", "3"}, {"outliers", "3"}}, 1), ParamError);
  EXPECT_THROW(Make({{"beacons", "0"}, {"outliers", "0"}}, 1), ParamError);
  EXPECT_THROW(Make({{"range_error", "0"}}, 1), ParamError);
  EXPECT_THROW(Make({{"range_error", "0.5"}}, 1), ParamError);
  EXPECT_THROW(Make({{"radius", "1"}}, 1), ParamError);
  EXPECT_THROW(Make({{"steps", "0"}}, 1), ParamError);
  EXPECT_THROW(Make({{"odometry_error", "0"}}, 1), ParamError);
  EXPECT_THROW(info.resolve("beacon-ranges", {{"outliers", "9"}}), ParamError);
  try {
    Make({{"outliers", "6"}}, 1);
    ADD_FAILURE() << "no error";
  } catch (const ParamError& e) {
    EXPECT_EQ(std::string(e.what()), "beacon-ranges.outliers = 6: must be < beacons (6)");
  }
  const ParamMap resolved = info.resolve("beacon-ranges", {});
  EXPECT_EQ(resolved.at("scenario"), "two-robots");
  EXPECT_EQ(resolved.at("steps"), "50");
}

TEST(BeaconRangesTest, BadSceneFilesFailWithTheirLine) {
  const std::string path = testing::TempDir() + "/bad_scene.csv";
  std::ofstream(path) << "box,-1,1,-1,1\ntruth,0,0\nrange,0,1,1,abc,0.1,0\n";
  try {
    ReadBeaconScene(path);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bad_scene.csv:3:"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ReadBeaconScene(testing::TempDir() + "/no_such_scene.csv"), std::invalid_argument);
}

// A UTF-8 byte-order mark at the start is skipped; file content quoted in a
// message has its control and non-ASCII bytes escaped.
TEST(BeaconRangesTest, SceneByteOrderMarkSkippedAndQuotedBytesEscaped) {
  const std::string scene = "box,-1,1,-1,1\ntruth,0,0\nrange,0,1,1,1,0.1,0\n";
  std::istringstream bom("\xEF\xBB\xBF" + scene);
  EXPECT_EQ(ReadBeaconScene(bom, "bom.csv").ranges.size(), 1u);
  auto error = [](const std::string& text) {
    std::istringstream in(text);
    try {
      ReadBeaconScene(in, "scene.csv");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string nul = error(scene + std::string("range,0,1,1,1\0,0.1,0\n", 21));
  EXPECT_NE(nul.find("scene.csv:4: field 5: '1\\x00' is not a finite number"), std::string::npos)
      << nul;
  const std::string kind = error("\x1b[2J,1\n");
  EXPECT_NE(kind.find("unknown row kind '\\x1b[2J'"), std::string::npos) << kind;
}

}  // namespace
}  // namespace icp

namespace icp {
namespace {

// The mixture likelihood prefers the truth to states far from it, even
// with outliers among the ranges; outside the search box nothing is
// possible.
TEST(BeaconRangesTest, ProbabilisticLikelihoodPrefersTheTruth) {
  for (const char* scenario : {"two-robots", "random", "moving"}) {
    SCOPED_TRACE(scenario);
    std::vector<Step> steps = AllSteps(*Make({{"scenario", scenario}, {"steps", "20"}}, 6));
    for (const Step& step : steps) {
      ASSERT_TRUE(step.views.Offers(View::kProbabilistic));
      const ProbabilisticView& view = *step.views.probabilistic;
      const double truth = view.log_likelihood(step.truth);
      EXPECT_TRUE(std::isfinite(truth));
      for (double dx : {-3.0, 3.0})
        for (double dy : {-3.0, 0.0, 3.0}) {
          const std::vector<double> far = {step.truth[0] + dx, step.truth[1] + dy};
          EXPECT_GT(truth, view.log_likelihood(far)) << dx << " " << dy;
        }
      EXPECT_EQ(view.log_likelihood({1e6, 0}), -std::numeric_limits<double>::infinity());
      RandomEngine rng(1);
      for (int i = 0; i < 20; ++i) {
        EXPECT_TRUE(std::isfinite(view.log_likelihood(view.sample_prior(rng))));
        EXPECT_TRUE(std::isfinite(view.log_likelihood(view.sample_global(rng))));
      }
    }
  }
}

TEST(BeaconRangesTest, ProbabilisticMotionIsTheOdometryAndDrawsNothingOfTheProblem) {
  const ParamMap params = {{"scenario", "moving"}, {"steps", "30"}};
  auto a = Make(params, 8), b = Make(params, 8);
  RandomEngine rng(2);
  const double e = BeaconRangesParams().odometry_error;
  Step sa, sb;
  std::vector<double> previous;
  while (a->Next(&sa)) {
    ASSERT_TRUE(b->Next(&sb));
    SCOPED_TRACE("step " + std::to_string(sa.views.step));
    const ProbabilisticView& view = *sa.views.probabilistic;
    std::vector<double> moved = sa.views.step == 0 ? sa.truth : previous;
    view.sample_motion(moved, rng);
    if (sa.views.step == 0) {
      EXPECT_EQ(moved, sa.truth);
    } else {
      // Drawn within the reading ± e, the reading within e/2 of the truth.
      EXPECT_LE(std::fabs(moved[0] - sa.truth[0]), 1.5 * e + 1e-12);
      EXPECT_LE(std::fabs(moved[1] - sa.truth[1]), 1.5 * e + 1e-12);
      EXPECT_TRUE(sa.views.measurement_set->predict(Box({Interval(previous[0]), Interval(previous[1])}))
                      .Contains(moved));
    }
    view.log_likelihood(moved);
    view.sample_global(rng);
    previous = sa.truth;
    EXPECT_EQ(sa.truth, sb.truth);
    const ConstraintSystem& ca = sa.views.csp->csp;
    const ConstraintSystem& cb = sb.views.csp->csp;
    ASSERT_EQ(ca.constraints().size(), cb.constraints().size());
    for (int i = 0; i < static_cast<int>(ca.constraints().size()); ++i)
      EXPECT_EQ(ca.ConstraintToString(i), cb.ConstraintToString(i));
  }
}

}  // namespace
}  // namespace icp
