#include "experiments/paper002/paper002.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace icp {
namespace {

StepRecord StepOf(int k, double half_width, double theta_centre, double theta_truth, bool held) {
  StepRecord s;
  s.step = k;
  s.vars = {{"x", 1 - half_width, 1 + half_width, 1.1},
            {"y", 2 - half_width, 2 + half_width, 2},
            {"theta", theta_centre - 0.1, theta_centre + 0.1, theta_truth}};
  s.area = 4 * half_width * half_width;
  s.centre_error = 0.1;
  s.contained = held ? 1 : 0;
  return s;
}

TEST(Paper002Test, RunStatsFromTheSteps) {
  RunRecord run;
  // Heading error wrapped: centre pi - 0.01 against truth -pi + 0.01 is 0.02.
  run.steps = {StepOf(0, 0.05, 0, 0.01, true), StepOf(1, 0.1, 0, -0.01, true),
               StepOf(2, 0.08, std::numbers::pi - 0.01, -std::numbers::pi + 0.01, true)};
  const IndoorRunStats s = IndoorStats(run);
  EXPECT_NEAR(s.widest_x, 0.2, 1e-12);
  EXPECT_NEAR(s.widest_y, 0.2, 1e-12);
  EXPECT_NEAR(s.widest_theta_deg, 0.2 * 180 / std::numbers::pi, 1e-9);
  EXPECT_DOUBLE_EQ(s.position_error, 0.1);
  EXPECT_NEAR(s.heading_error_deg, (0.01 + 0.01 + 0.02) / 3 * 180 / std::numbers::pi, 1e-9);
  EXPECT_DOUBLE_EQ(s.growth_share, 0.5);  // the 3-D box grew at step 1, shrank at step 2
  EXPECT_TRUE(std::isnan(IndoorStats(RunRecord()).widest_x));
}

RunRecord IndoorRun(const std::string& algorithm, const std::string& path, std::uint64_t seed) {
  RunRecord run;
  run.spec.algorithm = algorithm;
  run.spec.problem = "indoor-landmarks";
  run.spec.problem_params = {{"path", path}};
  run.spec.seed = seed;
  run.spec_file = "specs/default.yaml#indoor";
  run.status = RunStatus::kOk;
  run.steps = {StepOf(0, 0.05, 0, 0, true), StepOf(1, 0.07, 0, 0, true)};
  run.steps[1].properties = {{"assumption_held", std::int64_t{1}}};
  run.metrics.steps = 2;
  run.metrics.consistency_rate = 1;
  run.properties = {{"associations_right", std::int64_t{10}},
                    {"associations_wrong", std::int64_t{1}},
                    {"associations_missed", std::int64_t{2}},
                    {"wrong_association_steps", std::int64_t{1}},
                    {"wrong_association_losses", std::int64_t{0}}};
  return run;
}

TEST(Paper002Test, TableRowsPerConfigurationAndPathWithThePapersRows) {
  const std::vector<RunRecord> runs = {IndoorRun("landmark-tracking", "a", 1),
                                       IndoorRun("landmark-tracking", "a", 2),
                                       IndoorRun("landmark-tracking", "b", 1)};
  const std::vector<TextTable> tables = Paper002Tables(runs);
  ASSERT_EQ(tables.size(), 2u);
  const TextTable& accuracy = tables[0];
  ASSERT_EQ(accuracy.rows.size(), 4u);  // a, b, and the paper's two rows
  EXPECT_EQ(accuracy.rows[0][1], "a");
  EXPECT_EQ(accuracy.rows[0][2], "2");
  EXPECT_EQ(accuracy.rows[0][4], "100 (2)");
  EXPECT_EQ(accuracy.rows[1][1], "b");
  EXPECT_NE(accuracy.rows[3][5].find("0.2"), std::string::npos);
  const TextTable& associations = tables[1];
  ASSERT_EQ(associations.rows.size(), 2u);
  EXPECT_EQ(associations.rows[0][3], "20 / 2 / 4");
  EXPECT_EQ(associations.rows[0][4], "0 of 2");
  // Without indoor runs each table is a sentence saying where they come
  // from, not an empty section.
  for (const TextTable& empty : Paper002Tables({})) {
    EXPECT_TRUE(empty.rows.empty()) << empty.title;
    ASSERT_EQ(empty.notes.size(), 1u) << empty.title;
    EXPECT_NE(empty.notes[0].find("specs/default.yaml"), std::string::npos) << empty.title;
  }
}

}  // namespace
}  // namespace icp
