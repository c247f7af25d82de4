#include "algorithms/q_relaxed/q_relaxed.h"

#include <atomic>
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "algorithms/relaxed/relaxed_testing.h"
#include "core/contractor_testing.h"

namespace icp {
namespace {

using testing::Lines;

TEST(QRelaxedTest, QZeroIsTheRepeatedIntersection) {
  const auto c = Lines(1, 6, 0);
  auto solver = MakeQRelaxed({{"auto_q", "false"}}, 0);
  const StepResult r = solver->Step(c.views, StopCondition());
  FixpointContractor plain(std::make_shared<IntersectionContractor>(c.views.measurement_set->measurements),
                           1e-3, 1000);
  Box box = c.views.measurement_set->prior;
  ContractContext context;
  plain.Contract(box, context);
  EXPECT_EQ(r.estimate->Hull(), box);
  EXPECT_TRUE(r.estimate->Contains(c.truth));
  EXPECT_LT(box.MaxWidth(), 0.5);
}

TEST(QRelaxedTest, OutliersEmptyTheIntersectionButNotTheRelaxedOne) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto c = Lines(seed, 20, 7);
    const StepResult strict = MakeQRelaxed({{"auto_q", "false"}}, 0)->Step(c.views, StopCondition());
    EXPECT_TRUE(strict.estimate->Hull().IsEmpty()) << seed;
    const StepResult fixed = MakeQRelaxed({{"auto_q", "false"}, {"q", "7"}}, 0)->Step(c.views, StopCondition());
    EXPECT_TRUE(fixed.estimate->Contains(c.truth)) << seed;
    EXPECT_EQ(IntProperty(fixed.properties, "q").value(), 7);
    const StepResult found = MakeQRelaxed({}, 0)->Step(c.views, StopCondition());
    EXPECT_LE(IntProperty(found.properties, "q").value(), 7) << seed;
    EXPECT_TRUE(found.estimate->Contains(c.truth)) << seed;
    EXPECT_TRUE(found.estimate->Hull().IsSubsetOf(fixed.estimate->Hull())) << seed;
  }
}

TEST(QRelaxedTest, PavingKeepsTheTruthInNarrowBoxes) {
  const auto c = Lines(3, 8, 2);
  const StepResult r =
      MakeQRelaxed({{"mode", "pave"}, {"epsilon", "0.02"}}, 0)->Step(c.views, StopCondition());
  ASSERT_EQ(r.estimate->Kind(), "paving");
  EXPECT_TRUE(r.estimate->Contains(c.truth));
  const auto& paving = dynamic_cast<const PavingEstimate&>(*r.estimate);
  EXPECT_GE(paving.boundary().size(), 1u);
  for (const Box& b : paving.boundary()) EXPECT_LT(b.MaxWidth(), 0.02);
  // Tighter than the contracted box of the same q.
  const int q = static_cast<int>(IntProperty(r.properties, "q").value());
  const StepResult box = MakeQRelaxed({{"q", std::to_string(q)}, {"auto_q", "false"}}, 0)
                             ->Step(c.views, StopCondition());
  EXPECT_LE(r.estimate->Area(0, 1), box.estimate->Area(0, 1));
  EXPECT_TRUE(r.estimate->Hull().IsSubsetOf(box.estimate->Hull()));
}

TEST(QRelaxedTest, AsAFilterStartsFromThePrediction) {
  auto c = Lines(4, 10, 3);
  // A motion model that says the state did not move by more than 0.5.
  c.views.measurement_set->predict = [](const Box& previous) {
    Box out = previous;
    for (std::size_t d = 0; d < out.size(); ++d) out[d] = out[d] + Interval(-0.5, 0.5);
    return out;
  };
  auto solver = MakeQRelaxed({{"q", "5"}, {"auto_q", "false"}}, 0);
  const StepResult first = solver->Step(c.views, StopCondition());
  const StepResult second = solver->Step(c.views, StopCondition());
  EXPECT_TRUE(second.estimate->Contains(c.truth));
  EXPECT_TRUE(second.estimate->Hull().IsSubsetOf(first.estimate->Hull()));
  EXPECT_EQ(IntProperty(second.properties, "reset").value(), 0);
  auto unfiltered = MakeQRelaxed({{"q", "5"}, {"auto_q", "false"}, {"filter", "false"}}, 0);
  unfiltered->Step(c.views, StopCondition());
  EXPECT_EQ(unfiltered->Step(c.views, StopCondition()).estimate->Hull(), first.estimate->Hull());
}

TEST(QRelaxedTest, AFilterThatLosesTheTruthRestartsFromTheGlobalPrior) {
  // The robot jumps from one scene's truth to another's while the motion
  // model says it moved by at most 0.5: the tracked search holds no point
  // of the second scene, and the step must fall back to the global prior.
  auto first = Lines(4, 10, 2);
  auto second = Lines(5, 10, 2);
  ASSERT_GT(std::abs(first.truth[0] - second.truth[0]) + std::abs(first.truth[1] - second.truth[1]), 2);
  second.views.measurement_set->predict = [](const Box& previous) {
    Box out = previous;
    for (std::size_t d = 0; d < out.size(); ++d) out[d] = out[d] + Interval(-0.5, 0.5);
    return out;
  };
  auto solver = MakeQRelaxed({{"q", "2"}, {"auto_q", "false"}, {"mode", "pave"}}, 0);
  solver->Step(first.views, StopCondition());
  const StepResult r = solver->Step(second.views, StopCondition());
  EXPECT_EQ(IntProperty(r.properties, "reset").value(), 1);
  EXPECT_TRUE(r.estimate->Contains(second.truth));
  EXPECT_EQ(IntProperty(solver->RunProperties(), "resets").value(), 1);
}

TEST(QRelaxedTest, WithAutoQATrackedSearchNeedingTooManyOutliersRestarts) {
  // As above, but auto_q keeps the tracked search non-empty by dropping
  // measurements: the outlier count betrays the lost track.
  auto first = Lines(4, 10, 2);
  auto second = Lines(5, 10, 2);
  second.views.measurement_set->predict = [](const Box& previous) {
    Box out = previous;
    for (std::size_t d = 0; d < out.size(); ++d) out[d] = out[d] + Interval(-0.5, 0.5);
    return out;
  };
  auto stays = MakeQRelaxed({{"mode", "pave"}, {"outlier_share", "1"}}, 0);
  stays->Step(first.views, StopCondition());
  const StepResult kept = stays->Step(second.views, StopCondition());
  EXPECT_EQ(IntProperty(kept.properties, "reset").value(), 0);
  EXPECT_GT(IntProperty(kept.properties, "q").value(), 5);
  EXPECT_FALSE(kept.estimate->Contains(second.truth));
  auto restarts = MakeQRelaxed({{"mode", "pave"}, {"outlier_share", "0.3"}}, 0);
  restarts->Step(first.views, StopCondition());
  const StepResult r = restarts->Step(second.views, StopCondition());
  EXPECT_EQ(IntProperty(r.properties, "reset").value(), 1);
  EXPECT_LE(IntProperty(r.properties, "q").value(), 2);
  EXPECT_TRUE(r.estimate->Contains(second.truth));
}

TEST(QRelaxedTest, APavingStoppedByTheTimeLimitSaysSo) {
  // It was reported as truncated at max_boxes, with a status the harness
  // stores as ok instead of the run's timeout.
  auto c = Lines(3, 8, 2);
  std::atomic<bool> cancel = false;
  auto& measurements = c.views.measurement_set->measurements;
  const SharedContractors wrapped = testing::CancelAfterCalls({measurements[0]}, 40, &cancel);
  measurements[0] = wrapped[0];
  const StopCondition stop = StopCondition().WithCancelFlag(&cancel);
  const StepResult r = MakeQRelaxed({{"mode", "pave"}, {"epsilon", "0.001"}, {"q", "2"}}, 0)
                           ->Step(c.views, stop);
  ASSERT_TRUE(cancel);
  EXPECT_EQ(r.summary.status, ContractStatus::kStopped);
  EXPECT_NE(r.summary.message.find("time limit"), std::string::npos) << r.summary.message;
  EXPECT_EQ(r.summary.message.find("max_boxes"), std::string::npos) << r.summary.message;
  EXPECT_EQ(IntProperty(r.properties, "truncated").value(), 1);
  EXPECT_TRUE(r.estimate->Contains(c.truth));
  // max_boxes alone still says max_boxes, and is no stop.
  const StepResult full =
      MakeQRelaxed({{"mode", "pave"}, {"epsilon", "0.001"}, {"max_boxes", "5"}}, 0)
          ->Step(Lines(3, 8, 2).views, StopCondition());
  EXPECT_NE(full.summary.status, ContractStatus::kStopped);
  EXPECT_NE(full.summary.message.find("max_boxes"), std::string::npos) << full.summary.message;
}

TEST(QBoundTest, FloorsTheDecimalShareExactly) {
  // As doubles, 0.7 * 90 is 62.99999999999999 and 0.35 * 180 is
  // 62.99999999999999: the floor must read 0.7 as 7/10, 0.35 as 35/100.
  EXPECT_EQ(QBound(0, 0.7, 90), 63);
  EXPECT_EQ(QBound(0, 0.35, 180), 63);
  for (int m = 0; m <= 2000; ++m) {
    EXPECT_EQ(QBound(0, 0.3, m), 3 * m / 10) << m;
    EXPECT_EQ(QBound(0, 0.7, m), 7 * m / 10) << m;
    EXPECT_EQ(QBound(0, 0.35, m), 35 * m / 100) << m;
  }
  EXPECT_EQ(QBound(0, 1, 17), 17);
  EXPECT_EQ(QBound(0, 0, 17), 0);
  EXPECT_EQ(QBound(13, 0.3, 20), 13);  // q is the least bound
  EXPECT_EQ(QBound(13, 0.3, 50), 15);
}

TEST(QRelaxedTest, WithoutAutoQTheShareSetsQAndTheTruthIsKept) {
  // 7 outliers of 20: a share of 0.35 allows exactly them.
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto c = Lines(seed, 20, 7);
    const StepResult r = MakeQRelaxed({{"auto_q", "false"}, {"outlier_share", "0.35"}}, 0)
                             ->Step(c.views, StopCondition());
    EXPECT_EQ(IntProperty(r.properties, "q").value(), 7);
    EXPECT_EQ(IntProperty(r.properties, "q_bound").value(), 7);
    EXPECT_EQ(IntProperty(r.properties, "tracked").value(), 0);
    EXPECT_EQ(IntProperty(r.properties, "inconsistent").value(), 0);
    EXPECT_TRUE(r.estimate->Contains(c.truth)) << seed;
  }
}

TEST(QRelaxedTest, AutoQAboveTheBoundIsAnInconsistency) {
  // The default share 0 with auto_q: a global step that needs outliers
  // says so, and a tracked step restarts.
  auto c = Lines(4, 10, 2);
  c.views.measurement_set->predict = [](const Box& previous) { return previous; };
  auto solver = MakeQRelaxed({{"mode", "pave"}}, 0);
  const StepResult first = solver->Step(c.views, StopCondition());
  EXPECT_GT(IntProperty(first.properties, "q").value(), 0);
  EXPECT_EQ(IntProperty(first.properties, "q_bound").value(), 0);
  EXPECT_EQ(IntProperty(first.properties, "inconsistent").value(), 1);
  EXPECT_EQ(IntProperty(first.properties, "reset").value(), 0);
  const StepResult second = solver->Step(c.views, StopCondition());
  EXPECT_EQ(IntProperty(second.properties, "tracked").value(), 0);
  EXPECT_EQ(IntProperty(second.properties, "reset").value(), 1);
  // With a share that allows them, the second step follows the first.
  auto allowed = MakeQRelaxed({{"mode", "pave"}, {"outlier_share", "0.3"}}, 0);
  const StepResult started = allowed->Step(c.views, StopCondition());
  EXPECT_EQ(IntProperty(started.properties, "inconsistent").value(), 0);
  const StepResult followed = allowed->Step(c.views, StopCondition());
  EXPECT_EQ(IntProperty(followed.properties, "tracked").value(), 1);
  EXPECT_EQ(IntProperty(followed.properties, "inconsistent").value(), 0);
  EXPECT_TRUE(followed.estimate->Contains(c.truth));
}

TEST(QRelaxedTest, RejectsBadParameters) {
  EXPECT_THROW(MakeQRelaxed({{"q", "-1"}}, 0), ParamError);
  EXPECT_THROW(MakeQRelaxed({{"mode", "sivia"}}, 0), ParamError);
  EXPECT_THROW(MakeQRelaxed({{"epsilon", "0"}}, 0), ParamError);
  EXPECT_THROW(MakeQRelaxed({{"outlier_share", "-0.1"}}, 0), ParamError);
  EXPECT_THROW(MakeQRelaxed({{"outlier_share", "1.5"}}, 0), ParamError);
}

}  // namespace
}  // namespace icp
