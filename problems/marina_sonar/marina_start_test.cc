// The start=area prior of marina-sonar: the thesis' 10,368 m² particle prior
// (Fig. 6.9) about the true start, used by every view at the first step.
#include <gtest/gtest.h>

#include <vector>

#include "core/random.h"
#include "problems/marina_sonar/marina_map.h"
#include "problems/marina_sonar/marina_sonar.h"
#include "problems/registry.h"

namespace icp {
namespace {

std::vector<Step> DriveFrom(const std::string& start, int steps, std::uint64_t seed) {
  return ProblemSteps("marina-sonar", {{"steps", std::to_string(steps)}, {"start", start}}, seed);
}

double AreaOf(const Box& b) { return b[0].Width() * b[1].Width(); }

TEST(MarinaStartTest, AreaPriorIsTheThesisAreaAndHoldsTheTrueStart) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const std::vector<Step> steps = DriveFrom("area", 3, seed);
    ASSERT_EQ(steps.size(), 3u);
    const Box& prior = steps[0].views.measurement_set->prior;
    EXPECT_NEAR(AreaOf(prior), 10368, 1e-6) << "seed " << seed;
    EXPECT_DOUBLE_EQ(prior[0].Width(), 144);
    EXPECT_DOUBLE_EQ(prior[1].Width(), 72);
    EXPECT_TRUE(prior.Contains(steps[0].truth)) << "seed " << seed;
    // The CSP's first state and the particle prior start from the same box.
    EXPECT_EQ(steps[0].views.csp->csp.domains(), prior);
    RandomEngine rng(seed);
    for (int i = 0; i < 200; ++i) {
      // (x, y), then the filter's hidden sensor biases.
      const std::vector<double> particle = steps[0].views.probabilistic->sample_prior(rng);
      EXPECT_TRUE(prior.Contains({particle[0], particle[1]}));
    }
    // Later steps: the whole map, as the other starts.
    EXPECT_GT(steps[1].views.measurement_set->prior.MaxWidth(), 400);
  }
}

TEST(MarinaStartTest, AreaLiesBetweenTheKnownAndTheUnknownStart) {
  const double known = AreaOf(DriveFrom("known", 1, 1)[0].views.measurement_set->prior);
  const double area = AreaOf(DriveFrom("area", 1, 1)[0].views.measurement_set->prior);
  const double unknown = AreaOf(DriveFrom("unknown", 1, 1)[0].views.measurement_set->prior);
  EXPECT_LT(known, area);
  EXPECT_LT(area, unknown);
}

TEST(MarinaStartTest, AreaNearAnEdgeSlidesInsideTheBounds) {
  const Box bounds({Interval(0, 460), Interval(0, 280)});
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {1, 1}, {459, 279}, {230, 140}, {10, 270}}) {
    const Box b = MarinaAreaStart(x, y, bounds);
    EXPECT_NEAR(AreaOf(b), 10368, 1e-6);
    EXPECT_TRUE(b.Contains({x, y})) << x << ", " << y;
    EXPECT_GE(b[0].lo(), 0);
    EXPECT_LE(b[0].hi(), 460);
    EXPECT_GE(b[1].lo(), 0);
    EXPECT_LE(b[1].hi(), 280);
  }
  // Away from the edges it is centred on the truth.
  const Box centred = MarinaAreaStart(230, 140, bounds);
  EXPECT_DOUBLE_EQ(centred[0].lo(), 158);
  EXPECT_DOUBLE_EQ(centred[1].lo(), 104);
}

TEST(MarinaStartTest, AreaNeedsTheTrueStart) {
  MarinaSonarParams p;
  p.start = "area";
  MarinaRecord r;  // no truth
  EXPECT_THROW(MarinaSonarProblem(p, LoadMarinaMap(ShippedMarinaMapPath()), {r}), ParamError);
}

}  // namespace
}  // namespace icp
