// The contraction order of paper 000 §3 on random CSPs with a known
// solution: 3B-BC4 ⊆ BC4 ≈ BC3 ⊆ HC4, up to the precision parameters, and a
// second contraction of a contracted box changes nothing beyond them.
//
// "BC4 ≈ BC3" is, precisely, BC3 ⊆ BC4: for a variable occurring once BC4
// uses HC4Revise, whose backward sweep takes the hull of unions (abs, sqr,
// sin, ...) at inner nodes, while BC3 tests slices on the exact range; so BC3
// can be tighter (e.g. sqrt(abs(cos((-2.875+v3)^3))) = c, random seed 159),
// never looser. On the car-track CSP they coincide (algorithms/bc3/bc3_test.cc).
#include <gtest/gtest.h>

#include <algorithm>

#include "algorithms/registry.h"
#include "tests/random_csp.h"

namespace icp {
namespace {

// Tight settings so that the fixpoints are comparable.
const ParamMap kTight = {{"ratio", "1e-6"}};

Box Contract(const std::string& algorithm, const ConstraintSystem& csp, Box box,
             ParamMap params = kTight) {
  ContractContext context;
  FindAlgorithm(algorithm).contractor(params, csp)->Contract(box, context);
  return box;
}

// a ⊆ b enlarged by tol times the initial width of each component.
::testing::AssertionResult InsideUpTo(const Box& a, const Box& b, const Box& initial, double tol) {
  if (a.IsEmpty()) return ::testing::AssertionSuccess();
  if (b.IsEmpty()) return ::testing::AssertionFailure() << "b is empty, a is not";
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double slack = tol * std::min(initial[i].Width(), 1e6);
    if (a[i].lo() < b[i].lo() - slack || a[i].hi() > b[i].hi() + slack)
      return ::testing::AssertionFailure() << "component " << i << ": " << a[i] << " not in "
                                           << b[i] << " (slack " << slack << ")";
  }
  return ::testing::AssertionSuccess();
}

// BC3 tests slices with the natural interval extension, which is exact for
// single occurrences of continuous operations only; with a divisor interval
// holding 0 HC4's relational projection can be tighter than BC3 (a known
// difference between box and hull consistency). So BC3 is compared on
// continuous operations, the others on everything.
TEST(OrderingTest, ThreeBInsideBC4InsideHC4AndBC3CloseToBC4) {
  int strictly_tighter_3b = 0, strictly_tighter_bc4 = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    testing::RandomCspOptions options;
    options.discontinuous_ops = seed % 2 == 0;
    testing::RandomCsp r = testing::MakeRandomCsp(seed, options);
    const Box& init = r.csp.domains();
    Box hc4 = Contract("hc4", r.csp, init);
    Box bc3 = Contract("bc3", r.csp, init, {{"ratio", "1e-6"}, {"epsilon", "1e-9"}});
    Box bc4 = Contract("bc4", r.csp, init, {{"ratio", "1e-6"}, {"epsilon", "1e-9"}});
    Box tb = Contract("3b-bc4", r.csp, init, {{"inner.ratio", "1e-6"}, {"slices", "8"}});
    ASSERT_TRUE(tb.Contains(r.point)) << "seed " << seed;
    EXPECT_TRUE(InsideUpTo(tb, bc4, init, 1e-4)) << "3B-BC4 vs BC4, seed " << seed;
    EXPECT_TRUE(InsideUpTo(bc4, hc4, init, 1e-4)) << "BC4 vs HC4, seed " << seed;
    if (!options.discontinuous_ops) {
      EXPECT_TRUE(InsideUpTo(bc3, bc4, init, 1e-3)) << "BC3 vs BC4, seed " << seed;
      EXPECT_TRUE(InsideUpTo(bc3, hc4, init, 1e-3)) << "BC3 vs HC4, seed " << seed;
    }
    if (!tb.IsSubsetOf(bc4) || !(tb == bc4)) ++strictly_tighter_3b;
    if (!(bc4 == hc4)) ++strictly_tighter_bc4;
  }
  // The comparison is not vacuous: the stronger consistencies do bite.
  EXPECT_GT(strictly_tighter_3b, 30);
  EXPECT_GT(strictly_tighter_bc4, 30);
}

TEST(OrderingTest, ContractingTwiceChangesNothingBeyondThePrecision) {
  for (const AlgorithmInfo& info : Algorithms()) {
    if (info.test_only || info.contractor == nullptr) continue;
    // LIC solves each ICSP once, alone, with no propagation between them
    // (what paper 004's DIGO adds): a second pass does contract more.
    if (info.name == "lic") continue;
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
      testing::RandomCsp r = testing::MakeRandomCsp(seed);
      auto contractor = info.contractor({}, r.csp);
      Box once = r.csp.domains();
      ContractContext context;
      contractor->Contract(once, context);
      Box twice = once;
      contractor->Contract(twice, context);
      EXPECT_TRUE(InsideUpTo(once, twice, r.csp.domains(), 2e-2))
          << info.name << " seed " << seed;
    }
  }
}

}  // namespace
}  // namespace icp
