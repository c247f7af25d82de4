#include "core/paving.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/constraint_contractor.h"
#include "core/contractor_algebra.h"
#include "core/random.h"

namespace icp {
namespace {

TEST(PavingTest, ARingIsCoveredByNarrowBoxes) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-3, 3}), y = csp.AddVariable("y", {-3, 3});
  csp.AddConstraint(Sqr(x) + Sqr(y), Interval(1, 4));
  SharedContractors ring = ConstraintContractors(csp);
  const PavingResult paving = Pave(csp.domains(), *ring[0], 0.1, 1000000, StopCondition());
  EXPECT_FALSE(paving.truncated);
  double area = 0;
  for (const Box& b : paving.boxes) {
    EXPECT_LT(b.MaxWidth(), 0.1);
    area += b[0].Width() * b[1].Width();
  }
  // The ring's area is 3 pi; the boxes cover it with a thin margin.
  EXPECT_GT(area, 3 * M_PI);
  EXPECT_LT(area, 3 * M_PI * 1.3);
  RandomEngine rng(1);
  for (int i = 0; i < 2000; ++i) {
    const double r = UniformReal(rng, 1, 2), a = UniformReal(rng, 0, 2 * M_PI);
    const std::vector<double> p = {r * std::cos(a), r * std::sin(a)};
    if (p[0] * p[0] + p[1] * p[1] < 1 || p[0] * p[0] + p[1] * p[1] > 4) continue;
    bool covered = false;
    for (const Box& b : paving.boxes) covered = covered || b.Contains(p);
    EXPECT_TRUE(covered) << p[0] << " " << p[1];
  }
}

TEST(PavingTest, RelaxedPavingSeparatesThePieces) {
  // Three intervals, one of them allowed to miss: the solution is
  // [0.5, 1] u [2, 2.5]; a paving shows the gap that the hull fills.
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-10, 10});
  csp.AddConstraint(x, Interval(0, 1));
  csp.AddConstraint(x, Interval(2, 3));
  csp.AddConstraint(x, Interval(0.5, 2.5));
  QIntersectionContractor relaxed(ConstraintContractors(csp), 1);
  const PavingResult paving = Pave(csp.domains(), relaxed, 0.01, 100000, StopCondition());
  double total = 0;
  for (const Box& b : paving.boxes) {
    total += b[0].Width();
    EXPECT_TRUE(b[0].IsSubsetOf(Interval(0.5, 1)) || b[0].IsSubsetOf(Interval(2, 2.5))) << b[0];
  }
  EXPECT_DOUBLE_EQ(total, 1.0);
}

TEST(PavingTest, MaxBoxesTruncatesSoundly) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-3, 3}), y = csp.AddVariable("y", {-3, 3});
  csp.AddConstraint(Sqr(x) + Sqr(y), Interval(1, 4));
  SharedContractors ring = ConstraintContractors(csp);
  const PavingResult paving = Pave(csp.domains(), *ring[0], 1e-3, 50, StopCondition());
  EXPECT_TRUE(paving.truncated);
  EXPECT_LE(paving.boxes.size(), 50u);
  for (double a = 0; a < 2 * M_PI; a += 0.01) {
    const std::vector<double> p = {1.5 * std::cos(a), 1.5 * std::sin(a)};
    bool covered = false;
    for (const Box& b : paving.boxes) covered = covered || b.Contains(p);
    EXPECT_TRUE(covered);
  }
  EXPECT_THROW(Pave(csp.domains(), *ring[0], 0, 10, StopCondition()), std::invalid_argument);
}

}  // namespace
}  // namespace icp
