#include "problems/chain/chain.h"

#include <gtest/gtest.h>

#include "core/tape.h"
#include "problems/registry.h"

namespace icp {
namespace {

TEST(ChainTest, HasThreeConstraintsPerStepAndTheTruthInsideTheDomains) {
  ChainParams p;
  p.w = 7;
  Step step = MakeChainStep(p, 42);
  EXPECT_EQ(step.views.csp->csp.num_variables(), 3 * (p.w + 1));
  EXPECT_EQ(step.views.csp->csp.constraints().size(), 3u * p.w);
  ASSERT_EQ(step.csp_truth.size(), static_cast<std::size_t>(step.views.csp->csp.num_variables()));
  EXPECT_TRUE(step.views.csp->csp.domains().Contains(step.csp_truth));
}

TEST(ChainTest, TruthSatisfiesEveryConstraint) {
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    ChainParams p;
    p.w = 10;
    Step step = MakeChainStep(p, seed);
    Box point;
    for (double t : step.csp_truth) point.push_back(Interval(t));
    CompiledSystem sys(step.views.csp->csp);
    std::vector<Interval> slots;
    for (int c = 0; c < sys.num_constraints(); ++c) {
      Interval value = sys.tape(c).Forward(point, slots);
      EXPECT_FALSE(Intersect(value, sys.tape(c).range()).IsEmpty())
          << "seed " << seed << " constraint " << step.views.csp->csp.ConstraintToString(c);
    }
  }
}

TEST(ChainTest, SeedsGiveDifferentDrivesAndTheSameSeedTheSameDrive) {
  ChainParams p;
  EXPECT_EQ(MakeChainStep(p, 1).csp_truth, MakeChainStep(p, 1).csp_truth);
  EXPECT_NE(MakeChainStep(p, 1).csp_truth, MakeChainStep(p, 2).csp_truth);
}

TEST(ChainTest, RegistryRejectsBadParameters) {
  const ProblemInfo& info = FindProblem("chain");
  EXPECT_THROW(info.make({{"w", "0"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"speed", "3"}}, 1), ParamError);
  auto problem = info.make({{"w", "3"}}, 1);
  Step step;
  ASSERT_TRUE(problem->Next(&step));
  EXPECT_EQ(step.views.csp->csp.constraints().size(), 9u);
  EXPECT_FALSE(problem->Next(&step));
}

}  // namespace
}  // namespace icp
