#include "algorithms/accumulator/accumulator.h"

#include <gtest/gtest.h>

#include "algorithms/q_relaxed/q_relaxed.h"
#include "algorithms/relaxed/relaxed_testing.h"

namespace icp {
namespace {

using testing::Lines;

TEST(AccumulatorTest, TheHighestCountHoldsTheTruth) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto c = Lines(seed, 20, 7);
    const StepResult r = MakeAccumulator({{"cells", "200"}}, 0)->Step(c.views, StopCondition());
    ASSERT_EQ(r.estimate->Kind(), "accumulator");
    const auto& acc = dynamic_cast<const AccumulatorEstimate&>(*r.estimate);
    int row = 0, col = 0;
    ASSERT_TRUE(acc.grid().CellOf(c.truth[0], c.truth[1], &row, &col));
    EXPECT_GE(acc.counts().at<std::int32_t>(row, col), 13) << seed;
    EXPECT_LE(IntProperty(r.properties, "q").value(), 7) << seed;
    EXPECT_EQ(IntProperty(r.estimate->Extras(), "max_count").value(), 20 - IntProperty(r.properties, "q").value());
  }
}

TEST(AccumulatorTest, AGivenQKeepsEveryCellCountingMMinusQ) {
  const auto c = Lines(2, 20, 7);
  const StepResult r = MakeAccumulator({{"cells", "100"}, {"q", "7"}, {"auto_q", "false"}}, 0)
                           ->Step(c.views, StopCondition());
  EXPECT_TRUE(r.estimate->Contains(c.truth));
  EXPECT_EQ(IntProperty(r.estimate->Extras(), "threshold").value(), 13);
}

TEST(AccumulatorTest, TheSumOfTheSourcesIsTheAccumulatorOfAll) {
  // Prop. 13: accumulators of disjoint sets of measurements add up.
  auto c = Lines(3, 7, 3);
  const StepResult all = MakeAccumulator({{"cells", "150"}}, 0)->Step(c.views, StopCondition());
  c.views.measurement_set->sources = {0, 0, 0, 1, 1, 1, 1};
  const StepResult split = MakeAccumulator({{"cells", "150"}}, 0)->Step(c.views, StopCondition());
  const auto& a = dynamic_cast<const AccumulatorEstimate&>(*all.estimate);
  const auto& b = dynamic_cast<const AccumulatorEstimate&>(*split.estimate);
  EXPECT_EQ(cv::countNonZero(a.counts() != b.counts()), 0);
  EXPECT_GE(IntProperty(split.properties, "max_count_source_0").value(), 1);
  EXPECT_GE(IntProperty(split.properties, "max_count_source_1").value(), 1);
}

TEST(AccumulatorTest, RejectsWhatItCannotGrid) {
  auto c = Lines(1, 3, 0);
  c.views.measurement_set->prior[0] = Interval(-kInf, 0);
  EXPECT_THROW(MakeAccumulator({}, 0)->Step(c.views, StopCondition()), std::invalid_argument);
  EXPECT_THROW(MakeAccumulator({{"cells", "0"}}, 0), ParamError);
}

}  // namespace
}  // namespace icp
