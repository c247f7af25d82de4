// Performance profiles of hand-built runs whose profiles are known: the
// ratios to each instance's best, failed and missing runs as not solved,
// repeats as their median, and the report's table.
#include "report/performance_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "report/report_testing.h"

namespace icp {
namespace {

using testing::MakeRun;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const SolverProfile& Of(const PerformanceProfile& p, const std::string& solver) {
  for (const SolverProfile& s : p.solvers)
    if (s.solver == solver) return s;
  throw std::out_of_range(solver);
}

TEST(PerformanceProfileTest, RatiosToTheBestOfEachInstance) {
  // Instance i1: A 1, B 2, C 4. i2: A 3, B 1, C failed. i3: A 10, B 10,
  // C 5. i4: only A failed (nobody solves it).
  const PerformanceProfile p = ComputeProfile({{"A", "i1", 1},
                                               {"B", "i1", 2},
                                               {"C", "i1", 4},
                                               {"A", "i2", 3},
                                               {"B", "i2", 1},
                                               {"C", "i2", kNaN},
                                               {"A", "i3", 10},
                                               {"B", "i3", 10},
                                               {"C", "i3", 5},
                                               {"A", "i4", kNaN}});
  EXPECT_EQ(p.instances, 4);
  ASSERT_EQ(p.solvers.size(), 3u);
  EXPECT_EQ(p.solvers[0].solver, "A");  // first-entry order
  EXPECT_EQ(Of(p, "A").ratios, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(Of(p, "B").ratios, (std::vector<double>{1, 2, 2}));
  EXPECT_EQ(Of(p, "C").ratios, (std::vector<double>{1, 4}));
  EXPECT_EQ(Of(p, "A").solved, 3);
  EXPECT_EQ(Of(p, "C").solved, 2);
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "A"), 1), 0.25);
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "A"), 1.5), 0.25);
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "A"), 2), 0.5);
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "A"), 10), 0.75);  // i4 is never solved
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "B"), 1.99), 0.25);
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "B"), 2), 0.75);
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "C"), 3.9), 0.25);
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "C"), 4), 0.5);
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "C"), 1e9), 0.5);  // failed on i2, not run on i4
}

TEST(PerformanceProfileTest, RepeatsGiveTheirMedianAndZeroBestsAreExact) {
  const PerformanceProfile p = ComputeProfile({{"A", "i1", 2},
                                               {"A", "i1", 9},
                                               {"A", "i1", 4},  // median 4
                                               {"B", "i1", 1},
                                               {"B", "i1", 3},  // median 2
                                               {"A", "i2", 0},
                                               {"B", "i2", 0},
                                               {"A", "i3", 0},
                                               {"B", "i3", 1}});  // infinitely worse
  EXPECT_EQ(p.instances, 3);
  EXPECT_EQ(Of(p, "A").ratios, (std::vector<double>{1, 1, 2}));
  EXPECT_EQ(Of(p, "B").ratios, (std::vector<double>{1, 1}));
  EXPECT_EQ(Of(p, "B").solved, 3);  // solved i3, but never within a factor of 0
  EXPECT_DOUBLE_EQ(Rho(p, Of(p, "B"), 1e300), 2.0 / 3);
  EXPECT_EQ(Rho(ComputeProfile({}), SolverProfile{}, 1), 0);
}

TEST(PerformanceProfileTest, RunsAreConfigurationsOnInstancesAndFailuresCountAsUnsolved) {
  // Two seeds of one problem configuration: two instances. HC4 takes 1 µs,
  // BC4 2 µs on seed 1; on seed 2 HC4 fails and BC4 takes 3 µs.
  const std::vector<RunRecord> runs = {
      MakeRun("bc4", {}, {{"w", "5"}}, 1, {2e-6, 2e-6}),
      MakeRun("hc4", {}, {{"w", "5"}}, 1, {1e-6, 1e-6}),
      MakeRun("hc4", {{"carry", "none"}}, {{"w", "5"}}, 1, {4e-6, 4e-6}),
      MakeRun("hc4", {}, {{"w", "5"}}, 2, {}, RunStatus::kFailed, "threw"),
      MakeRun("bc4", {}, {{"w", "5"}}, 2, {3e-6})};
  const PerformanceProfile p = RunsProfile(runs, ProfileMetric::kTime);
  EXPECT_EQ(p.instances, 2);
  ASSERT_EQ(p.solvers.size(), 3u);
  // Display order: HC4 before BC4, default parameters first.
  EXPECT_EQ(p.solvers[0].solver, "HC4");
  EXPECT_EQ(p.solvers[1].solver, "HC4 {carry=none}");
  EXPECT_EQ(p.solvers[2].solver, "BC4");
  EXPECT_DOUBLE_EQ(Rho(p, p.solvers[0], 1), 0.5);
  EXPECT_DOUBLE_EQ(Rho(p, p.solvers[0], 100), 0.5);  // its failure is not solved
  EXPECT_DOUBLE_EQ(Rho(p, p.solvers[1], 3.9), 0);
  EXPECT_DOUBLE_EQ(Rho(p, p.solvers[1], 4), 0.5);  // not run on seed 2
  EXPECT_DOUBLE_EQ(Rho(p, p.solvers[2], 1), 0.5);
  EXPECT_DOUBLE_EQ(Rho(p, p.solvers[2], 2), 1);
  // Every run's box is 4 m²: all tie on area.
  const PerformanceProfile area = RunsProfile(runs, ProfileMetric::kArea);
  EXPECT_DOUBLE_EQ(Rho(area, area.solvers[2], 1), 1);
  EXPECT_DOUBLE_EQ(Rho(area, area.solvers[0], 1), 0.5);

  const TextTable t = ProfileTable(runs, ProfileMetric::kTime);
  EXPECT_NE(t.title.find("of the 2 instances"), std::string::npos) << t.title;
  ASSERT_EQ(t.headers.size(), 2 + std::size(kProfileTaus));
  EXPECT_EQ(t.headers[2], "τ = 1");
  EXPECT_EQ(t.headers[3], "τ = 1.5");
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"HC4", "1", "0.50", "0.50", "0.50", "0.50", "0.50"}));
  EXPECT_EQ(t.rows[2], (std::vector<std::string>{"BC4", "2", "0.50", "0.50", "1.00", "1.00", "1.00"}));
}

}  // namespace
}  // namespace icp
