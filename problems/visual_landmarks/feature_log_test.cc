#include "problems/visual_landmarks/feature_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "problems/visual_landmarks/visual_landmarks.h"

namespace icp {
namespace {

const std::string kExample = std::string(ICPBENCH_VISUAL_LANDMARKS_DATA) + "/example_tracks.csv";

// The shipped example: the straight route of paper 004 §5.1, 30 steps, seed 1.
VisualDriveParams ExampleParams() {
  VisualDriveParams p;
  p.steps = 30;
  return p;
}

// Every interval of the read drive holds the written one; the references
// are the same.
void ExpectEncloses(const VisualDrive& read, const VisualDrive& written) {
  ASSERT_EQ(read.steps.size(), written.steps.size());
  EXPECT_EQ(read.poses, written.poses);
  ASSERT_EQ(read.landmarks.size(), written.landmarks.size());
  EXPECT_EQ(read.landmarks, written.landmarks);
  for (std::size_t k = 0; k < read.steps.size(); ++k) {
    const VisualDriveStep &r = read.steps[k], &w = written.steps[k];
    if (k > 0) {
      EXPECT_TRUE(w.ds.IsSubsetOf(r.ds)) << k;
      EXPECT_TRUE(w.dtheta.IsSubsetOf(r.dtheta)) << k;
    }
    EXPECT_TRUE(w.gps[0].IsSubsetOf(r.gps[0]) && w.gps[1].IsSubsetOf(r.gps[1])) << k;
    ASSERT_EQ(r.sightings.size(), w.sightings.size()) << k;
    for (std::size_t i = 0; i < r.sightings.size(); ++i) {
      EXPECT_EQ(r.sightings[i].landmark, w.sightings[i].landmark);
      EXPECT_TRUE(w.sightings[i].u.IsSubsetOf(r.sightings[i].u) &&
                  w.sightings[i].v.IsSubsetOf(r.sightings[i].v));
      // Enclosing, not wider than a few ulps.
      EXPECT_LT(r.sightings[i].u.Width() - w.sightings[i].u.Width(), 1e-9);
    }
  }
}

TEST(FeatureLogTest, Update) {
  if (!std::getenv("ICPBENCH_UPDATE_GOLDEN")) GTEST_SKIP() << "set ICPBENCH_UPDATE_GOLDEN=1 to rewrite";
  std::ofstream out(kExample);
  WriteFeatureLog(SimulateVisualDrive(ExampleParams(), 1), out,
                  "visual-landmarks example feature-track log (problems/visual_landmarks/"
                  "feature_log.h): paper 004's straight route, 30 steps, seed 1 of the simulator.\n"
                  "Written by ICPBENCH_UPDATE_GOLDEN=1 build/problems/visual_landmarks/feature_log_test");
}

TEST(FeatureLogTest, WrittenDrivesReadBackEnclosed) {
  for (std::uint64_t seed : {1u, 2u}) {
    VisualDriveParams p;
    p.route = "loop";
    p.speed = 1;
    p.steps = 40;
    p.landmarks = 20;
    const VisualDrive drive = SimulateVisualDrive(p, seed);
    std::stringstream text;
    WriteFeatureLog(drive, text, "a comment\nover two lines");
    ExpectEncloses(ReadFeatureLog(text, "loop.csv"), drive);
  }
}

TEST(FeatureLogTest, TheShippedExampleIsTheSimulatedDrive) {
  ExpectEncloses(ReadFeatureLog(kExample), SimulateVisualDrive(ExampleParams(), 1));
}

// The problem replays a log: the same CSPs hold the truth, and a log without
// references runs too, with no truth to judge.
TEST(FeatureLogTest, TheProblemReplaysALog) {
  for (const char* phase : {"teach", "repeat"}) {
    auto problem = MakeVisualLandmarks({{"log", kExample}, {"phase", phase}, {"w", "5"}}, 7);
    EXPECT_EQ(problem->NumSteps(), 30);
    Step step;
    int steps = 0;
    while (problem->Next(&step)) {
      ++steps;
      ASSERT_EQ(step.truth.size(), 3u);
      ASSERT_TRUE(step.views.csp->csp.domains().Contains(step.csp_truth)) << phase << " " << step.views.step;
    }
    EXPECT_EQ(steps, 30);
  }
  // Without references: teach runs, no truth; repeat has nothing to start from.
  std::stringstream bare;
  bare << "step,0,0,0,0,0,0.01,-0.02,0.02,,,\n"
          "track,0,3,410.5,250.25,1\n"
          "step,1,0.1,0.005,0,0.001,0.1,0,0.02,,,\n"
          "track,1,3,411,250.5,1\n";
  const std::string path = ::testing::TempDir() + "bare_tracks.csv";
  {
    std::ofstream out(path);
    out << bare.str();
  }
  auto teach = MakeVisualLandmarks({{"log", path}}, 1);
  Step step;
  ASSERT_TRUE(teach->Next(&step));
  EXPECT_TRUE(step.truth.empty());
  EXPECT_TRUE(step.csp_truth.empty());
  EXPECT_TRUE(step.landmark_truth.empty());
  EXPECT_EQ(step.views.csp->csp.domains()[2], Interval(-Pi().hi(), Pi().hi()));
  std::ofstream(path) << "step,0,0,0,0,0,,,,,,\n";
  EXPECT_THROW(MakeVisualLandmarks({{"log", path}, {"phase", "repeat"}, {"map", kExample}}, 1),
               std::invalid_argument);
}

TEST(FeatureLogTest, ErrorsNameTheLineAndTheField) {
  auto read = [](const std::string& text) {
    std::istringstream in(text);
    return ReadFeatureLog(in, "d.csv");
  };
  const std::string step0 = "step,0,0,0,0,0,,,,,,\n";
  const std::pair<std::string, std::string> cases[] = {
      {"", "no step row"},
      {"track,0,1,2,3,1\n", "before the first step row"},
      {step0 + "step,0,0,0,0,0,,,,,,\n", "t must increase"},
      {step0 + "step,1,abc,0,0,0,,,,,,\n", "field 3 (ds)"},
      {step0 + "step,1,0.1,-1,0,0,,,,,,\n", "field 4 (ds_error)"},
      {step0 + "step,1,0.1,0,0,0,1,,,,,\n", "gps_x .. gps_error"},
      {step0 + "track,1,1,2,3,1\n", "repeats the t"},
      {step0 + "track,0,-1,2,3,1\n", "field 3 (landmark)"},
      {step0 + "track,0,1,2,3\n", "a track row has 6 fields"},
      {step0 + "pose,0\n", "unknown row kind 'pose'"},
      {step0 + "landmark,1,1e10,0,0\n", "field 3 (x)"},
      {step0 + "landmark,1,1,0,0\nlandmark,1,50,0,0\n", "landmark 1's reference position given twice"}};
  for (const auto& [text, expected] : cases) {
    try {
      read(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("d.csv", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace icp
