#include "harness/guarantee.h"

#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "harness/runner.h"

namespace icp {
namespace {

// A relaxed solver's step: its q, q_bound and tracked, the truth's outliers
// and whether the estimate held the truth.
StepRecord RelaxedStep(int step, int q, int q_bound, bool tracked, int true_outliers,
                       int contained) {
  StepRecord s;
  s.step = step;
  s.contained = contained;
  s.properties = {{"q", std::int64_t{q}},
                  {"q_bound", std::int64_t{q_bound}},
                  {"tracked", std::int64_t{tracked ? 1 : 0}},
                  {"true_outliers", std::int64_t{true_outliers}}};
  return s;
}

std::optional<std::int64_t> Held(const StepRecord& s) {
  return IntProperty(s.properties, "assumption_held");
}

std::string Reason(const StepRecord& s) {
  for (const Property& p : s.properties)
    if (p.name == "miss_reason") return std::get<std::string>(p.value);
  return "";
}

TEST(GuaranteeTest, AFilterHoldsTheAssumptionOnlyUntilItIsViolatedThenUntilARestart) {
  GuaranteeJudge judge;
  std::vector<StepRecord> steps = {
      RelaxedStep(0, 3, 3, false, 2, 1),  // a start: held
      RelaxedStep(1, 3, 3, true, 3, 1),   // tracked, 3 <= 3: held
      RelaxedStep(2, 3, 3, true, 4, 1),   // violated here
      RelaxedStep(3, 3, 3, true, 1, 1),   // tracked since: still not held
      RelaxedStep(4, 3, 3, false, 1, 1),  // restart: held again
      RelaxedStep(5, 3, 3, true, 0, 1),
  };
  const int expected[] = {1, 1, 0, 0, 1, 1};
  for (std::size_t i = 0; i < steps.size(); ++i) {
    judge.Judge(&steps[i]);
    EXPECT_EQ(Held(steps[i]), expected[i]) << i;
  }
}

TEST(GuaranteeTest, WithoutTheTruthOrAnAssumptionNothingIsJudged) {
  GuaranteeJudge judge;
  StepRecord unknown = RelaxedStep(0, 3, 3, false, 2, -1);
  judge.Judge(&unknown);
  EXPECT_FALSE(Held(unknown));
  EXPECT_TRUE(judge.RunProperties().empty());  // no loss to count without a truth
  StepRecord filter;  // a particle filter's step: no q_bound
  filter.contained = 0;
  judge.Judge(&filter);
  EXPECT_FALSE(Held(filter));
  EXPECT_EQ(Reason(filter), "");
}

TEST(GuaranteeTest, MissReasonsNameTheCauseAndALossCarriesItsFirstReason) {
  GuaranteeJudge judge;
  std::vector<StepRecord> steps = {
      RelaxedStep(0, 2, 13, false, 2, 1),
      RelaxedStep(1, 9, 13, true, 10, 0),    // auto_q took fewer than the truth
      RelaxedStep(2, 10, 13, true, 10, 0),   // carries step 1's loss
      RelaxedStep(3, 13, 13, false, 15, 0),  // violated
      RelaxedStep(4, 13, 13, false, 2, 0),   // held, q enough: the episode's reason
  };
  for (StepRecord& s : steps) judge.Judge(&s);
  EXPECT_EQ(Reason(steps[0]), "");
  EXPECT_EQ(Reason(steps[1]), "auto_q under-counted outliers (q=9, true 10)");
  EXPECT_EQ(Reason(steps[2]), "auto_q under-counted outliers (since step 1: q=9, true 10)");
  EXPECT_EQ(Reason(steps[3]), "assumption violated (15 true outliers > q_bound 13)");
  // Steps 1 to 4 are one loss: step 4 explains nothing itself.
  EXPECT_EQ(Reason(steps[4]), "auto_q under-counted outliers (since step 1: q=9, true 10)");
  StepRecord fresh = RelaxedStep(0, 13, 13, false, 2, 0);
  GuaranteeJudge other;
  other.Judge(&fresh);
  EXPECT_EQ(MissCategory(Reason(fresh)), "unexplained");
}

TEST(GuaranteeTest, CountsLossEpisodesAndTheStepsToReacquire) {
  LossEpisodes e;
  for (int c : {1, 0, 0, 1, -1, 1, 0, 1, 0, 0, 0}) e.Add(c);
  EXPECT_EQ(e.episodes(), 3);
  EXPECT_EQ(e.judged(), 10);
  EXPECT_EQ(e.reacquire_steps(), (std::vector<double>{2, 1}));  // the last has not ended
  EXPECT_TRUE(e.lost());
  // The same through the judge's run properties.
  GuaranteeJudge judge;
  int i = 0;
  for (int c : {1, 0, 0, 1, 0, 1}) {
    StepRecord s = RelaxedStep(i++, 3, 3, true, 0, c);
    judge.Judge(&s);
  }
  const Properties run = judge.RunProperties();
  EXPECT_EQ(IntProperty(run, "loss_episodes"), 2);
  EXPECT_EQ(NumberProperty(run, "reacquire_steps_median"), 1.5);
}

TEST(GuaranteeTest, RunRestartsReadsTheSolversOrTheFiltersCount) {
  RunRecord relaxed, filter, other;
  relaxed.properties = {{"resets", std::int64_t{4}}};
  filter.properties = {{"reinitialisations", std::int64_t{2}}};
  EXPECT_EQ(RunRestarts(relaxed), 4);
  EXPECT_EQ(RunRestarts(filter), 2);
  EXPECT_FALSE(RunRestarts(other));
}

TEST(MarinaGuaranteeTest, TheGuaranteedConfigurationHoldsTheTruthWhereverItsAssumptionHeld) {
  // 150 steps of the drive; the assumption of at most max(8, floor(0.2 m))
  // wrong returns fails on some steps (and, for the filter, from then on).
  for (std::uint64_t seed : {1, 2}) {
    const RunRecord r = ExecuteRun(RunSpec{"q-relaxed",
                                           {{"mode", "pave"},
                                            {"epsilon", "2"},
                                            {"auto_q", "false"},
                                            {"q", "8"},
                                            {"outlier_share", "0.2"}},
                                           "marina-sonar",
                                           {{"steps", "150"}},
                                           seed,
                                           0});
    ASSERT_EQ(r.status, RunStatus::kOk) << r.reason;
    int held = 0, violated = 0;
    for (const StepRecord& s : r.steps) {
      const std::optional<double> h = NumberProperty(s.properties, "assumption_held");
      ASSERT_TRUE(h) << s.step;
      if (*h == 1) {
        ++held;
        EXPECT_EQ(s.contained, 1) << "seed " << seed << ", step " << s.step;
      } else {
        ++violated;
      }
    }
    EXPECT_GT(held, 100) << seed;
    EXPECT_GT(violated, 0) << seed;
    EXPECT_TRUE(NumberProperty(r.properties, "loss_episodes")) << seed;
  }
}

}  // namespace
}  // namespace icp
