// Thesis 003's claims file (experiments/thesis003/claims.yaml) on synthetic
// runs: the guarantee judged only where its assumption held, the auto_q
// misses counted by their reason, the filter's coverage pooled over steps,
// and the figures recomputed from their runs' problems, where every
// difference carries a measured reason.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "paper/claims.h"
#include "paper/claims_testing.h"
#include "report/report_testing.h"

namespace icp {
namespace {

using testing::ClaimRow;
using testing::InExperiment;
using testing::MakeRun;

const ClaimsFile& Thesis003() { return ClaimsOf("thesis003"); }

const ParamMap kGuaranteed = {{"mode", "pave"}, {"epsilon", "2"}, {"auto_q", "false"},
                              {"q", "13"},      {"outlier_share", "0.3"}};
const ParamMap kAutoQ = {{"mode", "pave"}, {"epsilon", "2"}, {"outlier_share", "0.3"}};

// A marina-drive run from `start`: steps that hold the truth (1) or miss it
// (0), with the assumption held (1) or not (0) on each, and a miss reason.
RunRecord Marina(const std::string& algorithm, ParamMap params, const std::string& start,
                 const std::vector<int>& contained, const std::vector<int>& held = {},
                 std::uint64_t seed = 1) {
  RunRecord r = InExperiment(MakeRun(algorithm, std::move(params), {{"start", start}}, seed,
                                     std::vector<double>(contained.size(), 1e-3)),
                             "marina-drive");
  r.spec.problem = "marina-sonar";
  for (std::size_t i = 0; i < contained.size(); ++i) {
    StepRecord& s = r.steps[i];
    s.contained = contained[i];
    if (!held.empty()) s.properties.push_back({"assumption_held", std::int64_t{held[i]}});
    if (contained[i] == 0)
      s.properties.push_back(
          {"miss_reason", std::string("auto_q under-counted outliers (q=1, true 2)")});
  }
  r.metrics = ComputeMetrics(r.steps);
  return r;
}

TEST(Thesis003ClaimsTest, AnEmptyStoreGivesNoDataRowsThatNameTheirSpec) {
  const std::vector<ComparisonRow> rows = EvaluateClaims(Thesis003(), {});
  ASSERT_EQ(rows.size(), Thesis003().claims.size());
  for (const ComparisonRow& r : rows) {
    EXPECT_EQ(r.verdict, Verdict::kNoData) << r.id;
    const bool robust = r.id.rfind("ch6-robust", 0) == 0;
    EXPECT_NE(r.reason.find(robust ? "specs/marina.yaml" : "specs/default.yaml"),
              std::string::npos)
        << r.id << ": " << r.reason;
  }
}

TEST(Thesis003ClaimsTest, TheGuaranteeIsJudgedOnEveryStepWhereItsAssumptionHeld) {
  // A miss where the assumption failed does not count against it.
  std::vector<RunRecord> runs = {Marina("q-relaxed", kGuaranteed, "known", {1, 0, 1}, {1, 0, 1}),
                                 Marina("q-relaxed", kGuaranteed, "area", {1, 1}, {1, 1})};
  ComparisonRow r = ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-guarantee");
  EXPECT_EQ(r.verdict, Verdict::kMatch) << r.measured;
  EXPECT_NE(r.measured.find("over the 4 of 5 steps whose assumption held (2 configurations"),
            std::string::npos)
      << r.measured;
  // One miss where it held, on one step of one start, breaks it.
  runs[1] = Marina("q-relaxed", kGuaranteed, "area", {1, 0}, {1, 1});
  r = ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-guarantee");
  EXPECT_EQ(r.verdict, Verdict::kDiffers) << r.measured;
  EXPECT_NE(r.reason.find("unsound"), std::string::npos) << r.reason;
  // Runs that record no assumption cannot be judged.
  runs = {Marina("q-relaxed", kGuaranteed, "known", {1, 1})};
  r = ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-guarantee");
  EXPECT_EQ(r.verdict, Verdict::kNoData);
  EXPECT_NE(r.reason.find("assumption_held"), std::string::npos) << r.reason;
}

TEST(Thesis003ClaimsTest, AutoQIsJudgedOnItsPooledStepsAndItsMissesCountedByReason) {
  // Seed 1 holds the truth on 3 of 4 steps, seed 2 on all 4: 7 of 8 pooled.
  const std::vector<RunRecord> runs = {Marina("q-relaxed", kAutoQ, "known", {1, 0, 1, 1}),
                                       Marina("q-relaxed", kAutoQ, "known", {1, 1, 1, 1}, {}, 2)};
  const ComparisonRow r = ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-auto-q");
  EXPECT_EQ(r.verdict, Verdict::kDiffers) << r.measured;
  EXPECT_NE(r.measured.find("lowest 0.875"), std::string::npos) << r.measured;
  EXPECT_NE(r.reason.find("of the 1 steps that missed the truth, 1: auto_q under-counted"),
            std::string::npos)
      << r.reason;
}

TEST(Thesis003ClaimsTest, TheFiltersCoverageIsPooledOverItsRunsWeightedBySteps) {
  auto filter = [](std::size_t steps, double c95, std::uint64_t seed) {
    RunRecord r = Marina("particle-filter", {{"inject", "0"}}, "known",
                         std::vector<int>(steps, 1), {}, seed);
    r.properties = {{"coverage_50", 0.5}, {"coverage_90", 0.9}, {"coverage_95", c95}};
    return r;
  };
  // (1 * 0.80 + 3 * 1.00) / 4 = 0.95: within the band although one run is not.
  std::vector<RunRecord> runs = {filter(1, 0.8, 1), filter(3, 1.0, 2)};
  ComparisonRow r = ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-filter-coverage");
  EXPECT_EQ(r.verdict, Verdict::kMatch) << r.measured;
  EXPECT_NE(r.measured.find("lowest 0.95"), std::string::npos) << r.measured;
  EXPECT_EQ(ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-filter-coverage-50").verdict, Verdict::kMatch);
  runs = {filter(1, 1.0, 1), filter(3, 1.0, 2)};
  r = ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-filter-coverage");
  EXPECT_EQ(r.verdict, Verdict::kDiffers);
  EXPECT_NE(r.reason.find("95 %: 1;"), std::string::npos) << r.reason;
  // The 50 % box judged on its own level: 0.7 is 20 points over.
  for (RunRecord& run : runs) run.properties[0].value = 0.7;
  EXPECT_EQ(ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-filter-coverage-50").verdict, Verdict::kDiffers);
  // The car's claims read the car-filter experiment's runs only.
  EXPECT_EQ(ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-filter-coverage-car").verdict, Verdict::kNoData);
  RunRecord car = MakeRun("particle-filter", {}, {}, 1, std::vector<double>(4, 1e-3));
  car.spec.problem = "car-track";
  car.properties = {{"coverage_50", 0.55}, {"coverage_90", 0.9}, {"coverage_95", 0.93}};
  runs = {InExperiment(std::move(car), "car-filter")};
  EXPECT_EQ(ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-filter-coverage-car").verdict, Verdict::kMatch);
  EXPECT_EQ(ClaimRow(EvaluateClaims(Thesis003(), runs), "ch6-filter-coverage-car-50").verdict, Verdict::kMatch);
}

// The figure runs of the default spec, recomputed from their problems: each
// row is measured, and every difference has a measured reason.
TEST(Thesis003ClaimsTest, TheFiguresAreRecomputedAndEveryDifferenceHasAReason) {
  std::vector<RunRecord> runs;
  auto figure = [&](const std::string& algorithm, ParamMap params, const std::string& problem,
                    ParamMap problem_params, const std::string& experiment, int seed = 1) {
    RunRecord r = MakeRun(algorithm, std::move(params), std::move(problem_params), seed, {1e-3});
    r.spec.problem = problem;
    runs.push_back(InExperiment(std::move(r), experiment));
  };
  // Fig. 5.2 over two seeds (two sets of lines), judged by their median.
  const ParamMap lines = {{"lines", "20"}, {"outliers", "7"}};
  for (int seed : {1, 2}) {
    for (const char* p : {"1", "30"})
      figure("polynomial", {{"p", p}}, "line-intersection", lines, "fig5_2", seed);
    figure("polynomial", {}, "line-intersection", lines, "fig5_2", seed);  // p = 10, the default
    figure("polynomial", {{"approximation", "c1"}, {"p", "30"}}, "line-intersection", lines,
           "fig5_2", seed);
  }
  figure("accumulator", {}, "beacon-ranges", {{"scenario", "two-robots"}}, "fig5_5");
  const std::vector<ComparisonRow> rows = EvaluateClaims(Thesis003(), runs);
  for (const char* id : {"fig5_2-white-converges", "fig5_2-peak", "fig5_2-c1-c3",
                         "fig5_5-maxima", "fig5_6-several", "fig5_7-one", "fig5_7-localizes"}) {
    const ComparisonRow& r = ClaimRow(rows, id);
    EXPECT_NE(r.verdict, Verdict::kNoData) << id << ": " << r.reason;
    if (r.verdict == Verdict::kDiffers) {
      EXPECT_NE(r.reason, kNotMeasured) << id << ": " << r.measured;
    }
  }
  for (const char* id : {"fig5_2-white-converges", "fig5_2-peak", "fig5_2-c1-c3"})
    EXPECT_NE(ClaimRow(rows, id).measured.find("median of 2 seeds"), std::string::npos)
        << ClaimRow(rows, id).measured;
  // Fig. 5.7: the 4 correct ranges meet at the truth alone.
  EXPECT_EQ(ClaimRow(rows, "fig5_7-localizes").verdict, Verdict::kMatch)
      << ClaimRow(rows, "fig5_7-localizes").measured;
}

}  // namespace
}  // namespace icp
