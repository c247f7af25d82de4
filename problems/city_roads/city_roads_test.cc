#include "problems/city_roads/city_roads.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "problems/marina_sonar/marina_map.h"
#include "problems/registry.h"

namespace icp {
namespace {

std::vector<Step> Drive(const ParamMap& params, std::uint64_t seed) {
  return ProblemSteps("city-roads", params, seed);
}

TEST(CityMapTest, ShippedPngIsTheDrawnMapInItsFrame) {
  const MarinaMap map = LoadMarinaMap(ShippedCityMapPath());
  ASSERT_EQ(map.image->rows(), 300);
  ASSERT_EQ(map.image->cols(), 300);
  EXPECT_EQ(cv::countNonZero((map.image->pixels() != 0) != (DrawCityMap() != 0)), 0)
      << "data/city.png differs from DrawCityMap(): rerun the city_map tool";
  EXPECT_EQ(map.image->frame().pixel_size, 1);
  // Roads 10 m wide about x = 75 and y = 125; a block between them.
  EXPECT_TRUE(InsideWallPixel(*map.image, 70.5, 10.5, 0));
  EXPECT_TRUE(InsideWallPixel(*map.image, 10.5, 129.5, 0));
  EXPECT_FALSE(InsideWallPixel(*map.image, 50.5, 50.5, 0));
  EXPECT_LT(std::filesystem::file_size(ShippedCityMapPath()), 5000u);
}

TEST(CitySimulatorTest, TheCarStaysOnTheRoadsAndItsReadingsBoundItsMotion) {
  const CityRoadsParams p;
  const std::vector<CityRecord> records = SimulateCityRoads(p, 4);
  const MarinaMap map = LoadMarinaMap(ShippedCityMapPath());
  ASSERT_EQ(static_cast<int>(records.size()), p.steps);
  double driven = 0;
  for (std::size_t k = 0; k + 1 < records.size(); ++k) {
    const CityRecord &r = records[k], &next = records[k + 1];
    EXPECT_TRUE(InsideWallPixel(*map.image, r.truth_x, r.truth_y, 0)) << k;
    const double dx = next.truth_x - r.truth_x, dy = next.truth_y - r.truth_y;
    const double chord = std::hypot(dx, dy);
    driven += chord;
    EXPECT_LE(std::fabs(r.speed * p.dt - chord), 0.9 * p.speed_error * p.dt + 1e-9) << k;
    EXPECT_LE(std::fabs(std::remainder(r.heading - std::atan2(dy, dx), 2 * M_PI)),
              0.9 * p.compass_error + 1e-9)
        << k;
  }
  EXPECT_GT(driven, 1300);  // most of the 1500 m route
}

// Soundness: on a short drive every ICP algorithm, through the CSP view
// with the roads, and the relaxed solvers keep the truth in every box, and
// the roads keep the box small.
TEST(CityRoadsViewsTest, EveryAlgorithmKeepsTheTruthAtEveryStep) {
  const std::vector<Step> steps = Drive({{"steps", "25"}}, 2);
  for (const std::string name :
       {"hc3", "hc4", "bc3", "bc4", "3b-bc4", "q-relaxed", "polynomial", "accumulator"}) {
    auto estimator = FindAlgorithm(name).make({}, 1);
    double widest = 0;
    for (const Step& step : steps) {
      ASSERT_EQ(step.views.csp->extra_contractors.size(), step.views.csp->states.size() / 2);
      const StepResult result = estimator->Step(step.views, StopCondition());
      ASSERT_TRUE(result.estimate->Contains(step.truth)) << name << " step " << step.views.step;
      widest = std::max(widest, result.estimate->Hull().MaxWidth());
    }
    EXPECT_LT(widest, 60) << name;
  }
}

// Without the roads the boxes grow with the drive (Fig. 4.17 (a)); with them
// they stay bounded (Fig. 4.17 (b)).
TEST(CityRoadsViewsTest, TheRoadsBoundWhatDeadReckoningLetsGrow) {
  auto last_width = [](const std::string& roads) {
    auto hc4 = FindAlgorithm("hc4").make({}, 1);
    double width = 0;
    for (const Step& step : Drive({{"steps", "80"}, {"roads", roads}}, 3)) {
      EXPECT_TRUE(step.views.csp->extra_contractors.empty() == (roads == "false"));
      const StepResult result = hc4->Step(step.views, StopCondition());
      EXPECT_TRUE(result.estimate->Contains(step.truth)) << roads << " " << step.views.step;
      width = result.estimate->Hull().MaxWidth();
    }
    return width;
  };
  const double dead_reckoning = last_width("false"), roads = last_width("true");
  EXPECT_GT(dead_reckoning, 50);
  EXPECT_LT(roads, dead_reckoning / 3);
}

TEST(CityRoadsViewsTest, ParticlesStartInTheStartBoxAndWeighRoadsHigher) {
  const std::vector<Step> steps = Drive({{"steps", "2"}}, 1);
  const ProbabilisticView& pv = *steps[0].views.probabilistic;
  RandomEngine rng(1);
  for (int i = 0; i < 100; ++i) {
    const std::vector<double> s = pv.sample_prior(rng);
    EXPECT_LE(std::hypot(s[0] - steps[0].truth[0], s[1] - steps[0].truth[1]), 2 * std::sqrt(2.0));
  }
  EXPECT_GT(pv.log_likelihood({75, 50}), pv.log_likelihood({50, 50}));
}

// A particle pushed off the map (a large speed_error) is impossible, not
// an error: the filter drops it (it used to fail "not inside its domain").
TEST(CityRoadsViewsTest, AStateOffTheMapIsImpossible) {
  for (const char* roads : {"true", "false"}) {
    const std::vector<Step> steps = Drive({{"steps", "2"}, {"roads", roads}}, 1);
    const ProbabilisticView& pv = *steps[0].views.probabilistic;
    EXPECT_EQ(pv.log_likelihood({-1e4, 50}), -INFINITY) << roads;
    EXPECT_EQ(pv.log_likelihood({50, 1e6}), -INFINITY) << roads;
    EXPECT_GT(pv.log_likelihood({75, 50}), -INFINITY) << roads;
  }
}

TEST(CityRoadsRegistryTest, OffersTheThreeViews) {
  const ProblemInfo& p = FindProblem("city-roads");
  EXPECT_EQ(p.offers,
            (std::vector<View>{View::kCsp, View::kMeasurementSet, View::kProbabilistic}));
  EXPECT_THROW(p.resolve("city-roads", {{"steps", "0"}}), ParamError);
}

}  // namespace
}  // namespace icp
