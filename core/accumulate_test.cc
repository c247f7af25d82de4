#include "core/accumulate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constraint_contractor.h"
#include "core/contractor_testing.h"
#include "core/random.h"

namespace icp {
namespace {

TEST(GridTest, CellsCoverTheSearchBoxAndBordersBelongToBoth) {
  const Grid grid(Box{{-1, 1}, {0, 3}}, 0, 1, 4, 3);
  EXPECT_EQ(grid.CellX(0).lo(), -1);
  EXPECT_EQ(grid.CellX(3).hi(), 1);
  EXPECT_EQ(grid.CellY(1), Interval(1, 2));
  EXPECT_EQ(grid.ColsMeeting(Interval(0)), (std::pair<int, int>{1, 3}));  // a shared border
  EXPECT_EQ(grid.ColsMeeting(Interval(0.1, 0.2)), (std::pair<int, int>{2, 3}));
  EXPECT_EQ(grid.RowsMeeting(Interval(5, 6)), (std::pair<int, int>{0, 0}));
  int r = 0, c = 0;
  EXPECT_TRUE(grid.CellOf(0.9, 2.5, &r, &c));
  EXPECT_EQ(r, 2);
  EXPECT_EQ(c, 3);
  EXPECT_FALSE(grid.CellOf(2, 2, &r, &c));
  EXPECT_THROW(Grid(Box{{0, kInf}, {0, 1}}, 0, 1, 2, 2), std::invalid_argument);
}

TEST(GridTest, ADegenerateExtentIsCoveredAndMet) {
  // A point and a subnormal width: the cells' common width is 0 or
  // underflows, and the index guess must not divide by it.
  for (const Interval& x :
       {Interval(1, 1), Interval(0, 5e-324), Interval(1, std::nextafter(1.0, 2))}) {
    const Grid grid(Box{x, {0, 1}}, 0, 1, 7, 2);
    EXPECT_EQ(grid.CellX(0).lo(), x.lo());
    EXPECT_EQ(grid.CellX(6).hi(), x.hi());
    for (int c = 0; c < 7; ++c) EXPECT_TRUE(grid.CellX(c).IsSubsetOf(x)) << c;
    for (double t : {x.lo(), x.hi()}) {
      const auto [first, last] = grid.ColsMeeting(Interval(t));
      ASSERT_LT(first, last) << t;
      for (int c = first; c < last; ++c) EXPECT_TRUE(grid.CellX(c).Contains(t)) << t;
    }
    EXPECT_EQ(grid.ColsMeeting(x), (std::pair<int, int>{0, 7}));
    int r = 0, c = 0;
    EXPECT_TRUE(grid.CellOf(x.lo(), 0.5, &r, &c));
    EXPECT_FALSE(grid.CellOf(x.hi() + 1, 0.5, &r, &c));
  }
}

// m random lines cos(a) x + sin(a) y in [c - e, c + e], the first `inliers`
// of them through p.
ConstraintSystem Lines(RandomEngine& rng, int m, int inliers, const std::vector<double>& p) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-10, 10}), y = csp.AddVariable("y", {-10, 10});
  for (int i = 0; i < m; ++i) {
    const double a = UniformReal(rng, 0, M_PI);
    double c = std::cos(a) * p[0] + std::sin(a) * p[1];
    if (i >= inliers) c += UniformReal(rng, 2, 5);
    csp.AddConstraint(std::cos(a) * x + std::sin(a) * y, Interval(c - 0.05, c + 0.05));
  }
  return csp;
}

TEST(AccumulatorTest, CountsEveryLineThroughEachCellAndPeaksAtTheTruth) {
  RandomEngine rng(5);
  const std::vector<double> p = {1.3, -2.7};
  const ConstraintSystem csp = Lines(rng, 12, 8, p);
  const SharedContractors cs = ConstraintContractors(csp);
  const Grid grid(csp.domains(), 0, 1, 80, 60);
  const cv::Mat counts = Accumulate(grid, cs, StopCondition());
  int r = 0, c = 0;
  ASSERT_TRUE(grid.CellOf(p[0], p[1], &r, &c));
  EXPECT_GE(counts.at<std::int32_t>(r, c), 8);
  // Against testing every cell with every contractor: never more, and every
  // point's lines are counted in its cell (prop. 32).
  for (int row = 0; row < grid.rows(); ++row)
    for (int col = 0; col < grid.cols(); ++col) {
      int brute = 0;
      for (const auto& m : cs) {
        Box cell = grid.Block(row, row + 1, col, col + 1);
        ContractContext context;
        m->Contract(cell, context);
        brute += cell.IsEmpty() ? 0 : 1;
      }
      EXPECT_LE(counts.at<std::int32_t>(row, col), brute);
    }
  for (int i = 0; i < 3000; ++i) {
    const std::vector<double> q = {UniformReal(rng, -10, 10), UniformReal(rng, -10, 10)};
    ASSERT_TRUE(grid.CellOf(q[0], q[1], &r, &c));
    EXPECT_GE(counts.at<std::int32_t>(r, c), testing::KeptBy(cs, q));
  }
}

TEST(AccumulatorTest, AStoppedAccumulatorCountsEverything) {
  RandomEngine rng(6);
  const ConstraintSystem csp = Lines(rng, 3, 3, {0, 0});
  const Grid grid(csp.domains(), 0, 1, 10, 10);
  bool stopped = false;
  const cv::Mat counts = Accumulate(grid, ConstraintContractors(csp),
                                    StopCondition::After(std::chrono::seconds(0)), nullptr, &stopped);
  EXPECT_TRUE(stopped);
  EXPECT_EQ(cv::countNonZero(counts == 3), 100);
}

}  // namespace
}  // namespace icp
