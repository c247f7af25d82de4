#include "algorithms/polynomial/polynomial.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>

#include "algorithms/q_relaxed/q_relaxed.h"
#include "algorithms/relaxed/relaxed_testing.h"
#include "core/box_polynomial.h"
#include "core/box_polynomial_testing.h"
#include "core/contractor_testing.h"

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
  // Prop. 21 (eq. 4.37): the relaxed composition by its definition (the hull
  // over the subsets of m - q measurements of their composition) is inside
  // one q-relaxed intersection (c1, p = 1), for every q. c2's Horner scheme
  // encloses that definition but may exceed c1 (it is an outer
  // approximation of the composition, not the composition).
  const auto c = Lines(6, 10, 3);
  const MeasurementSetView& set = *c.views.measurement_set;
  const std::vector<Box> composed = testing::ExpandedSortTransform(set.prior, set.measurements);
  const StepResult horner =
      MakePolynomial({{"approximation", "c2"}, {"p", "1"}}, 0)->Step(c.views, StopCondition());
  const StepResult intersected =
      MakePolynomial({{"approximation", "c1"}, {"p", "1"}}, 0)->Step(c.views, StopCondition());
  int strictly_inside = 0;
  for (int q = 0; q <= 10; ++q) {
    const Box& definition = composed[10 - q];
    EXPECT_TRUE(definition.IsSubsetOf(intersected.hulls_by_q[q])) << q;
    EXPECT_TRUE(definition.IsSubsetOf(horner.hulls_by_q[q])) << q;
    strictly_inside += definition != intersected.hulls_by_q[q] ? 1 : 0;
  }
  // Composition narrows where intersection cannot: a strict inclusion somewhere.
  EXPECT_GT(strictly_inside, 0);
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

TEST(PolynomialTest, C2IsTheRepeatedHornerCoefficient) {
  // c2 shares the first pass among the q and computes one coefficient at a
  // time after it: the boxes are those of the plain definition, for every q.
  for (const int p : {1, 2, 10})
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto c = Lines(seed, 14, 4);
      const SharedContractors& ms = c.views.measurement_set->measurements;
      const Box& prior = c.views.measurement_set->prior;
      const int m = static_cast<int>(ms.size());
      const StepResult r = MakePolynomial({{"approximation", "c2"}, {"p", std::to_string(p)}}, 0)
                               ->Step(c.views, StopCondition());
      for (int q = 0; q <= m; ++q) {
        Box expected = prior;
        for (int i = 0; i < p && q < m && !expected.IsEmpty(); ++i) {
          const Box before = expected;
          expected = HornerSortTransform(before, ms, StopCondition())[m - q];
          if (expected == before) break;
        }
        if (expected.IsEmpty()) expected.SetEmpty();
        EXPECT_EQ(r.hulls_by_q[q], expected) << p << " " << seed << " " << q;
      }
    }
}

TEST(PolynomialTest, C2AndC3StopAtTheTimeLimitWithASoundSet) {
  // c3 with p = 10000 (in range) kept evaluating its p m coefficients after
  // the stop condition fired, (p m)^2 / 2 hulls; c2 had no message. Both now
  // return at once, stopped, with every q's set still holding the truth.
  for (const std::string approximation : {"c2", "c3"}) {
    auto c = Lines(8, 3, 0);
    std::atomic<bool> cancel = false;
    auto& ms = c.views.measurement_set->measurements;
    ms = testing::CancelAfterCalls(ms, 200, &cancel);
    const auto start = std::chrono::steady_clock::now();
    const StepResult r = MakePolynomial({{"approximation", approximation}, {"p", "10000"}}, 0)
                             ->Step(c.views, StopCondition().WithCancelFlag(&cancel));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 10) << approximation;
    EXPECT_TRUE(cancel) << approximation;
    EXPECT_EQ(r.summary.status, ContractStatus::kStopped) << approximation;
    EXPECT_NE(r.summary.message.find("time limit"), std::string::npos) << r.summary.message;
    for (const Box& b : r.hulls_by_q) EXPECT_TRUE(b.Contains(c.truth)) << approximation;
  }
}

TEST(PolynomialTest, RejectsBadParameters) {
  EXPECT_THROW(MakePolynomial({{"approximation", "c4"}}, 0), ParamError);
  EXPECT_THROW(MakePolynomial({{"p", "0"}}, 0), ParamError);
}

}  // namespace
}  // namespace icp
