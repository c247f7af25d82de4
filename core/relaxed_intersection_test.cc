#include "core/relaxed_intersection.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/random.h"

namespace icp {
namespace {

TEST(RelaxedIntersectionTest, IntervalsByHand) {
  // Points in at least 4 - q of [0,4], [1,5], [2,6], [7,9].
  const std::vector<Interval> xs = {{0, 4}, {1, 5}, {2, 6}, {7, 9}};
  EXPECT_TRUE(RelaxedIntersection(xs, 0).IsEmpty());
  EXPECT_EQ(RelaxedIntersection(xs, 1), Interval(2, 4));
  EXPECT_EQ(RelaxedIntersection(xs, 2), Interval(1, 5));
  EXPECT_EQ(RelaxedIntersection(xs, 3), Interval(0, 9));
  EXPECT_EQ(RelaxedIntersection(xs, 4), Interval::Entire());
}

TEST(RelaxedIntersectionTest, TwoPiecesGiveTheirHull) {
  // Fig. 3.4 (b): the 2-relaxed intersection is [1,2] u [6,7]; its hull is returned.
  const std::vector<Interval> xs = {{0, 2}, {1, 3}, {5, 7}, {6, 8}};
  EXPECT_EQ(RelaxedIntersection(xs, 2), Interval(1, 7));
}

TEST(RelaxedIntersectionTest, ClosedBoundsTouchAndEmptiesHoldNothing) {
  const std::vector<Interval> touching = {{0, 1}, {1, 2}};
  EXPECT_EQ(RelaxedIntersection(touching, 0), Interval(1, 1));
  const std::vector<Interval> with_empty = {{0, 1}, Interval::Empty(), {0.5, 3}};
  EXPECT_TRUE(RelaxedIntersection(with_empty, 0).IsEmpty());
  EXPECT_EQ(RelaxedIntersection(with_empty, 1), Interval(0.5, 1));
  EXPECT_THROW(RelaxedIntersection(touching, -1), std::invalid_argument);
}

TEST(RelaxedIntersectionTest, QZeroIsThePlainIntersection) {
  const std::vector<Interval> xs = {{-1, 4}, {0, 5}, {-3, 2.5}};
  EXPECT_EQ(RelaxedIntersection(xs, 0), Interval(0, 2.5));
}

TEST(RelaxedIntersectionTest, BoxesPerDimension) {
  // Fig. 3.5-like: the 1-relaxed intersection of 4 boxes, per dimension.
  const std::vector<Box> boxes = {Box{{0, 4}, {0, 4}}, Box{{1, 5}, {3, 6}},
                                  Box{{2, 6}, {-1, 1}}, Box{{3, 8}, {0.5, 5}}};
  const Box r = RelaxedIntersection(boxes, 1, 2);
  EXPECT_EQ(r[0], Interval(2, 5));
  EXPECT_EQ(r[1], Interval(0.5, 4));
  EXPECT_TRUE(RelaxedIntersection(boxes, 0, 2).IsEmpty());
  EXPECT_EQ(RelaxedIntersection(std::vector<Box>{}, 0, 2), Box(2));
}

// The lowest and highest bound covered by m - q intervals, by counting.
Interval BruteForce(const std::vector<Interval>& xs, int q) {
  const int need = static_cast<int>(xs.size()) - q;
  Interval out = Interval::Empty();
  for (const Interval& x : xs)
    for (double t : {x.lo(), x.hi()}) {
      int cover = 0;
      for (const Interval& y : xs) cover += y.Contains(t) ? 1 : 0;
      if (cover >= need) out = Hull(out, Interval(t));
    }
  return out;
}

TEST(RelaxedIntersectionTest, MatchesCountingOnRandomIntervals) {
  RandomEngine rng(7);
  for (int trial = 0; trial < 500; ++trial) {
    const int m = UniformInt(rng, 1, 12);
    std::vector<Interval> xs;
    for (int i = 0; i < m; ++i) {
      // Integer bounds make ties (touching and equal bounds) frequent.
      const double a = UniformInt(rng, -10, 10), b = UniformInt(rng, -10, 10);
      xs.emplace_back(std::min(a, b), std::max(a, b));
    }
    for (int q = 0; q < m; ++q) EXPECT_EQ(RelaxedIntersection(xs, q), BruteForce(xs, q)) << trial;
  }
}

}  // namespace
}  // namespace icp
