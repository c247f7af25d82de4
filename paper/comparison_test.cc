// The published-vs-measured rules on synthetic runs: the verdicts follow
// the numbers, and rows without runs name the spec that produces them.
#include "paper/comparison.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "report/report_testing.h"

namespace icp {
namespace {

using testing::InExperiment;
using testing::MakeRun;

const ComparisonRow& Row(const std::vector<ComparisonRow>& rows, const std::string& item) {
  for (const ComparisonRow& r : rows)
    if (r.item == item) return r;
  static const ComparisonRow kNone{"(no such row)", "", "", "", Verdict::kNoData, ""};
  ADD_FAILURE() << "no row " << item;
  return kNone;
}

TEST(ComparisonTest, WithinFactorIsSymmetricAndRejectsNonPositive) {
  EXPECT_TRUE(WithinFactor(1.5, 1, 1.5));
  EXPECT_TRUE(WithinFactor(1, 1.5, 1.5));
  EXPECT_FALSE(WithinFactor(1.51, 1, 1.5));
  EXPECT_FALSE(WithinFactor(0, 1, 1.5));
  EXPECT_FALSE(WithinFactor(std::numeric_limits<double>::quiet_NaN(), 1, 1.5));
}

TEST(ComparisonTest, TallyCountsEachVerdict) {
  const auto row = [](Verdict v) { return ComparisonRow{"item", "1", "2", "rule", v, ""}; };
  const VerdictTally tally = Tally({row(Verdict::kMatch), row(Verdict::kNoData),
                                    row(Verdict::kDiffers), row(Verdict::kMatch),
                                    row(Verdict::kMatch), row(Verdict::kNoData)});
  EXPECT_EQ(tally.match, 3);
  EXPECT_EQ(tally.differ, 1);
  EXPECT_EQ(tally.no_data, 2);
  EXPECT_EQ(ToString(tally), "Verdicts: 3 match, 1 differ, 2 no data");
  EXPECT_EQ(ToString(Tally({})), "Verdicts: 0 match, 0 differ, 0 no data");
}

TEST(ComparisonTest, AnEmptyStoreGivesNoDataRowsThatNameTheirSpec) {
  for (const auto& rows :
       {Thesis003Comparison({})}) {
    ASSERT_FALSE(rows.empty());
    for (const ComparisonRow& r : rows) {
      EXPECT_EQ(r.verdict, Verdict::kNoData) << r.item;
      EXPECT_FALSE(r.published.empty()) << r.item;
      EXPECT_NE(r.reason.find("specs/"), std::string::npos)
          << r.item << ": " << r.reason;
    }
  }
}

// A marina run of q-relaxed: steps that hold the truth (1) or miss it (0),
// with the assumption held (1) or not (0) on each, and a miss reason.
RunRecord MarinaRelaxed(ParamMap params, const std::vector<int>& contained,
                        const std::vector<int>& held) {
  RunRecord r = InExperiment(MakeRun("q-relaxed", std::move(params), {{"start", "known"}}, 1,
                                     std::vector<double>(contained.size(), 1e-3)),
                             "marina");
  r.spec.problem = "marina-sonar";
  for (std::size_t i = 0; i < contained.size(); ++i) {
    StepRecord& s = r.steps[i];
    s.contained = contained[i];
    s.properties.push_back({"assumption_held", std::int64_t{held[i]}});
    if (contained[i] == 0)
      s.properties.push_back(
          {"miss_reason", std::string("auto_q under-counted outliers (q=1, true 2)")});
  }
  r.metrics = ComputeMetrics(r.steps);
  return r;
}

TEST(ComparisonTest, TheMarinaGuaranteeIsJudgedOverTheStepsWhereTheAssumptionHeld) {
  const std::string item = "§6.7.2: set membership holds the truth (start known)";
  const ParamMap guaranteed = {{"auto_q", "false"}, {"q", "13"}, {"outlier_share", "0.3"}};
  // A miss where the assumption failed does not count against it; auto_q's
  // misses stand beside it.
  std::vector<RunRecord> runs = {
      MarinaRelaxed(guaranteed, {1, 0, 1}, {1, 0, 1}),
      MarinaRelaxed({{"outlier_share", "1"}}, {1, 0, 0, 1}, {1, 1, 1, 1})};
  ComparisonRow r = Row(Thesis003Comparison(runs), item);
  EXPECT_EQ(r.verdict, Verdict::kMatch) << r.measured;
  EXPECT_NE(r.measured.find("1 over 2 of 3 steps"), std::string::npos) << r.measured;
  EXPECT_NE(r.measured.find("auto_q: 0.5 overall"), std::string::npos) << r.measured;
  EXPECT_NE(r.measured.find("auto_q under-counted outliers on 2 of 2"), std::string::npos)
      << r.measured;
  // A miss where it held breaks the guarantee.
  runs[0] = MarinaRelaxed(guaranteed, {1, 0, 1}, {1, 1, 1});
  r = Row(Thesis003Comparison(runs), item);
  EXPECT_EQ(r.verdict, Verdict::kDiffers) << r.measured;
}

TEST(ComparisonTest, TheFiltersCoverageIsPooledOverItsRunsWeightedBySteps) {
  const std::string item = "§6.7: the particle filter's 95 % region holds the truth (start known)";
  auto filter = [](std::size_t steps, double c95) {
    RunRecord r = InExperiment(MakeRun("particle-filter", {}, {{"start", "known"}}, 1,
                                       std::vector<double>(steps, 1e-3)),
                               "marina");
    r.spec.problem = "marina-sonar";
    r.metrics = ComputeMetrics(r.steps);
    r.properties = {{"coverage_50", 0.5}, {"coverage_90", 0.9}, {"coverage_95", c95}};
    return r;
  };
  // (1 * 0.80 + 3 * 1.00) / 4 = 0.95: within the band although one run is not.
  std::vector<RunRecord> runs = {filter(1, 0.8), filter(3, 1.0)};
  ComparisonRow r = Row(Thesis003Comparison(runs), item);
  EXPECT_EQ(r.verdict, Verdict::kMatch) << r.measured;
  EXPECT_NE(r.measured.find("0.95 of 4 steps"), std::string::npos) << r.measured;
  runs = {filter(1, 1.0), filter(3, 1.0)};
  EXPECT_EQ(Row(Thesis003Comparison(runs), item).verdict, Verdict::kDiffers);
}

TEST(ComparisonTest, TheTableNumbersRowsAndListsReasons) {
  const TextTable t =
      ComparisonTable("T", {{"a", "1", "1", "equal", Verdict::kMatch, ""},
                            {"b", "1", "2", "equal", Verdict::kDiffers, kNotMeasured}});
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"2", "b", "1", "2", "differs"}));
  ASSERT_EQ(t.items.size(), 2u);
  EXPECT_EQ(t.items[0], "1. a: match (rule: equal)");
  EXPECT_EQ(t.items[1], std::string("2. b: differs (rule: equal); ") + kNotMeasured);
}

}  // namespace
}  // namespace icp
