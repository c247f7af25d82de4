// The published-vs-measured rules on synthetic runs: the verdicts follow
// the numbers, and rows without runs name the spec that produces them.
#include "paper/comparison.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "experiments/paper000/paper000.h"
#include "experiments/paper004/paper004.h"
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

// A run whose every step has the given x-y area.
RunRecord WithArea(RunRecord run, double area) {
  for (StepRecord& s : run.steps) s.area = area;
  run.metrics = ComputeMetrics(run.steps);
  return run;
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
       {Paper000Comparison({}), Thesis003Comparison({}), Paper004Comparison({})}) {
    ASSERT_FALSE(rows.empty());
    for (const ComparisonRow& r : rows) {
      EXPECT_EQ(r.verdict, Verdict::kNoData) << r.item;
      EXPECT_FALSE(r.published.empty()) << r.item;
      EXPECT_NE(r.reason.find("specs/"), std::string::npos)
          << r.item << ": " << r.reason;
    }
  }
  const std::vector<ComparisonRow> rows = Paper004Comparison({});  // Row refers into it
  const ComparisonRow& post = Row(rows, "§4.2, Fig. 13: post-localization stays consistent");
  EXPECT_NE(post.reason.find("specs/default.yaml (experiment window)"), std::string::npos) << post.reason;
}

TEST(ComparisonTest, Table1RatiosToHc4DecideTheVerdicts) {
  auto t1 = [](RunRecord r) { return InExperiment(std::move(r), kPaper000Table1); };
  std::vector<RunRecord> runs = {
      t1(MakeRun("hc4", {}, {}, 1, {0.4e-3})), t1(MakeRun("bc3", {}, {}, 1, {0.8e-3})),
      t1(MakeRun("bc4", {}, {}, 1, {0.45e-3})), t1(MakeRun("3b-bc4", {}, {}, 1, {1.2}))};
  std::vector<ComparisonRow> rows = Paper000Comparison(runs);
  EXPECT_EQ(Row(rows, "Table 1: BC3 / HC4").measured, "2");
  EXPECT_EQ(Row(rows, "Table 1: BC3 / HC4").verdict, Verdict::kMatch);
  EXPECT_EQ(Row(rows, "Table 1: 3B-BC4 / HC4").verdict, Verdict::kMatch);  // 3000 vs 2692
  EXPECT_EQ(Row(rows, "Table 1: algorithms by time").verdict, Verdict::kMatch);
  EXPECT_EQ(Row(rows, "Table 1: algorithms by time").measured, "HC4 < BC4 < BC3 < 3B-BC4");
  // 0.4 ms against the published 0.52: within the factor.
  EXPECT_EQ(Row(rows, "Table 1: HC4, ms per CSP").verdict, Verdict::kMatch);
  EXPECT_EQ(Row(rows, "Fig. 3: every box holds the truth").verdict, Verdict::kMatch);
  EXPECT_EQ(Row(rows, "Fig. 4: HC4, BC3 and BC4 give similar areas").verdict, Verdict::kMatch);
  // Same areas: 3B-BC4 is not tighter.
  EXPECT_EQ(Row(rows, "Fig. 4: 3B-BC4 slightly tighter than the others").verdict,
            Verdict::kDiffers);

  runs[1] = t1(MakeRun("bc3", {}, {}, 1, {20e-3}));  // 50 x HC4
  runs[0] = t1(MakeRun("hc4", {}, {}, 1, {0.02e-3}));
  rows = Paper000Comparison(runs);
  EXPECT_EQ(Row(rows, "Table 1: BC3 / HC4").verdict, Verdict::kDiffers);
  EXPECT_EQ(Row(rows, "Table 1: BC3 / HC4").reason, kNotMeasured);
  // With the stored work counters the reason is measured: per CSP, from them.
  runs[0].properties = {{"revise_calls", std::int64_t{240}}};
  runs[1].properties = {{"revise_calls", std::int64_t{280}},
                        {"newton_steps", std::int64_t{160}},
                        {"bisections", std::int64_t{40}}};
  rows = Paper000Comparison(runs);
  const std::string reason = Row(rows, "Table 1: BC3 / HC4").reason;
  EXPECT_NE(reason.find("BC3 revised 280 constraints (HC4: 240)"), std::string::npos) << reason;
  EXPECT_NE(reason.find("160 Newton steps and 40 bisections"), std::string::npos) << reason;
  EXPECT_NE(reason.find("HC4 runs 26x faster than published, BC3 0.051x"), std::string::npos)
      << reason;
  runs[3].properties = {{"inner_calls", std::int64_t{300}}, {"revise_calls", std::int64_t{24000}}};
  rows = Paper000Comparison(runs);
  const std::string three_b = Row(rows, "Table 1: 3B-BC4 / HC4").reason;  // 60000x HC4
  EXPECT_NE(three_b.find("ran 300 inner contractions (shaving trials) with 24000 revisions, "
                         "100x HC4's 240, and a revision cost 600x one of HC4's"),
            std::string::npos)
      << three_b;
  const ComparisonRow& absolute = Row(rows, "Table 1: HC4, ms per CSP");
  EXPECT_EQ(absolute.verdict, Verdict::kDiffers);
  EXPECT_NE(absolute.reason.find("by construction"), std::string::npos);
}

TEST(ComparisonTest, Fig2FlatCarriedWindowsCiteTheMemorylessRow) {
  auto window = [](const std::string& carry, double w, double area) {
    ParamMap params;
    if (!carry.empty()) params["carry"] = carry;
    return InExperiment(
        WithArea(MakeRun("hc4", params, {{"w", FormatNumber(w)}}, 1, {1e-5 * w, 1e-5 * w}), area),
        kPaper000Window);
  };
  const std::vector<RunRecord> runs = {window("", 1, 16),        window("", 20, 16),
                                       window("", 50, 16),       window("none", 1, 21.3),
                                       window("none", 20, 17.8), window("none", 50, 16.8)};
  const std::vector<ComparisonRow> rows = Paper000Comparison(runs);
  const ComparisonRow& memoryless = Row(rows, "Fig. 2: area, w = 1 to 20, hc4 {carry=none}");
  EXPECT_EQ(memoryless.verdict, Verdict::kMatch) << memoryless.measured;
  const ComparisonRow& carried = Row(rows, "Fig. 2: area, w = 1 to 20, hc4");
  EXPECT_EQ(carried.verdict, Verdict::kDiffers);
  EXPECT_EQ(carried.measured, "0 % (16 to 16 m²)");
  // The reason cites the memoryless row by its number.
  std::size_t number = 0;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (&rows[i] == &memoryless) number = i + 1;
  EXPECT_NE(carried.reason.find("carry=none, row " + std::to_string(number) + ")"),
            std::string::npos)
      << carried.reason;
  EXPECT_EQ(Row(rows, "Fig. 2: area, w = 20 to 50, hc4 {carry=none}").verdict, Verdict::kMatch);
  EXPECT_EQ(Row(rows, "Fig. 2: time per CSP grows linearly with w").verdict, Verdict::kMatch);
}

// Carried windows read as the mean area over the window's states (the steps'
// window_mean_area): 10 -> 8.5 m² is paper 000's fall within 5 points.
TEST(ComparisonTest, Fig2AsTheWindowsMeanArea) {
  auto window = [](double w, double window_area) {
    RunRecord r = WithArea(MakeRun("hc4", {}, {{"w", FormatNumber(w)}}, 1, {1e-5, 1e-5}), 16);
    for (StepRecord& s : r.steps) s.properties.push_back({"window_mean_area", window_area});
    return InExperiment(std::move(r), kPaper000Window);
  };
  const std::vector<ComparisonRow> rows =
      Paper000Comparison({window(1, 10), window(20, 8.5), window(50, 8.4)});
  const ComparisonRow& fall = Row(rows, "Fig. 2 as the mean area over the window's states, w = 1 to 20, hc4");
  EXPECT_EQ(fall.verdict, Verdict::kMatch) << fall.measured;
  EXPECT_EQ(fall.measured, "-15 % (10 to 8.5 m²)");
  EXPECT_EQ(Row(rows, "Fig. 2 as the mean area over the window's states, w = 20 to 50, hc4").verdict,
            Verdict::kMatch);
}

TEST(ComparisonTest, Paper004ConsistencyFollowsTheSteps) {
  std::vector<RunRecord> runs = {MakeRun("hc4", {}, {}, 1, {1e-5, 1e-5})};
  const std::string item = "eq. 31: every ICP box holds the truth";
  EXPECT_EQ(Row(Paper004Comparison(runs), item).verdict, Verdict::kMatch);
  runs[0].steps[1].contained = 0;
  runs[0].metrics = ComputeMetrics(runs[0].steps);
  const ComparisonRow r = Row(Paper004Comparison(runs), item);
  EXPECT_EQ(r.verdict, Verdict::kDiffers);
  EXPECT_NE(r.measured.find("lowest 0.5"), std::string::npos) << r.measured;
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
