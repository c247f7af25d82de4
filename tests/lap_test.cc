// Every ICP algorithm keeps the truth at every step of a car-track lap, with
// each step's contracted box fed to the next (the harness's own run loop).
#include <gtest/gtest.h>

#include "algorithms/registry.h"
#include "tests/test_names.h"
#include "harness/runner.h"

namespace icp {
namespace {

class LapTest : public ::testing::TestWithParam<std::string> {};

TEST_P(LapTest, KeepsTheTruthAtEveryStep) {
  // A whole lap (2000 steps) for the propagation algorithms; 3B, about 100
  // times slower, drives the first 200 steps (the unknown heading and the
  // first turn) to keep the suite fast.
  const bool three_b = GetParam().rfind("3b", 0) == 0;
  const ParamMap problem = three_b ? ParamMap{{"steps", "200"}, {"w", "10"}} : ParamMap{};
  RunRecord r = ExecuteRun(RunSpec{GetParam(), {}, "car-track", problem, 1, 0});
  ASSERT_EQ(r.status, RunStatus::kOk) << r.reason;
  ASSERT_EQ(static_cast<int>(r.steps.size()), three_b ? 200 : 2000);
  for (const StepRecord& s : r.steps) {
    ASSERT_EQ(s.contained, 1) << GetParam() << " lost the truth at step " << s.step;
    ASSERT_NE(s.status, "empty");
  }
  EXPECT_EQ(r.metrics.consistency_rate, 1.0);
  // The GPS box alone is 5 m x 5 m: fusing odometry and gyro does better.
  EXPECT_LT(r.metrics.mean_area, 25.0);
}

INSTANTIATE_TEST_SUITE_P(AllAlgorithms, LapTest, ::testing::ValuesIn(testing::AlgorithmsNeeding(View::kCsp)),
                         testing::RegistryName());

}  // namespace
}  // namespace icp
