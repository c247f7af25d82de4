#include "harness/association_metrics.h"

#include <gtest/gtest.h>

namespace icp {
namespace {

Step StepWith(std::vector<int> truth) {
  Step step;
  LandmarkObservationView view;
  view.observations.resize(truth.size());
  step.views.landmark_observations = std::move(view);
  step.observation_truth = std::move(truth);
  return step;
}

std::int64_t Int(const Properties& p, const char* name) { return IntProperty(p, name).value(); }

std::optional<std::vector<int>> Given(std::vector<int> associations) { return associations; }

// An estimator that associates is judged at a step without returns too: its
// guarantee still holds there (or still does not).
TEST(AssociationJudgeTest, AStepWithoutReturnsIsJudgedForAnAssociatingEstimator) {
  AssociationJudge judge;
  Properties out;
  judge.Judge(StepWith({}), Given({}), 1, &out);
  EXPECT_EQ(Int(out, "associations_right"), 0);
  EXPECT_EQ(Int(out, "assumption_held"), 1);
}

TEST(AssociationJudgeTest, CountsRightWrongAndMissedAndWhenTheAssumptionBroke) {
  AssociationJudge judge;
  Properties first, second, third;
  // Returns of landmarks 4 and 7 and a spurious one: 4 right, 7 missed,
  // the spurious one rejected.
  judge.Judge(StepWith({4, 7, -1}), Given({4, -1, -1}), 1, &first);
  EXPECT_EQ(Int(first, "associations_right"), 1);
  EXPECT_EQ(Int(first, "associations_wrong"), 0);
  EXPECT_EQ(Int(first, "associations_missed"), 1);
  EXPECT_EQ(Int(first, "assumption_held"), 1);
  // 4 given 5 (wrong), the spurious one given 7 (wrong); the truth lost.
  judge.Judge(StepWith({4, -1}), Given({5, 7}), 0, &second);
  EXPECT_EQ(Int(second, "associations_wrong"), 2);
  EXPECT_EQ(Int(second, "assumption_held"), 0);
  // All right again, but the run's guarantee stays broken.
  judge.Judge(StepWith({4}), Given({4}), 1, &third);
  EXPECT_EQ(Int(third, "assumption_held"), 0);
  const Properties run = judge.RunProperties();
  EXPECT_EQ(Int(run, "associations_right"), 2);
  EXPECT_EQ(Int(run, "associations_wrong"), 2);
  EXPECT_EQ(Int(run, "associations_missed"), 1);
  EXPECT_EQ(Int(run, "wrong_association_steps"), 1);
  EXPECT_EQ(Int(run, "wrong_association_losses"), 1);
}

TEST(AssociationJudgeTest, NothingForEstimatorsThatDoNotAssociateOrStepsWithoutTruth) {
  AssociationJudge judge;
  Properties out;
  judge.Judge(StepWith({1, 2}), std::nullopt, 1, &out);  // a relaxed solver on the same step
  judge.Judge(StepWith({}), std::nullopt, 1, &out);      // ... at a step without returns
  Step unknown = StepWith({});
  unknown.views.landmark_observations->observations.resize(2);
  judge.Judge(unknown, Given({1, 2}), -1, &out);  // a logged drive without identities
  judge.Judge(Step(), Given({}), 1, &out);        // another problem
  EXPECT_TRUE(out.empty());
  EXPECT_TRUE(judge.RunProperties().empty());
}

TEST(AssociationJudgeTest, AssociationsNotOnePerReturnAreRefused) {
  AssociationJudge judge;
  Properties out;
  EXPECT_THROW(judge.Judge(StepWith({1, 2}), Given({1}), 1, &out), std::invalid_argument);
}

}  // namespace
}  // namespace icp
