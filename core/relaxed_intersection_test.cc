#include "core/relaxed_intersection.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/random.h"
#include "core/relaxed_intersection_testing.h"

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

TEST(RelaxedIntersectionTest, BoxesGiveTheExactHull) {
  // Fig. 3.5-like: 4 boxes, q = 1. Only A∩B∩D = [3,4]x[3,4] and
  // A∩C∩D = [3,4]x[0.5,1] lie in three boxes; the per-dimension hull of the
  // thesis would give [2,5]x[0.5,4].
  const std::vector<Box> boxes = {Box{{0, 4}, {0, 4}}, Box{{1, 5}, {3, 6}},
                                  Box{{2, 6}, {-1, 1}}, Box{{3, 8}, {0.5, 5}}};
  EXPECT_EQ(RelaxedIntersection(boxes, 1, 2), (Box{{3, 4}, {0.5, 4}}));
  EXPECT_TRUE(RelaxedIntersection(boxes, 0, 2).IsEmpty());
  EXPECT_EQ(RelaxedIntersection(boxes, 3, 2), (Box{{0, 8}, {-1, 6}}));
  EXPECT_EQ(RelaxedIntersection(std::vector<Box>{}, 0, 2), Box(2));
  EXPECT_EQ(RelaxedIntersection(boxes, 4, 2), Box(2));
  EXPECT_THROW(RelaxedIntersection(boxes, -1, 2), std::invalid_argument);
}

TEST(RelaxedIntersectionTest, BoxesThatOnlyTouchShareTheirFace) {
  // Closed boxes: a shared edge or corner is a common point; an empty box
  // holds none.
  const std::vector<Box> corner = {Box{{0, 1}, {0, 1}}, Box{{1, 2}, {1, 2}}};
  EXPECT_EQ(RelaxedIntersection(corner, 0, 2), (Box{{1, 1}, {1, 1}}));
  Box empty(2);
  empty.SetEmpty();
  const std::vector<Box> with_empty = {Box{{0, 1}, {0, 1}}, empty, Box{{0.5, 3}, {1, 3}}};
  EXPECT_TRUE(RelaxedIntersection(with_empty, 0, 2).IsEmpty());
  EXPECT_EQ(RelaxedIntersection(with_empty, 1, 2), (Box{{0.5, 1}, {1, 1}}));
}

// Random boxes with integer bounds (frequent ties, touching and degenerate
// boxes) against the brute-force grid, in 1 to 4 dimensions.
TEST(RelaxedIntersectionTest, BoxesMatchTheGridOnRandomBoxes) {
  RandomEngine rng(11);
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 1 + trial % 4;
    const int m = UniformInt(rng, 1, n >= 3 ? 7 : 14);
    std::vector<Box> boxes;
    for (int i = 0; i < m; ++i) {
      Box b(n);
      for (std::size_t d = 0; d < n; ++d) {
        const double a = UniformInt(rng, -6, 6), c = UniformInt(rng, -6, 6);
        b[d] = Interval(std::min(a, c), std::max(a, c));
      }
      if (UniformInt(rng, 0, 19) == 0) b.SetEmpty();
      boxes.push_back(b);
    }
    for (int q = 0; q < m; ++q)
      EXPECT_EQ(RelaxedIntersection(boxes, q, n), testing::ReferenceRelaxedIntersection(boxes, q, n))
          << trial << " q=" << q;
  }
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
