#include "harness/landmark_metrics.h"

#include <gtest/gtest.h>

#include <string>
#include <cmath>

namespace icp {
namespace {

// A problem-side position function for the test: the landmark's components
// are its position box itself.
std::array<Interval, 3> Identity(const Box& b) { return {b[0], b[1], b[2]}; }

double Number(const Properties& props, const std::string& name) {
  return NumberProperty(props, name).value_or(NAN);
}

TEST(LandmarkJudgeTest, CountsHeldLandmarksAndAveragesTheScoredOnes) {
  Step step;
  step.landmark_position = &Identity;
  step.landmark_truth = {{0, {1, 1, 1}}, {1, {5, 5, 5}}, {2, {0, 0, 0}}};
  step.scored_landmarks = {0, 1};
  LandmarkJudge judge;
  Properties first;
  judge.Judge(step,
              {{0, Box{Interval(0, 2), Interval(0, 2), Interval(0, 2)}},
               {1, Box{Interval(4, 6), Interval(0, 1), Interval(4, 6)}}},  // misses y
              &first);
  EXPECT_EQ(Number(first, "landmarks"), 2);
  EXPECT_EQ(Number(first, "landmarks_contained"), 1);
  EXPECT_EQ(Number(first, "L0_held"), 1);
  EXPECT_EQ(Number(first, "L1_held"), 0);
  EXPECT_EQ(Number(first, "L1_y_hi"), 1);
  Properties second;
  judge.Judge(step,
              {{0, Box{Interval(0.5, 1.5), Interval(0.9, 1.1), Interval(0.8, 1.2)}},
               {1, Box{Interval(4.9, 5.1), Interval(4.9, 5.3), Interval(4.8, 5.2)}},
               {2, Box{Interval(-1, 1), Interval(-0.5, 0.5), Interval(-1, 1)}}},  // not scored
              &second);
  EXPECT_EQ(Number(second, "landmarks_contained"), 3);
  const Properties run = judge.RunProperties();
  EXPECT_EQ(Number(run, "landmarks_mapped"), 3);
  EXPECT_EQ(Number(run, "landmarks_scored"), 2);
  EXPECT_DOUBLE_EQ(Number(run, "landmark_consistency"), 4.0 / 5.0);
  EXPECT_NEAR(Number(run, "mpv"), (1.0 * 0.2 * 0.4 + 0.2 * 0.4 * 0.4) / 2, 1e-12);
  EXPECT_NEAR(Number(run, "mdw_x"), (1.0 + 0.2) / 2, 1e-12);
  EXPECT_NEAR(Number(run, "mdw_y"), (0.2 + 0.4) / 2, 1e-12);
  EXPECT_NEAR(Number(run, "mdw_z"), (0.4 + 0.4) / 2, 1e-12);
  EXPECT_EQ(Number(run, "L1_truth_y"), 5);
}

TEST(LandmarkJudgeTest, AScoredLandmarkLeftUnboundedMakesTheMeansInfinite) {
  Step step;
  step.landmark_position = &Identity;
  step.scored_landmarks = {0, 1};
  LandmarkJudge judge;
  Properties props;
  judge.Judge(step, {{0, Box{Interval(0, 1), Interval(0, kInf), Interval(0, 1)}}}, &props);
  const Properties run = judge.RunProperties();
  EXPECT_EQ(Number(run, "mdw_x"), kInf);  // landmark 1 never reported
  EXPECT_EQ(Number(run, "mpv"), kInf);
  EXPECT_EQ(Number(run, "landmarks_mapped"), 1);
}

TEST(LandmarkJudgeTest, NothingWithoutLandmarks) {
  LandmarkJudge judge;
  Properties props;
  judge.Judge(Step(), {}, &props);
  EXPECT_TRUE(props.empty());
  EXPECT_TRUE(judge.RunProperties().empty());
}

}  // namespace
}  // namespace icp
