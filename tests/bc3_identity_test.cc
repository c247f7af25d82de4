// The optimized BC3 bound search (algorithms/bc3/) against the frozen copy of
// the one it replaced (tests/bc3_reference.h): the same bounds, bit for bit,
// on every (constraint, variable) of seeded random CSPs over random sub-boxes,
// and the same boxes from whole contractions of BC3, BC4 and 3B-BC4 on random
// CSPs and car-track windows. Speed-ups of the search must not move a bound.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>

#include "algorithms/bc3/bc3.h"
#include "algorithms/bc4/bc4.h"
#include "algorithms/three_b/three_b.h"
#include "core/random.h"
#include "problems/chain/chain.h"
#include "tests/bc3_reference.h"
#include "tests/random_csp.h"

namespace icp {
namespace {

std::string Hex(const Interval& x) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%a, %a]", x.lo(), x.hi());
  return buf;
}

// Equal bounds, bit for bit (so -0 and +0 differ); all empty boxes are equal.
::testing::AssertionResult SameBits(const Box& a, const Box& b) {
  if (a.size() != b.size()) return ::testing::AssertionFailure() << "sizes differ";
  if (a.IsEmpty() || b.IsEmpty()) {
    if (a.IsEmpty() == b.IsEmpty()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "only one box is empty";
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i].lo()) != std::bit_cast<std::uint64_t>(b[i].lo()) ||
        std::bit_cast<std::uint64_t>(a[i].hi()) != std::bit_cast<std::uint64_t>(b[i].hi()))
      return ::testing::AssertionFailure()
             << "component " << i << ": " << Hex(a[i]) << " vs " << Hex(b[i]);
  }
  return ::testing::AssertionSuccess();
}

// A random sub-box of box: each component cut at random points, sometimes
// to a point, sometimes kept whole.
Box RandomSubBox(const Box& box, RandomEngine& rng) {
  Box out = box;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Interval& x = box[i];
    switch (UniformIndex(rng, 4)) {
      case 0: break;
      case 1: out[i] = Interval(UniformReal(rng, x.lo(), x.hi())); break;
      default: {
        double a = UniformReal(rng, x.lo(), x.hi()), b = UniformReal(rng, x.lo(), x.hi());
        out[i] = Interval(std::min(a, b), std::max(a, b));
      }
    }
  }
  return out;
}

struct NarrowCase {
  double epsilon;
  int max_bisections;
  testing::RandomCspOptions options;
};

class NarrowIdentityTest : public ::testing::TestWithParam<int> {};

TEST_P(NarrowIdentityTest, SameBoundsAsTheReference) {
  testing::RandomCspOptions deep;
  deep.max_depth = 6;
  testing::RandomCspOptions wide;
  wide.domain_half_width = 1000;
  const NarrowCase cases[] = {{1e-6, 200, {}}, {1e-3, 200, deep}, {1e-9, 200, wide},
                              {1e-6, 3, {}},   {1e-6, 0, deep}};
  const NarrowCase& k = cases[GetParam()];
  BoxNarrower narrower(k.epsilon, k.max_bisections);
  testing::ReferenceBoxNarrower reference(k.epsilon, k.max_bisections);
  RandomEngine rng(1000 + GetParam());
  int narrowed = 0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    testing::RandomCsp r = testing::MakeRandomCsp(seed, k.options);
    CompiledSystem system(r.csp);
    for (int trial = 0; trial < 4; ++trial) {
      const Box box = trial == 0 ? r.csp.domains() : RandomSubBox(r.csp.domains(), rng);
      for (int c = 0; c < system.num_constraints(); ++c) {
        for (int v : system.tape(c).variables()) {
          Box mine = box, theirs = box;
          WorkCounters w1, w2;
          const bool ok = narrower.Narrow(system.tape(c), v, mine, w1);
          const bool ref = reference.Narrow(system.tape(c), v, theirs, w2);
          ASSERT_EQ(ok, ref) << "seed " << seed << " trial " << trial << " c " << c << " v " << v;
          if (ok) {
            ASSERT_TRUE(SameBits(mine, theirs))
                << "seed " << seed << " trial " << trial << " c " << c << " v " << v;
          }
          if (ok && !(mine == box)) ++narrowed;
        }
      }
    }
  }
  EXPECT_GT(narrowed, 500);  // the cases bite
}

INSTANTIATE_TEST_SUITE_P(Cases, NarrowIdentityTest, ::testing::Range(0, 5));

template <class New, class Reference>
void ExpectSameContraction(const ConstraintSystem& csp, const BC3Params& p,
                           const std::string& what) {
  auto system = std::make_shared<CompiledSystem>(csp);
  New mine(system, p);
  Reference theirs(system, p);
  Box a = csp.domains(), b = csp.domains();
  ContractContext c1, c2;
  mine.Contract(a, c1);
  theirs.Contract(b, c2);
  EXPECT_TRUE(SameBits(a, b)) << what;
}

TEST(ContractionIdentityTest, BC3AndBC4OnRandomCsps) {
  for (std::uint64_t seed = 1; seed <= 1500; ++seed) {
    testing::RandomCsp r = testing::MakeRandomCsp(seed);
    const std::string what = "seed " + std::to_string(seed);
    ExpectSameContraction<BC3Contractor, testing::ReferenceBC3Contractor>(r.csp, {}, what);
    ExpectSameContraction<BC4Contractor, testing::ReferenceBC4Contractor>(r.csp, {}, what);
  }
}

TEST(ContractionIdentityTest, BC3OnCarTrackWindows) {
  for (int w : {5, 20}) {
    for (bool heading_known : {false, true}) {
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        ChainParams p;
        p.w = w;
        p.heading_known = heading_known;
        const Step step = MakeChainStep(p, seed);
        ExpectSameContraction<BC3Contractor, testing::ReferenceBC3Contractor>(
            step.views.csp->csp, {}, "w " + std::to_string(w) + " seed " + std::to_string(seed));
      }
    }
  }
}

TEST(ContractionIdentityTest, ThreeBBC4OnRandomCsps) {
  ShavingParams shaving;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    testing::RandomCsp r = testing::MakeRandomCsp(seed);
    auto system = std::make_shared<CompiledSystem>(r.csp);
    ThreeBContractor mine("3b-bc4", std::make_unique<BC4Contractor>(system, BC3Params{}), shaving);
    ThreeBContractor theirs("3b-bc4",
                            std::make_unique<testing::ReferenceBC4Contractor>(system, BC3Params{}),
                            shaving);
    Box a = r.csp.domains(), b = r.csp.domains();
    ContractContext c1, c2;
    mine.Contract(a, c1);
    theirs.Contract(b, c2);
    EXPECT_TRUE(SameBits(a, b)) << "seed " << seed;
  }
}

}  // namespace
}  // namespace icp
