// The tables of the suite's own car-track experiments (start, outage) on
// synthetic runs whose widths and areas are known.
#include "experiments/paper000/own_experiments.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "report/report_testing.h"

namespace icp {
namespace {

using testing::InExperiment;
using testing::MakeRun;

// A start run whose heading width at step k is width(k).
RunRecord StartRun(const std::string& algorithm, int seed, double (*width)(int)) {
  RunRecord r = MakeRun(algorithm, {}, {{"steps", "30"}}, seed, std::vector<double>(30, 1e-4));
  for (StepRecord& s : r.steps) s.vars[2] = {"theta", -width(s.step) / 2, width(s.step) / 2, 0};
  return InExperiment(std::move(r), "start");
}

const std::vector<std::string>& Row(const TextTable& t, const std::string& label) {
  for (const auto& row : t.rows)
    if (row[0] == label) return row;
  static const std::vector<std::string> kNone(7, "(none)");
  ADD_FAILURE() << "no row " << label << " in " << t.title;
  return kNone;
}

TEST(Paper000OwnExperimentsTest, TheHeadingWidthIsReadAtTheFirstThe20thAndTheLastStep) {
  std::vector<RunRecord> runs;
  for (int seed = 1; seed <= 3; ++seed) {
    runs.push_back(StartRun("hc4", seed, [](int k) { return k == 0 ? 6.0 : 1.0; }));
    runs.push_back(StartRun("3b-bc4", seed, [](int k) { return k < 19 ? 6.0 : 0.25; }));
  }
  runs.back().steps[10].contained = 0;
  runs.back().metrics = ComputeMetrics(runs.back().steps);
  const TextTable start = Paper000OwnExperimentTables(runs)[0];
  ASSERT_EQ(start.rows.size(), 2u);
  EXPECT_EQ(Row(start, "HC4"),
            (std::vector<std::string>{"HC4", "steps=30", "3", "6", "1", "1", "1"}));
  // The median over three seeds: 1, 1 and 29 of 30 hold the truth.
  EXPECT_EQ(Row(start, "3B-BC4"),
            (std::vector<std::string>{"3B-BC4", "steps=30", "3", "6", "0.25", "0.25", "1"}));
}

TEST(Paper000OwnExperimentsTest, TheOutageIsComparedWithTheStepsBeforeAndAfterIt) {
  std::vector<RunRecord> runs;
  for (int seed = 1; seed <= 3; ++seed) {
    RunRecord r = MakeRun("hc4", {}, {{"outage_start", "10"}, {"outage_length", "5"}}, seed,
                          std::vector<double>(25, 1e-4));
    for (StepRecord& s : r.steps) {
      s.area = s.step < 10 ? 4 : s.step < 15 ? 100.0 * seed : 2;
      if (s.step == 12) s.contained = 0;
    }
    r.metrics = ComputeMetrics(r.steps);
    runs.push_back(InExperiment(std::move(r), "outage"));
  }
  const std::vector<TextTable> tables = Paper000OwnExperimentTables(runs);
  EXPECT_TRUE(tables[0].rows.empty());
  EXPECT_NE(tables[0].notes.back().find("specs/default.yaml"), std::string::npos);
  ASSERT_EQ(tables[1].rows.size(), 1u);
  // Before: steps 5-9 (4 m²); during: 10-14 (100, 200, 300 m² by seed, 4 of
  // 5 steps hold the truth); after: 15-19 (2 m²).
  EXPECT_EQ(tables[1].rows[0], (std::vector<std::string>{"HC4", "outage_length=5,outage_start=10",
                                                         "3", "4", "200", "2", "0.8"}));
}

}  // namespace
}  // namespace icp
