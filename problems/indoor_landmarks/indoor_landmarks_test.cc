#include "problems/indoor_landmarks/indoor_landmarks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "core/polar_sighting.h"
#include "problems/registry.h"

namespace icp {
namespace {

std::vector<Step> Drive(const ParamMap& params, std::uint64_t seed) {
  return ProblemSteps("indoor-landmarks", params, seed);
}

TEST(IndoorMapTest, ShippedCorridorEndHasWallsAndEveryLandmarkType) {
  const IndoorMap map = ReadIndoorMap(ShippedCorridorMapPath());
  EXPECT_EQ(map.walls.size(), 28u);
  int count[3] = {0, 0, 0};
  for (const TypedLandmark& l : map.landmarks) ++count[l.type];
  EXPECT_EQ(count[0], 16);  // corners
  EXPECT_EQ(count[1], 12);  // edges
  EXPECT_EQ(count[2], 5);   // others
  EXPECT_EQ(map.landmarks[3].id, 3);
  const Box bounds = map.Bounds();
  EXPECT_EQ(bounds[0], Interval(0, 16.3));
  EXPECT_EQ(bounds[1], Interval(-2, 4));
}

TEST(IndoorMapTest, BadRowsAreNamedByLine) {
  auto read = [](const std::string& text) {
    std::istringstream in(text);
    return ReadIndoorMap(in, "m.csv");
  };
  EXPECT_THROW(read("x,y\n"), std::invalid_argument);
  try {
    read("# c\nkind,x1,y1,x2,y2\ncorner,1,2\ndoor,1,2\n");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("m.csv:4: kind must be wall, corner, edge or other"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(read("kind,x1,y1,x2,y2\nwall,0,0,1\n"), std::invalid_argument);
  EXPECT_THROW(read("kind,x1,y1,x2,y2\ncorner,0,nan\n"), std::invalid_argument);
  EXPECT_THROW(read("kind,x1,y1,x2,y2\nwall,0,0,1,1\n"), std::invalid_argument);  // no landmark
  // Coordinates past 1e9 m (a wall at 1e17 passed every geometric test unseen).
  try {
    read("kind,x1,y1,x2,y2\nwall,-1e17,-1e17,1e17,1e17\ncorner,1,2\n");
    ADD_FAILURE() << "accepted a wall at 1e17";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("m.csv:2: field 2 is beyond +-1e9 m"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read("kind,x1,y1,x2,y2\nwall,0,0,1,1\nedge,1,1\nother,2,2\n").landmarks[1].type, 2);
}

TEST(IndoorMapTest, WallsBlockTheLineOfSight) {
  const IndoorMap map = ReadIndoorMap(ShippedCorridorMapPath());
  EXPECT_TRUE(CrossesWall(map, 1, 1, 1, -1));     // through the corridor's wall
  EXPECT_FALSE(CrossesWall(map, 1, 1, 11, 1));    // along the corridor
  EXPECT_FALSE(CrossesWall(map, 3.45, 1, 3.45, -0.2));  // into a door's recess
  EXPECT_NEAR(DistanceToWalls(map, 1, 0.85), 0.85, 1e-12);
}

// The paper's two paths: 46 acquisitions 0.30 m apart, b starting 0.30 m to
// the left of a and turning the other way; every odometry interval holds
// the true motion and every return of a landmark its true polar
// coordinates; spurious returns are marked and only they can be outliers.
TEST(IndoorLandmarksTest, PathsAAndBReadingsHoldTheTruth) {
  for (const char* path : {"a", "b"}) {
    const std::vector<Step> steps = Drive({{"path", path}}, 5);
    ASSERT_EQ(steps.size(), 46u);
    const IndoorMap map = ReadIndoorMap(ShippedCorridorMapPath());
    int returns = 0, spurious = 0;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const Step& s = steps[k];
      const LandmarkObservationView& v = *s.views.landmark_observations;
      ASSERT_EQ(v.observations.size(), s.observation_truth.size());
      const Box here({Interval(s.truth[0]), Interval(s.truth[1]), Interval(s.truth[2])});
      if (k == 0) {
        EXPECT_FALSE(v.odometry.has_value());
        EXPECT_TRUE(v.prior.Contains(s.truth));
      } else {
        const std::vector<double>& before = steps[k - 1].truth;
        EXPECT_NEAR(std::hypot(s.truth[0] - before[0], s.truth[1] - before[1]), 0.30, 1e-9);
        const Box from({Interval(before[0]), Interval(before[1]), Interval(before[2])});
        EXPECT_TRUE(PredictPose(from, *v.odometry).Contains(s.truth)) << path << " step " << k;
      }
      for (std::size_t i = 0; i < v.observations.size(); ++i) {
        ++returns;
        const int id = s.observation_truth[i];
        EXPECT_EQ(s.views.measurement_set->outliers[i] && id >= 0, false) << "a landmark's return";
        if (id < 0) {
          ++spurious;
          continue;
        }
        const TypedLandmark& l = map.landmarks[id];
        EXPECT_EQ(v.observations[i].type, l.type);
        const auto world = SightingWorldBox(here, v.observations[i]);
        EXPECT_TRUE(world[0].Contains(l.x) && world[1].Contains(l.y)) << path << " step " << k;
        EXPECT_LE(std::hypot(l.x - s.truth[0], l.y - s.truth[1]), 6.0);
      }
    }
    EXPECT_GT(returns, 46 * 4) << path;               // several landmarks in sight at every step
    EXPECT_NEAR(spurious, 46, 8) << path;             // spurious_rate 1: one a step
  }
  const std::vector<Step> a = Drive({{"path", "a"}}, 5), b = Drive({{"path", "b"}}, 5);
  EXPECT_NEAR(b[0].truth[1] - a[0].truth[1], 0.30, 1e-12);
  EXPECT_GT(a.back().truth[2], 1.5);   // turned left, about 90 deg
  EXPECT_LT(b.back().truth[2], -1.5);  // turned right
}

TEST(IndoorLandmarksTest, NoSpuriousOrDroppedReturnsWhenTheRatesAreZero) {
  const std::vector<Step> steps = Drive({{"spurious_rate", "0"}, {"dropout_rate", "0"}}, 2);
  for (const Step& s : steps) {
    for (int id : s.observation_truth) EXPECT_GE(id, 0);
    for (bool outlier : s.views.measurement_set->outliers) EXPECT_FALSE(outlier);
  }
  // With dropouts, fewer returns from the same drive.
  std::size_t all = 0, dropped = 0;
  for (const Step& s : steps) all += s.observation_truth.size();
  for (const Step& s : Drive({{"spurious_rate", "0"}, {"dropout_rate", "0.5"}}, 2))
    dropped += s.observation_truth.size();
  EXPECT_LT(dropped, all * 0.7);
}

TEST(IndoorLandmarksTest, ANarrowFieldOfViewSeesOnlyAhead) {
  for (const Step& s : Drive({{"fov", "90"}, {"spurious_rate", "0"}}, 3))
    for (const PolarObservation& o : s.views.landmark_observations->observations)
      EXPECT_LE(std::abs(0.5 * (o.bearing.lo() + o.bearing.hi())), std::numbers::pi / 4 + 0.02);
}

TEST(IndoorLandmarksTest, TheRandomDriveKeepsClearOfTheWalls) {
  const IndoorMap map = ReadIndoorMap(ShippedCorridorMapPath());
  const std::vector<Step> steps = Drive({{"path", "random"}, {"steps", "300"}}, 11);
  ASSERT_EQ(steps.size(), 300u);
  double farthest = 0;
  for (const Step& s : steps) {
    EXPECT_GE(DistanceToWalls(map, s.truth[0], s.truth[1]), 0.4 - 1e-9);
    farthest = std::max(farthest, s.truth[0]);
  }
  EXPECT_GT(farthest, 4);  // it goes somewhere
}

// Fig. 9's premise: odometry alone, the pose box grows without bound.
TEST(IndoorLandmarksTest, DeadReckoningHoldsTheTruthAndGrows) {
  const std::vector<Step> steps = Drive({}, 1);
  Box pose = steps[0].views.landmark_observations->prior;
  double width = 0;
  for (std::size_t k = 1; k < steps.size(); ++k) {
    pose = PredictPose(pose, *steps[k].views.landmark_observations->odometry);
    EXPECT_TRUE(pose.Contains(steps[k].truth)) << k;
    const double w = pose[0].hi() - pose[0].lo();
    EXPECT_GT(w, width);
    width = w;
  }
  EXPECT_GT(width, 0.5);
}

// Whether box holds pose, its heading taken modulo 2 pi.
bool HoldsModuloTurns(const Box& box, const std::vector<double>& pose) {
  for (int turns = -4; turns <= 4; ++turns)
    if (box.Contains({pose[0], pose[1], pose[2] + 2 * std::numbers::pi * turns})) return true;
  return false;
}

// The measurement set's prediction puts the heading in the prior's frame:
// the relaxed solvers intersect the two, so an unwrapped heading would lose
// the truth once the drive has turned past pi.
TEST(IndoorLandmarksTest, PredictionsHoldTheTruthInThePriorsFrame) {
  const std::vector<Step> steps = Drive({{"path", "random"}, {"steps", "300"}}, 4);
  double turned = 0;
  for (std::size_t k = 1; k < steps.size(); ++k) {
    const MeasurementSetView& set = *steps[k].views.measurement_set;
    const std::vector<double>& before = steps[k - 1].truth;
    const Box next = set.predict(Box({Interval(before[0]), Interval(before[1]), Interval(before[2])}));
    EXPECT_TRUE(HoldsModuloTurns(Intersect(set.prior, next), steps[k].truth)) << k;
    const Box wide = set.predict(set.prior);
    EXPECT_TRUE(set.prior[2].IsSubsetOf(wide[2])) << "a heading box of 2 pi predicts every heading";
    turned = std::max(turned, std::abs(steps[k].truth[2]));
  }
  EXPECT_GT(turned, 2 * std::numbers::pi);  // the drive wraps
}

// The guaranteed relaxed configuration (auto_q = false) holds the truth on
// every step where its assumption holds: without ghosts, every step.
TEST(IndoorLandmarksTest, TheGuaranteedRelaxedSolverHoldsTheTruthOnEveryStep) {
  auto solver =
      FindAlgorithm("q-relaxed").make({{"outlier_share", "0.3"}, {"auto_q", "false"}}, 5);
  int steps = 0;
  for (const Step& s :
       Drive({{"path", "random"}, {"steps", "150"}, {"spurious_rate", "0"}}, 5)) {
    const StepResult r = solver->Step(s.views, StopCondition());
    EXPECT_TRUE(HoldsModuloTurns(r.estimate->Hull(), s.truth)) << s.views.step;
    ++steps;
  }
  EXPECT_EQ(steps, 150);
}

TEST(IndoorLandmarksTest, BadParametersAreRefused) {
  const ProblemInfo& info = FindProblem("indoor-landmarks");
  EXPECT_THROW(info.resolve("p", {{"path", "c"}}), ParamError);
  EXPECT_THROW(info.resolve("p", {{"path", "a"}, {"steps", "47"}}), ParamError);
  EXPECT_NO_THROW(info.resolve("p", {{"path", "random"}, {"steps", "47"}}));
  EXPECT_THROW(info.resolve("p", {{"map", "/nonexistent.csv"}}), std::invalid_argument);
  // A map whose wall runs through the start.
  const std::string walled = ::testing::TempDir() + "walled_map.csv";
  std::ofstream(walled) << "kind,x1,y1,x2,y2\nwall,0,0.6,5,0.6\ncorner,3,2\nedge,0,-1\n";
  try {
    info.resolve("p", {{"map", walled}});
    ADD_FAILURE() << "a start on a wall was accepted";
  } catch (const ParamError& e) {
    EXPECT_NE(std::string(e.what()).find("start (0.8, 0.85)"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(info.resolve("p", {{"map", walled}, {"path", "b"}}));  // 0.55 m from it
  EXPECT_THROW(info.resolve("p", {{"dropout_rate", "1"}}), ParamError);
  EXPECT_THROW(info.resolve("p", {{"wheel_radius", "0.0001"}}), ParamError);  // below its error
  EXPECT_THROW(info.resolve("p", {{"track_error", "0.5"}}), ParamError);
}

TEST(IndoorLandmarksTest, TheSameSeedGivesTheSameDrive) {
  const std::vector<Step> a = Drive({{"path", "random"}}, 9), b = Drive({{"path", "random"}}, 9);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].truth, b[k].truth);
    EXPECT_EQ(a[k].observation_truth, b[k].observation_truth);
  }
}

}  // namespace
}  // namespace icp
