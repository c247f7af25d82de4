#include "problems/visual_landmarks/visual_drive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace icp {
namespace {

// Every interval holds the truth, the truth follows eq. 11 with the true
// delta s and delta theta, and exactly the landmarks in the image are seen,
// each at a pixel box holding its true projection.
void ExpectMeasurementsHoldTheTruth(const VisualDriveParams& p, const VisualDrive& drive) {
  ASSERT_EQ(static_cast<int>(drive.poses.size()), p.steps);
  ASSERT_EQ(drive.steps.size(), drive.poses.size());
  for (int k = 0; k < p.steps; ++k) {
    const auto& pose = drive.poses[k];
    const VisualDriveStep& step = drive.steps[k];
    EXPECT_TRUE(step.gps[0].Contains(pose[0]) && step.gps[1].Contains(pose[1])) << "step " << k;
    if (k > 0) {
      const auto& before = drive.poses[k - 1];
      const double ds = p.speed * p.dt, dtheta = pose[2] - before[2];
      EXPECT_TRUE(step.ds.Contains(ds)) << "step " << k;
      EXPECT_TRUE(step.dtheta.Contains(dtheta)) << "step " << k;
      EXPECT_NEAR(pose[0], before[0] + ds * std::cos(before[2] + dtheta / 2), 1e-12);
      EXPECT_NEAR(pose[1], before[1] + ds * std::sin(before[2] + dtheta / 2), 1e-12);
    }
    std::size_t next = 0;
    for (int n = 0; n < static_cast<int>(drive.landmarks.size()); ++n) {
      const auto pixel = Project(pose, drive.landmarks[n], p.camera);
      if (!pixel) continue;
      ASSERT_LT(next, step.sightings.size()) << "step " << k << ": landmark " << n << " not seen";
      const LandmarkSighting& seen = step.sightings[next++];
      EXPECT_EQ(seen.landmark, n);
      EXPECT_TRUE(seen.u.Contains(pixel->u) && seen.v.Contains(pixel->v)) << "step " << k;
      EXPECT_NEAR(seen.u.Width(), 2 * p.pixel_error, 1e-9);
    }
    EXPECT_EQ(next, step.sightings.size()) << "step " << k << ": a landmark out of view seen";
  }
}

TEST(VisualDriveTest, StraightRouteIsThePapersScene) {
  const VisualDriveParams p;
  const VisualDrive drive = SimulateVisualDrive(p, 1);
  ExpectMeasurementsHoldTheTruth(p, drive);
  ASSERT_EQ(drive.landmarks.size(), 5u);
  EXPECT_NEAR(drive.poses.back()[0], 9.9, 1e-9);  // 99 steps of 0.1 m
  EXPECT_EQ(drive.poses.back()[1], 0);
  // Every landmark is seen from the start and for most of the drive.
  std::vector<int> seen(5, 0);
  for (const auto& step : drive.steps)
    for (const auto& sighting : step.sightings) ++seen[sighting.landmark];
  for (int n = 0; n < 5; ++n) {
    EXPECT_GE(seen[n], 50) << "landmark " << n;
    EXPECT_EQ(drive.steps[0].sightings[n].landmark, n);
  }
}

TEST(VisualDriveTest, LoopRouteClosesAndItsLandmarksLineIt) {
  VisualDriveParams p;
  p.route = "loop";
  p.speed = 1;
  p.steps = 184;  // one lap of 120 + 20 pi m, and a little more
  p.landmarks = 100;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const VisualDrive drive = SimulateVisualDrive(p, seed);
    ExpectMeasurementsHoldTheTruth(p, drive);
    const auto& end = drive.poses.back();
    EXPECT_LT(std::hypot(end[0], end[1]), 1.5);
    EXPECT_NEAR(end[2], 2 * std::numbers::pi, 0.1);
    ASSERT_EQ(drive.landmarks.size(), 100u);
    for (const auto& landmark : drive.landmarks) {
      double nearest = INFINITY;
      for (const auto& pose : drive.poses)
        nearest = std::min(nearest, std::hypot(landmark[0] - pose[0], landmark[1] - pose[1]));
      EXPECT_GE(nearest, 1.5);
      EXPECT_LE(nearest, 8.1);  // 8 m from the curve, poses 1 m apart
    }
  }
  // The map is the route's (layout_seed), not the drive's: a teach drive
  // and a repeat drive of other seeds, speeds and lengths share it.
  VisualDriveParams slow = p;
  slow.speed = 0.5;
  slow.steps = 10;
  EXPECT_EQ(SimulateVisualDrive(p, 7).landmarks, SimulateVisualDrive(slow, 8).landmarks);
  slow.layout_seed = 2;
  EXPECT_NE(SimulateVisualDrive(p, 7).landmarks, SimulateVisualDrive(slow, 8).landmarks);
}

TEST(VisualDriveTest, MoreThanFiveLandmarksOnTheStraightRouteKeepThePapersFive) {
  VisualDriveParams p;
  p.landmarks = 12;
  const VisualDrive drive = SimulateVisualDrive(p, 1);
  ASSERT_EQ(drive.landmarks.size(), 12u);
  EXPECT_EQ(drive.landmarks[4], (std::array<double, 3>{30, 0.2, 1.6}));
  ExpectMeasurementsHoldTheTruth(p, drive);
  p.landmarks = 3;
  EXPECT_EQ(SimulateVisualDrive(p, 1).landmarks.size(), 3u);
}

TEST(VisualDriveTest, BadParametersAreRejected) {
  VisualDriveParams p;
  p.route = "figure-eight";
  EXPECT_THROW(SimulateVisualDrive(p, 1), std::invalid_argument);
  p.route = "straight";
  p.steps = 0;
  EXPECT_THROW(SimulateVisualDrive(p, 1), std::invalid_argument);
  p.steps = 10;
  p.landmarks = 0;
  EXPECT_THROW(SimulateVisualDrive(p, 1), std::invalid_argument);
}

}  // namespace
}  // namespace icp
