#include "problems/line_intersection/line_intersection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "problems/measurement_checks.h"
#include "problems/registry.h"

namespace icp {
namespace {

TEST(LineIntersectionTest, OffersBothViewsOverTheSearchBox) {
  const LineIntersectionParams p;
  const Step step = MakeLineIntersectionStep(p, 3);
  ASSERT_TRUE(step.views.Offers(View::kMeasurementSet));
  ASSERT_TRUE(step.views.Offers(View::kCsp));
  const MeasurementSetView& set = *step.views.measurement_set;
  EXPECT_EQ(set.prior, Box({Interval(-10, 10), Interval(-10, 10)}));
  EXPECT_EQ(set.measurements.size(), 20u);
  EXPECT_EQ(set.outliers.size(), 20u);
  EXPECT_TRUE(set.sources.empty());
  EXPECT_FALSE(set.predict);
  const CspView& csp = *step.views.csp;
  EXPECT_EQ(csp.csp.constraints().size(), 20u);
  EXPECT_EQ(csp.states, (std::vector<StateRef>{{0, 0}, {0, 1}}));
  EXPECT_EQ(csp.newest, 0);
  EXPECT_EQ(step.views.space.names, (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(step.views.space.x, 0);
  EXPECT_EQ(step.views.space.y, 1);
  EXPECT_EQ(step.truth, step.csp_truth);
  EXPECT_TRUE(set.prior.Contains(step.truth));
  for (double t : step.truth) EXPECT_LE(std::abs(t), 5);
}

TEST(LineIntersectionTest, TruthSatisfiesTheInliersAndViolatesTheOutliers) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    SCOPED_TRACE(seed);
    const Step step = MakeLineIntersectionStep(LineIntersectionParams(), seed);
    const MeasurementSetView& set = *step.views.measurement_set;
    int outliers = 0;
    for (std::size_t i = 0; i < set.measurements.size(); ++i) {
      SCOPED_TRACE(step.views.csp->csp.ConstraintToString(static_cast<int>(i)));
      if (set.outliers[i]) {
        ++outliers;
        EXPECT_TRUE(RejectsTruth(*set.measurements[i], step.truth));
      } else {
        EXPECT_TRUE(KeepsTruth(*set.measurements[i], step.truth));
      }
    }
    EXPECT_EQ(outliers, 7);
  }
}

TEST(LineIntersectionTest, OutliersMissTheTruthByAClearMargin) {
  LineIntersectionParams p;
  p.radius = 1;
  p.offset_error = 0.01;
  const Step step = MakeLineIntersectionStep(p, 5);
  const MeasurementSetView& set = *step.views.measurement_set;
  for (std::size_t i = 0; i < set.measurements.size(); ++i) {
    // A box of half-width radius/20 around the truth still misses each
    // outlier line's band (they are at least radius/10 away along a unit
    // normal, and the box reaches at most sqrt(2) radius/20).
    Box box = BoxAround(step.truth, p.radius / 20);
    ContractContext context;
    set.measurements[i]->Contract(box, context);
    EXPECT_EQ(box.IsEmpty(), static_cast<bool>(set.outliers[i])) << i;
  }
}

TEST(LineIntersectionTest, SameSeedSameLinesOtherSeedOtherLines) {
  const LineIntersectionParams p;
  const Step a = MakeLineIntersectionStep(p, 11), b = MakeLineIntersectionStep(p, 11),
             c = MakeLineIntersectionStep(p, 12);
  EXPECT_EQ(Constraints(a), Constraints(b));
  EXPECT_EQ(a.truth, b.truth);
  EXPECT_EQ(a.views.measurement_set->outliers, b.views.measurement_set->outliers);
  EXPECT_NE(Constraints(a), Constraints(c));
  EXPECT_NE(a.truth, c.truth);
}

TEST(LineIntersectionTest, NoOutliersLeavesEveryLineThroughTheTruth) {
  LineIntersectionParams p;
  p.lines = 5;
  p.outliers = 0;
  const Step step = MakeLineIntersectionStep(p, 1);
  for (const auto& m : step.views.measurement_set->measurements)
    EXPECT_TRUE(KeepsTruth(*m, step.truth));
}

TEST(LineIntersectionTest, RegistryRejectsBadParametersAndYieldsOneStep) {
  const ProblemInfo& info = FindProblem("line-intersection");
  EXPECT_THROW(info.make({{"outliers", "20"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"lines", "3"}, {"outliers", "5"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"lines", "1"}, {"outliers", "0"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"radius", "0"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"offset_error", "-1"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"angles", "3"}}, 1), ParamError);
  EXPECT_THROW(info.resolve("line-intersection", {{"outliers", "20"}}), ParamError);
  try {
    info.make({{"outliers", "20"}}, 1);
    ADD_FAILURE() << "no error";
  } catch (const ParamError& e) {
    EXPECT_EQ(std::string(e.what()), "line-intersection.outliers = 20: must be < lines (20)");
  }
  EXPECT_EQ(info.resolve("line-intersection", {}).at("lines"), "20");
  auto problem = info.make({{"lines", "4"}, {"outliers", "1"}}, 1);
  EXPECT_EQ(problem->NumSteps(), 1);
  Step step;
  ASSERT_TRUE(problem->Next(&step));
  EXPECT_EQ(step.views.measurement_set->measurements.size(), 4u);
  EXPECT_FALSE(problem->Next(&step));
}

}  // namespace
}  // namespace icp
