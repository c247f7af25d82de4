// Property tests: every registered CSP algorithm keeps a known solution of random
// CSPs, and its result lies inside the initial box.
#include <gtest/gtest.h>

#include "algorithms/registry.h"
#include "tests/test_names.h"
#include "tests/random_csp.h"

namespace icp {
namespace {

class SoundnessTest : public ::testing::TestWithParam<std::string> {};

TEST_P(SoundnessTest, NeverRemovesTheKnownSolution) {
  const AlgorithmInfo& info = FindAlgorithm(GetParam());
  int contracted = 0;
  for (std::uint64_t seed = 1; seed <= 3000; ++seed) {
    testing::RandomCsp r = testing::MakeRandomCsp(seed);
    ASSERT_FALSE(r.csp.constraints().empty()) << "seed " << seed;
    auto contractor = info.contractor({}, r.csp);
    Box box = r.csp.domains();
    ContractContext context;
    ContractSummary s = contractor->Contract(box, context);
    ASSERT_NE(s.status, ContractStatus::kEmpty) << "seed " << seed;
    ASSERT_TRUE(box.Contains(r.point)) << "seed " << seed << ": lost the solution";
    ASSERT_TRUE(box.IsSubsetOf(r.csp.domains())) << "seed " << seed;
    if (!(box == r.csp.domains())) ++contracted;
  }
  // The generator makes constraints that bite: most systems contract.
  EXPECT_GT(contracted, 1500);
}

// Inconsistent systems: a constant constraint that fails, a variable forced
// out of its domain, and two constraints that contradict each other.
TEST_P(SoundnessTest, EmptiesTheBoxOfInconsistentSystems) {
  const AlgorithmInfo& info = FindAlgorithm(GetParam());
  std::vector<ConstraintSystem> systems(3);
  for (ConstraintSystem& csp : systems) csp.AddVariable("x", {0, 1});
  systems[0].AddConstraint(systems[0].Constant(1), Relation::kEq, systems[0].Constant(2));
  systems[1].AddConstraint(Sqr(systems[1].Var(0)), Relation::kEq, systems[1].Constant(4));
  Expr y = systems[2].AddVariable("y", {-10, 10});
  systems[2].AddConstraint(y, Relation::kEq, systems[2].Var(0) + 3.0);
  systems[2].AddConstraint(y, Relation::kLeq, systems[2].Constant(2));
  for (std::size_t i = 0; i < systems.size(); ++i) {
    Box box = systems[i].domains();
    ContractContext context;
    ContractSummary s = info.contractor({}, systems[i])->Contract(box, context);
    EXPECT_EQ(s.status, ContractStatus::kEmpty) << "system " << i;
    EXPECT_TRUE(box.IsEmpty()) << "system " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(AllAlgorithms, SoundnessTest, ::testing::ValuesIn(testing::AlgorithmsNeeding(View::kCsp)),
                         testing::RegistryName());

}  // namespace
}  // namespace icp
