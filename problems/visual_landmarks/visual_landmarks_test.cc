#include "problems/visual_landmarks/visual_landmarks.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "algorithms/hc4/hc4.h"
#include "core/tape.h"
#include "problems/registry.h"

namespace icp {
namespace {

std::unique_ptr<Problem> Make(ParamMap params, std::uint64_t seed) {
  return MakeVisualLandmarks(params, seed);
}

// The truth is a solution of every step's CSP: inside the domains, every
// constraint satisfiable at it; and HC4 on the whole window keeps it.
void ExpectTruthSolvesEveryStep(Problem& problem, const std::string& what) {
  Step step;
  std::vector<Interval> slots;
  while (problem.Next(&step)) {
    const ConstraintSystem& csp = step.views.csp->csp;
    const std::string where = what + " step " + std::to_string(step.views.step);
    ASSERT_EQ(step.csp_truth.size(), static_cast<std::size_t>(csp.num_variables())) << where;
    ASSERT_TRUE(csp.domains().Contains(step.csp_truth)) << where;
    Box point;
    for (double t : step.csp_truth) point.push_back(Interval(t));
    CompiledSystem sys(csp);
    for (int c = 0; c < sys.num_constraints(); ++c)
      ASSERT_FALSE(Intersect(sys.tape(c).Forward(point, slots), sys.tape(c).range()).IsEmpty())
          << where << ": " << csp.ConstraintToString(c);
    Box box = csp.domains();
    ContractContext context;
    MakeHC4({}, csp)->Contract(box, context);
    ASSERT_TRUE(box.Contains(step.csp_truth)) << where;
  }
}

TEST(VisualLandmarksTest, TheTruthSolvesEveryTeachAndRepeatWindow) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    auto straight = Make({{"steps", "40"}, {"w", "5"}}, seed);
    ExpectTruthSolvesEveryStep(*straight, "straight teach seed " + std::to_string(seed));
    auto cone = Make({{"steps", "40"}, {"w", "5"}, {"observation", "cone"}}, seed);
    ExpectTruthSolvesEveryStep(*cone, "straight teach, cone form, seed " + std::to_string(seed));
    auto loop = Make({{"route", "loop"}, {"speed", "1"}, {"steps", "60"}, {"landmarks", "30"},
                      {"w", "4"}},
                     seed);
    ExpectTruthSolvesEveryStep(*loop, "loop teach seed " + std::to_string(seed));
    auto repeat = Make({{"phase", "repeat"}, {"route", "loop"}, {"speed", "1"}, {"steps", "60"},
                        {"landmarks", "30"}, {"w", "4"}},
                       seed);
    ExpectTruthSolvesEveryStep(*repeat, "loop repeat seed " + std::to_string(seed));
  }
}

TEST(VisualLandmarksTest, WindowHoldsPosesThenLandmarksAndItsIcspsPartitionTheConstraints) {
  auto problem = Make({{"w", "3"}, {"steps", "6"}}, 1);
  Step step;
  while (problem->Next(&step)) {
    const CspView& view = *step.views.csp;
    const int k = step.views.step, oldest = std::max(0, k - 3);
    EXPECT_EQ(view.newest, k);
    ASSERT_TRUE(std::is_sorted(view.states.begin(), view.states.end()));
    const int poses = 3 * (k - oldest + 1);
    EXPECT_EQ(view.states[poses - 1], (StateRef{k, 2}));
    // The five landmarks of the straight route are in view from step 0.
    ASSERT_EQ(static_cast<int>(view.states.size()), poses + 5 * kLandmarkComponents);
    EXPECT_EQ(view.states[poses], StateRef::Landmark(0, kLandmarkXc));
    EXPECT_EQ(view.csp.names()[poses + kDepth], "L0.d");
    std::multiset<int> covered;
    int motions = 0;
    for (const CspView::Icsp& icsp : view.icsps) {
      EXPECT_GE(icsp.time, oldest);
      EXPECT_LE(icsp.time, k);
      motions += icsp.motion;
      covered.insert(icsp.constraints.begin(), icsp.constraints.end());
    }
    EXPECT_EQ(motions, k - oldest);
    // Every constraint is in an ICSP; only a landmark's eq. 12 is in several
    // (one per sighting of it).
    for (int c = 0; c < static_cast<int>(view.csp.constraints().size()); ++c)
      EXPECT_GE(covered.count(c), 1u) << "constraint " << c << " at step " << k;
    const std::size_t sightings = view.icsps.size() - motions;
    // Motions 3 constraints, sightings 5 (camera_model.h) and eq. 12 (3).
    EXPECT_EQ(covered.size(), 3 * motions + 5 * sightings + 3 * sightings + 2 * 5 * (oldest == 0));
    // The landmarks' truth for the metrics: every landmark, its position.
    ASSERT_EQ(step.landmark_truth.size(), 5u);
    EXPECT_EQ(step.landmark_truth.at(4), (std::array<double, 3>{30, 0.2, 1.6}));
    ASSERT_TRUE(step.landmark_position);
    // Six steps (0.6 m) give no landmark 5 degrees of parallax.
    EXPECT_TRUE(step.scored_landmarks.empty());
  }
}

// The map metrics score the landmarks the drive can locate: over the
// paper's 10 m, the four with parallax and not the fifth, almost on the line
// of travel (paper 004's "converged" four).
TEST(VisualLandmarksTest, ScoresTheLandmarksWithParallax) {
  Step step;
  ASSERT_TRUE(Make({}, 1)->Next(&step));
  EXPECT_EQ(step.scored_landmarks, (std::vector<int>{0, 1, 2, 3}));
  ASSERT_TRUE(Make({{"min_parallax", "0"}}, 1)->Next(&step));
  EXPECT_EQ(step.scored_landmarks.size(), 5u);
}

TEST(VisualLandmarksTest, RepeatReadsATaughtMapAndRefusesOneThatMissesALandmark) {
  const std::string path = ::testing::TempDir() + "visual_landmarks_map.csv";
  VisualDriveParams drive_params = DriveParams(VisualLandmarksParams{});
  const VisualDrive drive = SimulateVisualDrive(drive_params, 1);
  LandmarkMap map;
  for (int n = 0; n < 4; ++n) {
    const auto& l = drive.landmarks[n];
    map[n] = {Interval(l[0] - 0.1, l[0] + 0.2), Interval(l[1] - 0.1, l[1] + 0.1),
              Interval(l[2] - 0.05, l[2] + 0.1)};
  }
  {
    std::ofstream out(path);
    WriteLandmarkMap(map, out, "four of the five");
  }
  EXPECT_EQ(ReadLandmarkMap(path), map);
  const ParamMap repeat{{"phase", "repeat"}, {"map", path}, {"steps", "30"}};
  EXPECT_NO_THROW(ResolveVisualLandmarks("visual-landmarks", repeat));
  auto problem = Make(repeat, 2);
  Step step;
  ASSERT_TRUE(problem->Next(&step));
  // Landmark 4 is not in the map: its sightings are ignored.
  const CspView& view = *step.views.csp;
  EXPECT_EQ(view.states.back(), StateRef::Landmark(3, kLandmarkZ));
  EXPECT_EQ(view.csp.domains()[3 + kLandmarkXc], map[0][0]);
  EXPECT_EQ(view.csp.domains()[3 + kDepth], Interval(0.0));
  ExpectTruthSolvesEveryStep(*Make(repeat, 3), "repeat on a file map");

  map[2][1] = Interval(map[2][1].hi() + 1, map[2][1].hi() + 2);  // misses landmark 2
  {
    std::ofstream out(path);
    WriteLandmarkMap(map, out);
  }
  EXPECT_THROW(Make(repeat, 1), std::invalid_argument);
  std::remove(path.c_str());
  EXPECT_THROW(Make(repeat, 1), std::invalid_argument);  // no file: the run fails
  EXPECT_THROW(ResolveVisualLandmarks("visual-landmarks", {{"map", "x.csv"}}), ParamError);
}

TEST(VisualLandmarksTest, MapFileErrorsNameTheLine) {
  auto read = [](const std::string& text) {
    std::istringstream in(text);
    return ReadLandmarkMap(in, "m.csv");
  };
  const std::string header = "landmark,x_lo,x_hi,y_lo,y_hi,z_lo,z_hi\n";
  EXPECT_EQ(read("# c\n" + header + "3,1,2,3,4,5,6\n").at(3)[2], Interval(5, 6));
  for (const std::string& bad : {std::string("x,y\n"), header + "1,2,1,0,0,0,0\n",
                                 header + "-1,0,1,0,1,0,1\n", header + "1,0,1,0,1,0\n",
                                 header + "1,0,1,0,1,0,inf\n",
                                 header + "1,0,1,0,1,0,1\n1,0,1,0,1,0,1\n", std::string(""),
                                 "# no landmark\n" + header}) {
    try {
      read(bad);
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("m.csv", 0), 0u) << e.what();
    }
  }
}

// A bad log, or a map that exists and is bad, stops the spec (a
// ParamError at resolution) instead of failing every run; a map that does
// not exist yet is read when a run starts (an earlier command may write it).
TEST(VisualLandmarksTest, FilesAreCheckedWhenTheSpecIsResolved) {
  const ProblemInfo& info = FindProblem("visual-landmarks");
  const std::string dir = ::testing::TempDir();
  const std::string bad_log = dir + "/bad_features.csv";
  std::ofstream(bad_log) << "nothing,here\n";
  const std::string bad_map = dir + "/bad_map.csv";
  std::ofstream(bad_map) << "landmark,x_lo,x_hi,y_lo,y_hi,z_lo,z_hi\n";
  const std::string fifo = dir + "/fifo_map.csv";
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const std::pair<ParamMap, std::string> cases[] = {
      {{{"log", bad_log}}, bad_log},
      {{{"phase", "repeat"}, {"map", bad_map}}, bad_map + ": no landmark"},
      {{{"phase", "repeat"}, {"map", fifo}}, "is not a regular file"}};
  for (const auto& [params, expected] : cases) {
    try {
      info.resolve("visual-landmarks", params);
      ADD_FAILURE() << "accepted " << expected;
    } catch (const ParamError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(info.resolve("visual-landmarks", {{"phase", "repeat"}, {"map", dir + "/not_yet.csv"}}));
  std::remove(fifo.c_str());
}

}  // namespace
}  // namespace icp
