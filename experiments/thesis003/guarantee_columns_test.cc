#include "experiments/thesis003/guarantee_columns.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace icp {
namespace {

StepRecord Judged(int contained, int held, const std::string& reason = "") {
  StepRecord s;
  s.contained = contained;
  s.properties = {{"assumption_held", std::int64_t{held}}};
  if (!reason.empty()) s.properties.push_back({"miss_reason", reason});
  return s;
}

TEST(GuaranteeColumnsTest, PoolRunsOverTheStepsWhereTheAssumptionHeld) {
  RunRecord a, b;
  // Run a: held on 3 steps, one of which misses (2 steps to re-acquire);
  // run b: a step where the assumption failed, then re-acquired in 1.
  a.steps = {Judged(1, 1), Judged(0, 1, "auto_q under-counted outliers (q=1, true 2)"),
             Judged(0, 0, "assumption violated (3 true outliers > q_bound 2)"), Judged(1, 1)};
  b.steps = {Judged(0, 0, "assumption violated (4 true outliers > q_bound 2)"), Judged(1, 0)};
  GroupSummary g;
  g.ok_runs = {&a, &b};
  const GuaranteeSummary s = SummariseGuarantee(g);
  EXPECT_EQ(s.judged, 6);
  EXPECT_EQ(s.held, 3);
  EXPECT_DOUBLE_EQ(s.ConsistencyWhereHeld(), 2.0 / 3);
  EXPECT_EQ(s.misses, 3);
  EXPECT_EQ(s.dominant, "assumption violated");
  EXPECT_EQ(s.dominant_count, 2);
  EXPECT_DOUBLE_EQ(s.median_reacquire, 1.5);  // episodes of 2 and 1 steps
  const std::vector<std::string> cells = GuaranteeCells(g);
  ASSERT_EQ(cells.size(), GuaranteeHeaders().size());
  EXPECT_EQ(cells[0], "3 of 6");
  EXPECT_EQ(cells[3], "assumption violated (2 of 3 misses)");
}

TEST(GuaranteeColumnsTest, NoJudgedStepsGiveDashes) {
  RunRecord r;
  r.steps = {StepRecord{}};
  GroupSummary g;
  g.ok_runs = {&r};
  EXPECT_TRUE(std::isnan(SummariseGuarantee(g).ConsistencyWhereHeld()));
  EXPECT_EQ(GuaranteeCells(g), (std::vector<std::string>{"—", "—", "—", "—"}));
}

}  // namespace
}  // namespace icp
