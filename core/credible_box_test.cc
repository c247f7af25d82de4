// CredibleBox and WeightedQuantile (credible_box.h).
#include "core/credible_box.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/estimate.h"
#include "core/random.h"

namespace icp {
namespace {

TEST(WeightedQuantileTest, CountsTheWeightBelow) {
  const std::vector<double> v = {4, 1, 3, 2};
  const std::vector<double> w = {1, 1, 1, 1};
  EXPECT_EQ(WeightedQuantile(v, w, 0), 1);
  EXPECT_EQ(WeightedQuantile(v, w, 0.25), 2);  // exceeds a quarter only with 2
  EXPECT_EQ(WeightedQuantile(v, w, 0.6), 3);
  EXPECT_EQ(WeightedQuantile(v, w, 1), 4);
  EXPECT_EQ(WeightedQuantile(v, {0, 5, 0, 0}, 0.9), 1);
}

TEST(CredibleTailTest, IsSidaks) {
  EXPECT_NEAR(CredibleTail(0.95, 1), 0.025, 1e-15);
  EXPECT_NEAR(1 - 2 * CredibleTail(0.9, 2), std::sqrt(0.9), 1e-15);
  EXPECT_THROW(CredibleTail(1, 2), std::invalid_argument);
  EXPECT_THROW(CredibleTail(0.5, 0), std::invalid_argument);
}

// A known distribution: independent components (uniform x, exponential-ish
// y by unequal weights), so the level box holds about level of the weight.
TEST(CredibleBoxTest, HoldsItsLevelOfTheWeight) {
  RandomEngine rng(7);
  const int n = 20000;
  cv::Mat cloud(n, 2, CV_64F);
  std::vector<double> w(n);
  for (int i = 0; i < n; ++i) {
    cloud.at<double>(i, 0) = UniformReal(rng, -3, 5);
    cloud.at<double>(i, 1) = UniformReal(rng, 0, 10);
    w[i] = std::exp(-cloud.at<double>(i, 1) / 2);
  }
  double total = 0;
  for (double wi : w) total += wi;
  for (double level : {0.5, 0.9, 0.95}) {
    const Box box = CredibleBox(cloud, w, level);
    double inside = 0;
    for (int i = 0; i < n; ++i)
      if (box[0].Contains(cloud.at<double>(i, 0)) && box[1].Contains(cloud.at<double>(i, 1)))
        inside += w[i];
    EXPECT_NEAR(inside / total, level, 0.01) << level;
    // x uniform on [-3, 5]: its central sqrt(level) interval.
    const double half = 4 * std::sqrt(level);
    EXPECT_NEAR(box[0].lo(), 1 - half, 0.1) << level;
    EXPECT_NEAR(box[0].hi(), 1 + half, 0.1) << level;
    // The same box as the quantiles of a full sort.
    std::vector<double> x(n);
    for (int i = 0; i < n; ++i) x[i] = cloud.at<double>(i, 0);
    const double tail = CredibleTail(level, 2);
    EXPECT_EQ(box[0].lo(), WeightedQuantile(x, w, tail));
    EXPECT_EQ(box[0].hi(), WeightedQuantile(x, w, 1 - tail));
  }
  EXPECT_THROW(CredibleBox(cloud, std::vector<double>(n, 0.0), 0.9), std::invalid_argument);
  EXPECT_THROW(CredibleBox(cloud, w, 1), std::invalid_argument);
}

// The tails' selection against a full sort, where it is easy to get wrong:
// few particles, many ties (values on a coarse grid), zero weights, equal
// and very unequal weights, one and three components, every level.
TEST(CredibleBoxTest, EqualsTheSortedQuantilesWithTiesAndZeroWeights) {
  RandomEngine rng(11);
  for (int trial = 0; trial < 400; ++trial) {
    const int n = static_cast<int>(UniformInt(rng, 1, trial < 200 ? 40 : 3000));
    const int d = trial % 2 == 0 ? 1 : 3;
    const double grid = trial % 3 == 0 ? 0.5 : 1e-9;  // coarse: ties everywhere
    cv::Mat cloud(n, d, CV_64F);
    std::vector<double> w(n);
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < d; ++c)
        cloud.at<double>(i, c) = grid * std::round(UniformReal(rng, -3, 3) / grid);
      const double draw = UniformReal(rng, 0, 1);
      w[i] = trial % 4 == 0 ? 1 : draw < 0.1 ? 0 : std::exp(-20 * draw);
    }
    if (std::all_of(w.begin(), w.end(), [](double x) { return x == 0; })) w[0] = 1;
    for (double level : {0.5, 0.95, 0.999}) {
      const Box box = CredibleBox(cloud, w, level);
      const double tail = CredibleTail(level, d);
      for (int c = 0; c < d; ++c) {
        std::vector<double> v(n);
        for (int i = 0; i < n; ++i) v[i] = cloud.at<double>(i, c);
        ASSERT_EQ(box[c].lo(), WeightedQuantile(v, w, tail)) << trial << " " << level << " " << c;
        ASSERT_EQ(box[c].hi(), WeightedQuantile(v, w, 1 - tail)) << trial << " " << level << " " << c;
      }
    }
  }
}

// A NaN value (a broken particle) sorts after every number: it never
// narrows the box, and the box is the numbers' while they hold the tails.
TEST(CredibleBoxTest, NanValuesSortAfterEveryNumber) {
  const int n = 1000;
  cv::Mat cloud(n, 1, CV_64F);
  for (int i = 0; i < n; ++i) cloud.at<double>(i, 0) = i % 10 == 0 ? std::nan("") : i;
  const Box box = CredibleBox(cloud, std::vector<double>(n, 1.0), 0.5);
  EXPECT_FALSE(std::isnan(box[0].lo()));
  EXPECT_GE(box[0].lo(), 200);
  EXPECT_FALSE(std::isnan(box[0].hi()));
}

TEST(CredibleBoxTest, IsTheParticleEstimatesRegionAndSetsHaveNone) {
  cv::Mat cloud = (cv::Mat_<double>(4, 1) << 1, 2, 3, 4);
  const ParticleEstimate estimate(cloud, {1, 1, 1, 1});
  EXPECT_EQ(*estimate.CredibleRegion(0.5), CredibleBox(cloud, {1, 1, 1, 1}, 0.5));
  EXPECT_TRUE(ParticleEstimate(cloud, {0, 0, 0, 0}).CredibleRegion(0.5)->IsEmpty());
  EXPECT_FALSE(BoxEstimate(Box({Interval(0, 1)})).CredibleRegion(0.5));
}

}  // namespace
}  // namespace icp
