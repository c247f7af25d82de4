#include "algorithms/accumulator/accumulator.h"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>
#include <string>

#include "algorithms/q_relaxed/q_relaxed.h"
#include "algorithms/relaxed/relaxed_testing.h"
#include "core/constraint_contractor.h"
#include "core/memory_budget.h"

namespace icp {
namespace {

using testing::Lines;

// Stopped by its time limit, it says so and why the box is still sound
// (the message was empty, unlike q-relaxed's and polynomial's).
TEST(AccumulatorTest, AStoppedCountSaysWhy) {
  const auto c = Lines(1, 20, 7);
  const StepResult r = MakeAccumulator({{"cells", "400"}}, 0)
                           ->Step(c.views, StopCondition::After(std::chrono::duration<double>(0)));
  EXPECT_EQ(r.summary.status, ContractStatus::kStopped);
  EXPECT_NE(r.summary.message.find("time limit reached"), std::string::npos) << r.summary.message;
  EXPECT_TRUE(r.estimate->Contains(c.truth));
}

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

// Three lines x + y = 2, x - y = 0 (both through (1, 1)) and x = 3 over a
// prior whose x is the given interval and y [0, 2].
Views ThroughOneOne(const Interval& x_domain) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", x_domain), y = csp.AddVariable("y", {0, 2});
  csp.AddConstraint(x + y, Interval(2));
  csp.AddConstraint(x - y, Interval(0));
  csp.AddConstraint(x, Interval(3));
  Views views;
  views.space.names = {"x", "y"};
  views.space.x = 0;
  views.space.y = 1;
  MeasurementSetView view;
  view.prior = csp.domains();
  view.measurements = ConstraintContractors(csp);
  views.measurement_set = std::move(view);
  return views;
}

TEST(AccumulatorTest, ADegeneratePriorKeepsThePointThatSatisfiesMMinusQ) {
  // A point prior (x in [1, 1]) and a subnormal width once divided a zero
  // cell width and indexed the grid with NaN.
  for (const Interval& x :
       {Interval(1), Interval(1, 1 + 2.2e-16), Interval(1, std::nextafter(1.0, 2))}) {
    for (const char* cells : {"1", "7", "1000"}) {
      const Views views = ThroughOneOne(x);
      const StepResult r = MakeAccumulator({{"cells", cells}}, 0)->Step(views, StopCondition());
      EXPECT_TRUE(r.estimate->Contains({1, 1})) << x << " " << cells;
      EXPECT_EQ(IntProperty(r.properties, "q").value(), 1) << x << " " << cells;
      const Box hull = r.estimate->Hull();
      EXPECT_TRUE(hull[0].Contains(1) && hull[1].Contains(1)) << x << " " << cells;
    }
  }
  const Views subnormal = ThroughOneOne(Interval(0, 5e-324));
  const StepResult r = MakeAccumulator({}, 0)->Step(subnormal, StopCondition());
  EXPECT_FALSE(r.estimate->Hull().IsEmpty());
}

#if !defined(ICPBENCH_SANITIZED)  // ASan's shadow memory counts as data: no limit there
// Lowers this process's soft data limit (RLIMIT_DATA, what a worker's
// memory_limit_mb sets) to what it uses plus `headroom` bytes, for a scope.
class DataLimit {
 public:
  explicit DataLimit(std::size_t headroom) {
    getrlimit(RLIMIT_DATA, &saved_);
    rlimit lowered = saved_;
    std::size_t used = 0;
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("VmData:", 0) == 0) used = std::stoull(line.substr(7)) * 1024;
    lowered.rlim_cur = used + headroom;
    setrlimit(RLIMIT_DATA, &lowered);
  }
  ~DataLimit() { setrlimit(RLIMIT_DATA, &saved_); }

 private:
  rlimit saved_{};
};

TEST(AccumulatorTest, AGridOverTheMemoryLimitFailsBeforeItIsAllocated) {
  // cells = 20000 (in range) needs 1.5 GiB of counts, more than 4 threads'
  // grids under the default memory_limit_mb: OpenCV failed inside with
  // "Insufficient memory". Now the size and the limit are in the message,
  // as a bad_alloc, which the harness records as out of memory.
  const auto c = Lines(1, 5, 0);
  DataLimit limit(200 << 20);
  try {
    MakeAccumulator({{"cells", "20000"}}, 0)->Step(c.views, StopCondition());
    ADD_FAILURE() << "no error";
  } catch (const MemoryBudgetError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("20000 x 20000 cells"), std::string::npos) << what;
    EXPECT_NE(what.find("needs 1526 MiB"), std::string::npos) << what;
    EXPECT_NE(what.find("data limit of"), std::string::npos) << what;
  }
}

TEST(AccumulatorTest, UnderAMemoryLimitFewerThreadsCountTheSame) {
  // 1000 x 1000 cells: 4 MB a grid. With room for two grids besides the
  // result one thread counts into it; the counts are those of all threads.
  const auto c = Lines(2, 20, 7);
  const StepResult free = MakeAccumulator({}, 0)->Step(c.views, StopCondition());
  StepResult tight;
  {
    DataLimit limit(10 << 20);
    tight = MakeAccumulator({}, 0)->Step(c.views, StopCondition());
  }
  const auto& a = dynamic_cast<const AccumulatorEstimate&>(*free.estimate);
  const auto& b = dynamic_cast<const AccumulatorEstimate&>(*tight.estimate);
  EXPECT_EQ(cv::countNonZero(a.counts() != b.counts()), 0);
}
#endif

TEST(AccumulatorTest, RejectsWhatItCannotGrid) {
  auto c = Lines(1, 3, 0);
  c.views.measurement_set->prior[0] = Interval(-kInf, 0);
  EXPECT_THROW(MakeAccumulator({}, 0)->Step(c.views, StopCondition()), std::invalid_argument);
  EXPECT_THROW(MakeAccumulator({{"cells", "0"}}, 0), ParamError);
}

}  // namespace
}  // namespace icp
