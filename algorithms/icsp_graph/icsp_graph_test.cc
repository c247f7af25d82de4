#include "algorithms/icsp_graph/icsp_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "algorithms/registry.h"
#include "problems/visual_landmarks/visual_landmarks.h"

namespace icp {
namespace {

// Runs an estimator over a problem, checking on every step that the pose box
// and every landmark's position box hold the truth; returns the final
// landmark position boxes.
std::map<int, std::array<Interval, 3>> RunAndCheck(Estimator& estimator, Problem& problem,
                                                   const std::string& what) {
  std::map<int, std::array<Interval, 3>> last;
  Step step;
  while (problem.Next(&step)) {
    const std::string where = what + " step " + std::to_string(step.views.step);
    StepResult r = estimator.Step(step.views, StopCondition());
    EXPECT_TRUE(r.estimate->Contains(step.truth)) << where;
    for (const auto& [n, cone] : r.landmarks) {
      const std::array<Interval, 3> position = step.landmark_position(cone);
      for (int axis = 0; axis < 3; ++axis)
        EXPECT_TRUE(position[axis].Contains(step.landmark_truth.at(n)[axis]))
            << where << " landmark " << n << " axis " << axis;
      last[n] = position;
    }
  }
  return last;
}

TEST(IcspGraphTest, DigoAndLicHoldEveryPoseAndLandmarkOnEveryStep) {
  for (std::uint64_t seed : {1u, 2u}) {
    for (const char* w : {"1", "10"}) {
      const ParamMap teach{{"w", w}, {"steps", "60"}};
      auto digo = MakeDigo({}, seed);
      auto lic = MakeLic({}, seed);
      auto p1 = MakeVisualLandmarks(teach, seed);
      auto p2 = MakeVisualLandmarks(teach, seed);
      const auto by_digo = RunAndCheck(*digo, *p1, std::string("digo w=") + w);
      const auto by_lic = RunAndCheck(*lic, *p2, std::string("lic w=") + w);
      EXPECT_EQ(by_digo.size(), 5u);
      EXPECT_EQ(by_lic.size(), 5u);
    }
  }
  const ParamMap repeat{{"phase", "repeat"}, {"route", "loop"}, {"speed", "1"}, {"steps", "80"},
                        {"landmarks", "40"}, {"w", "5"}};
  auto digo = MakeDigo({}, 3);
  auto problem = MakeVisualLandmarks(repeat, 3);
  RunAndCheck(*digo, *problem, "digo repeat");
}

// The mean width on each axis of the scored landmarks' last boxes (MDW,
// paper 004 Table 2) after a whole teach drive.
std::array<double, 3> FinalMdw(Estimator& estimator, Problem& problem) {
  std::map<int, Box> last;
  Step step, final_step;
  while (problem.Next(&step)) {
    last = estimator.Step(step.views, StopCondition()).landmarks;
    final_step = step;
  }
  std::array<double, 3> mdw{0, 0, 0};
  for (int n : final_step.scored_landmarks) {
    const auto box = final_step.landmark_position(last.at(n));
    for (int axis = 0; axis < 3; ++axis)
      mdw[axis] += box[axis].Width() / final_step.scored_landmarks.size();
  }
  return mdw;
}

// Paper 004 Table 2's finding, on its scene at Xi = 10: DIGO maps every
// axis narrower than LIC, on every seed; and the observations written on the
// position too (the default) map narrower than on the cone alone.
TEST(IcspGraphTest, DigoMapsNarrowerThanLicOnEveryAxis) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    auto digo = MakeDigo({}, seed);
    auto lic = MakeLic({}, seed);
    auto p1 = MakeVisualLandmarks({}, seed);
    auto p2 = MakeVisualLandmarks({}, seed);
    const auto by_digo = FinalMdw(*digo, *p1);
    const auto by_lic = FinalMdw(*lic, *p2);
    auto cone_only = MakeDigo({}, seed);
    auto p3 = MakeVisualLandmarks({{"observation", "cone"}}, seed);
    const auto by_cone = FinalMdw(*cone_only, *p3);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_LT(by_digo[axis], by_lic[axis]) << "seed " << seed << " axis " << axis;
      EXPECT_LT(by_digo[axis], by_cone[axis]) << "seed " << seed << " axis " << axis;
      EXPECT_TRUE(std::isfinite(by_cone[axis])) << "seed " << seed << " axis " << axis;
    }
  }
}

// Every ICP algorithm of the registry runs on the problem (its windows keep
// the landmarks too) and holds every pose and landmark, teach and repeat.
TEST(IcspGraphTest, EveryIcpAlgorithmHoldsEveryPoseAndLandmark) {
  int algorithms = 0;
  for (const AlgorithmInfo& info : Algorithms()) {
    if (info.test_only || info.needs != View::kCsp) continue;
    ++algorithms;
    for (const char* phase : {"teach", "repeat"}) {
      auto estimator = info.make({}, 1);
      auto problem = MakeVisualLandmarks({{"phase", phase}, {"steps", "12"}, {"w", "3"}}, 2);
      const auto last = RunAndCheck(*estimator, *problem, info.name + " " + phase);
      EXPECT_FALSE(last.empty()) << info.name << " " << phase;
    }
  }
  EXPECT_GE(algorithms, 8);  // hc3, hc4, bc3, bc4, 3b-bc4, 3b-hc4, digo, lic
}

TEST(IcspGraphTest, InnerMustBeACspContractor) {
  EXPECT_NO_THROW(ResolveIcspGraph("digo", {{"inner", "bc4"}}));
  EXPECT_THROW(ResolveIcspGraph("digo", {{"inner", "q-relaxed"}}), ParamError);
  EXPECT_THROW(ResolveIcspGraph("lic", {{"inner", "nope"}}), ParamError);
  EXPECT_THROW(MakeLic({{"inner", "digo"}}, 1), ParamError);
}

}  // namespace
}  // namespace icp
