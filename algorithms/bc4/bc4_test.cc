#include "algorithms/bc4/bc4.h"

#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/hc4/hc4.h"
#include "problems/chain/chain.h"

namespace icp {
namespace {

Box RunBC4(const ConstraintSystem& csp, ContractSummary* summary = nullptr) {
  Box box = csp.domains();
  BC4Contractor bc4(std::make_shared<CompiledSystem>(csp), BC4Params());
  ContractContext context;
  ContractSummary s = bc4.Contract(box, context);
  if (summary) *summary = s;
  return box;
}

TEST(BC4Test, Paper000DependencyExampleIsContracted) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 4});
  Expr y = csp.AddVariable("y", {-1, 1});
  csp.AddConstraint(x * x + Sqr(y), Relation::kEq, csp.Constant(2));
  ContractSummary s;
  Box box = RunBC4(csp, &s);
  EXPECT_LT(box[0].hi(), std::sqrt(2.0) + 1e-5);
  EXPECT_GE(box[0].hi(), std::sqrt(2.0));
  EXPECT_GT(s.work.newton_steps, 0);  // x occurs twice: BC3 narrowing ran
}

TEST(BC4Test, SingleOccurrencesUseHC4ReviseOnly) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 4});
  Expr y = csp.AddVariable("y", {-1, 1});
  csp.AddConstraint(Sqr(x) + Sqr(y), Relation::kEq, csp.Constant(2));
  ContractSummary s;
  Box box = RunBC4(csp, &s);
  EXPECT_EQ(s.work.newton_steps, 0);
  EXPECT_EQ(s.work.bisections, 0);
  EXPECT_LT(box[0].hi(), std::sqrt(2.0) + 1e-12);
}

TEST(BC4Test, Paper000ThreeBExampleIsAFixpoint) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 2});
  Expr y = csp.AddVariable("y", {-2, 2});
  csp.AddConstraint(x + y, Relation::kEq, csp.Constant(0));
  csp.AddConstraint(x - y, Relation::kEq, csp.Constant(0));
  EXPECT_EQ(RunBC4(csp), csp.domains());
}

// On the car-track CSP every variable occurs once per constraint (paper 000
// §5): BC4 gives exactly HC4's box.
TEST(BC4Test, EqualsHC4OnChainWindows) {
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    ChainParams p;
    p.w = 12;
    Step step = MakeChainStep(p, seed);
    Box bc4 = RunBC4(step.views.csp->csp);
    Box hc4 = step.views.csp->csp.domains();
    ContractContext context;
    HC4Contractor(std::make_shared<CompiledSystem>(step.views.csp->csp), HC4Params())
        .Contract(hc4, context);
    EXPECT_EQ(bc4, hc4) << "seed " << seed;
    EXPECT_TRUE(bc4.Contains(step.csp_truth));
  }
}

}  // namespace
}  // namespace icp
