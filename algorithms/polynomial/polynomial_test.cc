#include "algorithms/polynomial/polynomial.h"

#include <gtest/gtest.h>

#include "algorithms/q_relaxed/q_relaxed.h"
#include "algorithms/relaxed/relaxed_testing.h"

namespace icp {
namespace {

using testing::Lines;

TEST(PolynomialTest, EveryApproximationKeepsTheTruthForEveryQ) {
  for (const std::string approximation : {"c1", "c2", "c3"})
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const auto c = Lines(seed, 12, 4);
      const StepResult r = MakePolynomial({{"approximation", approximation}, {"p", "3"}}, 0)
                               ->Step(c.views, StopCondition());
      ASSERT_EQ(r.hulls_by_q.size(), 13u);
      for (int q = 4; q <= 12; ++q)
        EXPECT_TRUE(r.hulls_by_q[q].Contains(c.truth)) << approximation << " " << seed << " " << q;
      // The sets grow with the outliers allowed.
      for (int q = 0; q < 12; ++q)
        EXPECT_TRUE(r.hulls_by_q[q].IsSubsetOf(r.hulls_by_q[q + 1])) << approximation << " " << q;
      EXPECT_TRUE(r.estimate->Contains(c.truth));
    }
}

TEST(PolynomialTest, RelaxedCompositionNestsInsideTheRelaxedIntersection) {
  // Prop. 21: one pass of the relaxed composition (c2, p = 1) is inside one
  // q-relaxed intersection (c1, p = 1), for every q.
  const auto c = Lines(6, 10, 3);
  const StepResult composed =
      MakePolynomial({{"approximation", "c2"}, {"p", "1"}}, 0)->Step(c.views, StopCondition());
  const StepResult intersected =
      MakePolynomial({{"approximation", "c1"}, {"p", "1"}}, 0)->Step(c.views, StopCondition());
  for (int q = 0; q <= 10; ++q)
    EXPECT_TRUE(composed.hulls_by_q[q].IsSubsetOf(intersected.hulls_by_q[q])) << q;
}

TEST(PolynomialTest, AutoQFindsTheFirstNonEmptyCoefficient) {
  const auto c = Lines(7, 20, 7);
  const StepResult r = MakePolynomial({}, 0)->Step(c.views, StopCondition());
  int first = 0;
  while (r.hulls_by_q[first].IsEmpty()) ++first;
  EXPECT_LE(first, 7);
  EXPECT_EQ(r.estimate->Hull(), r.hulls_by_q[first]);
  // Repetition narrows the coefficient of the true q (Fig. 5.2: p = 1 vs 10).
  const StepResult once = MakePolynomial({{"p", "1"}}, 0)->Step(c.views, StopCondition());
  EXPECT_TRUE(r.hulls_by_q[7].IsSubsetOf(once.hulls_by_q[7]));
  EXPECT_LT(BoxArea(r.hulls_by_q[7], 0, 1), BoxArea(once.hulls_by_q[7], 0, 1));
}

TEST(PolynomialTest, RejectsBadParameters) {
  EXPECT_THROW(MakePolynomial({{"approximation", "c4"}}, 0), ParamError);
  EXPECT_THROW(MakePolynomial({{"p", "0"}}, 0), ParamError);
}

}  // namespace
}  // namespace icp
