#include "algorithms/bc3/bc3.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/hc4/hc4.h"
#include "problems/chain/chain.h"

namespace icp {
namespace {

Box RunBC3(const ConstraintSystem& csp, BC3Params params = {}) {
  Box box = csp.domains();
  BC3Contractor bc3(std::make_shared<CompiledSystem>(csp), params);
  ContractContext context;
  bc3.Contract(box, context);
  return box;
}

// Paper 000 §3.3: y - 2x = 0 on [0,1] x [0,8] gives y in [0,2], x in [0,1].
// (The text writes y - x = 0 but computes with y - 2x; we use the computed one.)
TEST(BC3Test, Paper000WorkedExample) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  Expr y = csp.AddVariable("y", {0, 8});
  csp.AddConstraint(y - 2.0 * x, Relation::kEq, csp.Constant(0));
  BC3Params p;
  Box box = RunBC3(csp, p);
  EXPECT_EQ(box[0], Interval(0, 1));
  EXPECT_EQ(box[1].lo(), 0);
  EXPECT_GE(box[1].hi(), 2);
  EXPECT_LE(box[1].hi(), 2 + p.epsilon * 2);
}

// Paper 000 §3.2: BC3 contracts x*x + y^2 = 2 on [-2,4] x [-1,1] (HC4 cannot):
// x in [-sqrt 2, sqrt 2] up to the precision.
TEST(BC3Test, Paper000DependencyExample) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 4});
  Expr y = csp.AddVariable("y", {-1, 1});
  csp.AddConstraint(x * x + Sqr(y), Relation::kEq, csp.Constant(2));
  BC3Params p;
  Box box = RunBC3(csp, p);
  const double r = std::sqrt(2.0);
  EXPECT_LE(box[0].lo(), -r);
  EXPECT_GE(box[0].hi(), r);
  EXPECT_GT(box[0].lo(), -r - 4 * p.epsilon);
  EXPECT_LT(box[0].hi(), r + 4 * p.epsilon);
  EXPECT_EQ(box[1], Interval(-1, 1));
}

TEST(BC3Test, FindsTheOuterQuasiZerosOfAPeriodicConstraint) {
  // sin(x) = 1 on [0, 10]: the solutions are pi/2 and 5 pi/2.
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 10});
  csp.AddConstraint(Sin(x), Relation::kEq, csp.Constant(1));
  BC3Params p;
  p.epsilon = 1e-9;
  Box box = RunBC3(csp, p);
  const double pi = std::acos(-1.0);
  EXPECT_LE(box[0].lo(), pi / 2);
  EXPECT_GE(box[0].hi(), 5 * pi / 2);
  // sin is flat at its maximum: the quasi-zeros are as wide as sqrt(ulp).
  EXPECT_GT(box[0].lo(), pi / 2 - 1e-6);
  EXPECT_LT(box[0].hi(), 5 * pi / 2 + 1e-6);
}

TEST(BC3Test, InconsistencyGivesEmpty) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-1, 1});
  csp.AddConstraint(x * x - x, Interval(3, 4));  // x^2 - x <= 2 on [-1, 1]
  Box box = RunBC3(csp);
  EXPECT_TRUE(box.IsEmpty());
}

TEST(BC3Test, AConstantConstraintThatFailsEmptiesTheBox) {
  ConstraintSystem csp;
  csp.AddVariable("x", {0, 1});
  csp.AddConstraint(csp.Constant(1), Relation::kEq, csp.Constant(2));
  EXPECT_TRUE(RunBC3(csp).IsEmpty());
}

TEST(BC3Test, InequalitiesKeepTheirFeasibleSide) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-10, 10});
  csp.AddConstraint(x * x, Relation::kLeq, csp.Constant(4));
  Box box = RunBC3(csp);
  EXPECT_LE(box[0].lo(), -2);
  EXPECT_GE(box[0].hi(), 2);
  EXPECT_LT(box[0].hi(), 2 + 1e-5);
}

// Newton's mean-value step needs f continuous on the piece: across a pole
// of tan, of 1/x or of x^-1, or across atan2's branch cut (x < 0, y = 0),
// the derivative's enclosure does not bound the secants, and a step that
// trusted it removed solutions (found by a random-CSP probe).
TEST(BC3Test, KeepsTheSolutionsAcrossAPoleOrABranchCut) {
  const double pi = std::acos(-1.0);
  for (const Interval& domain : {Interval(-1, 3), Interval(-0.5, 8), Interval(-4, 0), Interval(-10, 10)}) {
    ConstraintSystem csp;
    Expr x = csp.AddVariable("x", domain);
    csp.AddConstraint(Tan(x), Relation::kEq, csp.Constant(1));
    const Box box = RunBC3(csp);
    for (int k = -4; k <= 3; ++k) {
      const double solution = pi / 4 + k * pi;
      if (domain.Contains(solution)) EXPECT_TRUE(box[0].Contains(solution)) << domain << " k " << k;
    }
  }
  for (int form = 0; form < 2; ++form) {
    for (const Interval& domain : {Interval(-4, 2), Interval(-1, 3), Interval(-10, 1.5)}) {
      ConstraintSystem csp;
      Expr x = csp.AddVariable("x", domain);
      csp.AddConstraint(form == 0 ? Pow(x, -1) : csp.Constant(1) / x, Interval(0.5, 1));
      const Box box = RunBC3(csp);
      EXPECT_TRUE(box[0].Contains(1)) << domain << " form " << form;
      EXPECT_TRUE(box[0].Contains(std::min(2.0, domain.hi()))) << domain << " form " << form;
    }
  }
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, -0.1});
  Expr y = csp.AddVariable("y", {-1, 1});
  csp.AddConstraint(Atan2(y, x), Relation::kEq, csp.Constant(-3));
  const Box box = RunBC3(csp);
  EXPECT_TRUE(box.Contains({-1, std::tan(3.0)})) << box[0] << " " << box[1];
}

TEST(BC3Test, UnboundedDomainsStaySoundWithinTheBisectionBudget) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", Interval());
  Expr y = csp.AddVariable("y", {1, 2});
  csp.AddConstraint(x * y, Relation::kEq, csp.Constant(4));
  Box box = RunBC3(csp);
  EXPECT_TRUE(box.Contains({2, 2}));
  EXPECT_TRUE(box.Contains({4, 1}));
}

TEST(BC3Test, KeepsTheTruthOfChainWindowsAndMatchesHC4There) {
  for (std::uint64_t seed = 0; seed < 5; ++seed) {
    ChainParams p;
    p.w = 8;
    Step step = MakeChainStep(p, seed);
    Box bc3 = RunBC3(step.views.csp->csp);
    ASSERT_TRUE(bc3.Contains(step.csp_truth)) << "seed " << seed;
    Box hc4 = step.views.csp->csp.domains();
    ContractContext context;
    HC4Contractor(std::make_shared<CompiledSystem>(step.views.csp->csp), HC4Params())
        .Contract(hc4, context);
    for (std::size_t i = 0; i < hc4.size(); ++i)
      EXPECT_NEAR(bc3[i].Width(), hc4[i].Width(), 0.02 * hc4[i].Width() + 1e-5) << "var " << i;
  }
}

}  // namespace
}  // namespace icp
