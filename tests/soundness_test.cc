// Property tests: every registered CSP algorithm keeps a known solution of random
// CSPs, and its result lies inside the initial box.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "algorithms/registry.h"
#include "core/minibex_parser.h"
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

// Systems a soundness probe found every algorithm, or some, emptied or cut
// past their solution (2026-12-07), each with a solution known exactly: as
// Minibex text (IBEX's reading, a decimal the real it spells) and the
// solution's coordinates to the nearest double (the box must meet the
// double's two neighbours around it, which enclose the real).
struct ProbeCase {
  const char* why;
  const char* text;
  std::vector<double> solution;
};

const ProbeCase kProbeCases[] = {
    {"two decimals, one enclosure: 0.1 and 0.100000000000000002 are two reals (x = 0.100000000000000001)",
     "Variables x in [0, 1]; Constraints (1e18 * (x - 0.1) - 1)^2 + (1e18 * (x - 0.100000000000000002) + 1)^2 = 0; end",
     {0.1}},
    {"the same across constraints (HC3's auxiliaries): x = -21.87",
     "Variables x in [-30, 0]; Constraints x + 21.87 = 0; 1 / (x + 21.869999999999999) <= 0; end", {-21.87}},
    {"an interval literal twice is two values, as in IBEX",
     "Variables x in [0, 10]; y in [0, 10]; Constraints (x - [1, 2])^2 + (y - [1, 2])^2 = 0; x = 1; y = 2; end",
     {1, 2}},
    {"sqrt defined for some y only at Newton's midpoint (x = 1.00000001, y = 1)",
     "Variables x in [0.5, 3]; y in [0.999, 1.001]; Constraints sqrt(x * y - 1) = 0.0001; end", {1.00000001, 1}},
    {"the same with x twice (BC4's Newton)",
     "Variables x in [0.5, 3]; y in [0.999, 1.001]; Constraints sqrt(x * y - 1) + x = 0.0001 + x; end",
     {1.00000001, 1}},
    {"log's domain crossed the same way (x = 1.00000001, y = 1)",
     "Variables x in [0.5, 3]; y in [0.999, 1.001]; Constraints log(x * y - 1) = log(0.00000001); end",
     {1.00000001, 1}},
};

TEST_P(SoundnessTest, KeepsTheSolutionsOfTheProbesSystems) {
  const AlgorithmInfo& info = FindAlgorithm(GetParam());
  for (const ProbeCase& c : kProbeCases) {
    const ConstraintSystem csp = ParseMinibex(c.text, "probe");
    Box box = csp.domains();
    ContractContext context;
    info.contractor({}, csp)->Contract(box, context);
    ASSERT_FALSE(box.IsEmpty()) << c.why;
    for (std::size_t i = 0; i < c.solution.size(); ++i) {
      const double v = c.solution[i];
      const Interval around(std::nextafter(v, -kInf), std::nextafter(v, kInf));
      EXPECT_FALSE(Intersect(box[i], around).IsEmpty())
          << c.why << ": " << csp.names()[i] << " in [" << box[i].lo() << ", " << box[i].hi() << "]";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllAlgorithms, SoundnessTest, ::testing::ValuesIn(testing::AlgorithmsNeeding(View::kCsp)),
                         testing::RegistryName());

}  // namespace
}  // namespace icp
