#include "algorithms/hc4/hc4.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "problems/chain/chain.h"

namespace icp {
namespace {

ContractSummary RunHC4(const ConstraintSystem& csp, Box& box, HC4Params params = {}) {
  HC4Contractor hc4(std::make_shared<CompiledSystem>(csp), params);
  ContractContext context;
  return hc4.Contract(box, context);
}

// Paper 002 §2.2: x3 = x1 + x2, x1 in [1,4], x2 in [1,2], x3 in [5,7]
// contracts to [3,4] x [1,2] x [5,6].
TEST(HC4Test, Paper002SumExample) {
  ConstraintSystem csp;
  Expr x1 = csp.AddVariable("x1", {1, 4});
  Expr x2 = csp.AddVariable("x2", {1, 2});
  Expr x3 = csp.AddVariable("x3", {5, 7});
  csp.AddConstraint(x3, Relation::kEq, x1 + x2);
  Box box = csp.domains();
  EXPECT_EQ(RunHC4(csp, box).status, ContractStatus::kContracted);
  EXPECT_EQ(box[0], Interval(3, 4));
  EXPECT_EQ(box[1], Interval(1, 2));
  EXPECT_EQ(box[2], Interval(5, 6));
}

// Paper 000 §3.2: x*x + y^2 = 2 on [-2,4] x [-1,1] is not contracted by HC4
// (dependency problem), x^2 + y^2 = 2 is: x in [-sqrt 2, sqrt 2].
TEST(HC4Test, Paper000DependencyExample) {
  ConstraintSystem product;
  Expr x = product.AddVariable("x", {-2, 4});
  Expr y = product.AddVariable("y", {-1, 1});
  product.AddConstraint(x * x + Sqr(y), Relation::kEq, product.Constant(2));
  Box box = product.domains();
  EXPECT_EQ(RunHC4(product, box).status, ContractStatus::kFixpoint);
  EXPECT_EQ(box, product.domains());

  ConstraintSystem square;
  x = square.AddVariable("x", {-2, 4});
  y = square.AddVariable("y", {-1, 1});
  square.AddConstraint(Sqr(x) + Sqr(y), Relation::kEq, square.Constant(2));
  box = square.domains();
  EXPECT_EQ(RunHC4(square, box).status, ContractStatus::kContracted);
  EXPECT_LE(box[0].lo(), -std::sqrt(2.0));
  EXPECT_GE(box[0].hi(), std::sqrt(2.0));
  EXPECT_LT(box[0].hi(), std::sqrt(2.0) + 1e-12);
  EXPECT_EQ(box[1], Interval(-1, 1));
}

// Paper 000 §3.5: x + y = 0, x - y = 0 on [-2,2]^2 is HC4-consistent as it is.
TEST(HC4Test, Paper000ThreeBExampleIsAFixpointForHC4) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 2});
  Expr y = csp.AddVariable("y", {-2, 2});
  csp.AddConstraint(x + y, Relation::kEq, csp.Constant(0));
  csp.AddConstraint(x - y, Relation::kEq, csp.Constant(0));
  Box box = csp.domains();
  EXPECT_EQ(RunHC4(csp, box).status, ContractStatus::kFixpoint);
  EXPECT_EQ(box, csp.domains());
}

TEST(HC4Test, InconsistentSystemGivesAnEmptyBox) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  Expr y = csp.AddVariable("y", {0, 1});
  csp.AddConstraint(x + y, Relation::kEq, csp.Constant(3));
  Box box = csp.domains();
  EXPECT_EQ(RunHC4(csp, box).status, ContractStatus::kEmpty);
  EXPECT_TRUE(box.IsEmpty());
}

// A chain converging geometrically (x = y/2, y = x/2 on [0,1]) stops at the
// revise budget instead of looping, and reports kStopped.
TEST(HC4Test, ReviseBudgetStopsSlowConvergence) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  Expr y = csp.AddVariable("y", {0, 1});
  csp.AddConstraint(x, Relation::kEq, y / 2.0);
  csp.AddConstraint(y, Relation::kEq, x / 2.0);
  Box box = csp.domains();
  HC4Params p;
  p.ratio = 0;
  p.max_revise_calls = 50;
  ContractSummary s = RunHC4(csp, box, p);
  EXPECT_EQ(s.status, ContractStatus::kStopped);
  EXPECT_EQ(s.work.revise_calls, 50);
  EXPECT_TRUE(box.Contains({0, 0}));
  EXPECT_LT(box[0].hi(), 1e-6);
}

TEST(HC4Test, KeepsTheTruthOfChainWindowsAndContractsThem) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    ChainParams p;
    p.w = 20;
    Step step = MakeChainStep(p, seed);
    Box box = step.views.csp->csp.domains();
    ContractSummary s = RunHC4(step.views.csp->csp, box);
    ASSERT_NE(s.status, ContractStatus::kEmpty) << "seed " << seed;
    EXPECT_TRUE(box.Contains(step.csp_truth)) << "seed " << seed;
    EXPECT_TRUE(box.IsSubsetOf(step.views.csp->csp.domains()));
    // Dead reckoning from the start narrows the headings to far less than 2 pi.
    EXPECT_LT(box[3 * p.w + 2].Width(), 7.0);
  }
}

// Told which variables changed in a box at a fixpoint, HC4 revises only what
// they reach: x0 = x1 = x2 and, apart, x3 = x4.
TEST(HC4Test, PropagatesFromTheChangedVariablesOnly) {
  ConstraintSystem csp;
  std::vector<Expr> x;
  for (int i = 0; i < 5; ++i) x.push_back(csp.AddVariable("x" + std::to_string(i), {0, 10}));
  csp.AddConstraint(x[0], Relation::kEq, x[1]);
  csp.AddConstraint(x[1], Relation::kEq, x[2]);
  csp.AddConstraint(x[3], Relation::kEq, x[4]);
  HC4Contractor hc4(std::make_shared<CompiledSystem>(csp), HC4Params());
  Box moved = csp.domains();
  moved[0] = Interval(2, 3);

  Box from_all = moved;
  ContractContext fresh;
  ContractSummary all = hc4.Contract(from_all, fresh);
  Box from_x0 = moved;
  ContractContext x0_changed;
  const int changed[] = {0};
  x0_changed.SetChanged(changed);
  ContractSummary some = hc4.Contract(from_x0, x0_changed);
  EXPECT_EQ(from_x0, from_all);
  EXPECT_EQ(from_x0[2], Interval(2, 3));
  EXPECT_EQ(from_x0[3], Interval(0, 10));
  EXPECT_LT(some.work.revise_calls, all.work.revise_calls);

  ContractContext none_changed;
  none_changed.SetChanged({});
  Box untouched = moved;
  ContractSummary none = hc4.Contract(untouched, none_changed);
  EXPECT_EQ(none.work.revise_calls, 0);
  EXPECT_EQ(none.status, ContractStatus::kFixpoint);
  EXPECT_EQ(untouched, moved);
}

TEST(HC4Test, RegistryBuildsItAndRejectsBadParameters) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  csp.AddConstraint(x, Relation::kEq, csp.Constant(0.5));
  const AlgorithmInfo& info = FindAlgorithm("hc4");
  EXPECT_THROW(info.contractor({{"ratio", "-1"}}, csp), ParamError);
  EXPECT_THROW(info.contractor({{"ratio", "abc"}}, csp), ParamError);
  EXPECT_THROW(info.contractor({{"speed", "1"}}, csp), ParamError);
  auto hc4 = info.contractor({{"ratio", "0.1"}}, csp);
  Box box = csp.domains();
  ContractContext context;
  hc4->Contract(box, context);
  EXPECT_EQ(box[0], Interval(0.5));
  EXPECT_THROW(FindAlgorithm("nope"), std::invalid_argument);
}

}  // namespace
}  // namespace icp
