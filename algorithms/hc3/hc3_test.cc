#include "algorithms/hc3/hc3.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/hc4/hc4.h"
#include "problems/chain/chain.h"

namespace icp {
namespace {

ContractSummary RunHC3(const ConstraintSystem& csp, Box& box, HC3Params params = {}) {
  HC3Contractor hc3(csp, params);
  ContractContext context;
  return hc3.Contract(box, context);
}

// Paper 002 §2.2, the worked example, step by step: [3,4], [1,2], [5,6].
TEST(HC3Test, Paper002SumExample) {
  ConstraintSystem csp;
  Expr x1 = csp.AddVariable("x1", {1, 4});
  Expr x2 = csp.AddVariable("x2", {1, 2});
  Expr x3 = csp.AddVariable("x3", {5, 7});
  csp.AddConstraint(x3, Relation::kEq, x1 + x2);
  Box box = csp.domains();
  EXPECT_EQ(RunHC3(csp, box).status, ContractStatus::kContracted);
  ASSERT_EQ(box.size(), 3u);  // the auxiliaries stay inside
  EXPECT_EQ(box[0], Interval(3, 4));
  EXPECT_EQ(box[1], Interval(1, 2));
  EXPECT_EQ(box[2], Interval(5, 6));
}

// Paper 000 §3.1: z = cos(2x - y) decomposes into a = 2x, b = a - y,
// z = cos(b): three primitives, two auxiliaries plus the constant 2.
TEST(HC3Test, Paper000DecompositionExample) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  Expr y = csp.AddVariable("y", {0, 1});
  Expr z = csp.AddVariable("z", {-1, 1});
  csp.AddConstraint(z, Relation::kEq, Cos(2.0 * x - y));
  HC3Contractor hc3(csp, HC3Params());
  // 2*x, 2x - y, cos(.), and z - cos(.) = 0.
  EXPECT_EQ(hc3.num_primitives(), 4);
  Box box = csp.domains();
  ContractContext context;
  hc3.Contract(box, context);
  // 2x - y in [-1, 2], so z = cos(.) >= cos(2) ~ -0.416.
  EXPECT_NEAR(box[2].lo(), std::cos(2.0), 1e-9);
  EXPECT_LE(box[2].lo(), std::cos(2.0));
}

// Paper 000 §3.2: neither HC3 nor HC4 contracts x*x + y^2 = 2 on
// [-2,4] x [-1,1]; both contract x^2 + y^2 = 2.
TEST(HC3Test, Paper000DependencyExample) {
  ConstraintSystem product;
  Expr x = product.AddVariable("x", {-2, 4});
  Expr y = product.AddVariable("y", {-1, 1});
  product.AddConstraint(x * x + Sqr(y), Relation::kEq, product.Constant(2));
  Box box = product.domains();
  RunHC3(product, box);
  EXPECT_EQ(box, product.domains());

  ConstraintSystem square;
  x = square.AddVariable("x", {-2, 4});
  y = square.AddVariable("y", {-1, 1});
  square.AddConstraint(Sqr(x) + Sqr(y), Relation::kEq, square.Constant(2));
  box = square.domains();
  RunHC3(square, box);
  EXPECT_LE(box[0].lo(), -std::sqrt(2.0));
  EXPECT_GE(box[0].hi(), std::sqrt(2.0));
  EXPECT_LT(box[0].hi(), std::sqrt(2.0) + 1e-9);
}

TEST(HC3Test, ConstraintOnASingleVariableRestrictsIt) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 10});
  csp.AddConstraint(x, Interval(2, 3));
  Box box = csp.domains();
  RunHC3(csp, box);
  EXPECT_EQ(box[0], Interval(2, 3));
}

TEST(HC3Test, InconsistencyGivesEmpty) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  csp.AddConstraint(Exp(x), Interval(5, 6));
  Box box = csp.domains();
  EXPECT_EQ(RunHC3(csp, box).status, ContractStatus::kEmpty);
  EXPECT_TRUE(box.IsEmpty());
}

// x = x / 2 converges geometrically to 0: the budget stops the shared loop,
// and x keeps what the primitives proved so far.
TEST(HC3Test, ReviseBudgetStopsSlowConvergence) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  csp.AddConstraint(x, Relation::kEq, x / 2.0);
  HC3Params p;
  p.ratio = 0;
  p.max_revise_calls = 200;
  Box box = csp.domains();
  ContractSummary s = RunHC3(csp, box, p);
  EXPECT_EQ(s.status, ContractStatus::kStopped);
  EXPECT_EQ(s.message, "max_revise_calls reached");
  EXPECT_EQ(s.work.revise_calls, 200);
  EXPECT_TRUE(box.Contains({0}));
  EXPECT_LT(box[0].hi(), 1e-6);
}

// On the car-track windows HC3 keeps the truth, and is never tighter than HC4
// beyond the propagation threshold (each variable occurs once per constraint).
TEST(HC3Test, KeepsTheTruthOfChainWindows) {
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    ChainParams p;
    p.w = 10;
    Step step = MakeChainStep(p, seed);
    Box hc3 = step.views.csp->csp.domains();
    ASSERT_NE(RunHC3(step.views.csp->csp, hc3).status, ContractStatus::kEmpty);
    EXPECT_TRUE(hc3.Contains(step.csp_truth)) << "seed " << seed;
    Box hc4 = step.views.csp->csp.domains();
    ContractContext context;
    HC4Contractor(std::make_shared<CompiledSystem>(step.views.csp->csp), HC4Params())
        .Contract(hc4, context);
    for (std::size_t i = 0; i < hc4.size(); ++i)
      EXPECT_LE(hc4[i].Width(), hc3[i].Width() * 1.01 + 1e-9) << "seed " << seed << " var " << i;
  }
}

}  // namespace
}  // namespace icp
