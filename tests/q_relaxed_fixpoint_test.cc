// q-relaxed's contract mode against the reference fixpoint of the q-relaxed
// intersection of one HC4 contractor per measurement (IBEX's
// CtcFixPoint(CtcQInter), algorithms/q_relaxed/q_relaxed_testing.h) on 48
// line, range and Minibex sets with outliers (tests/q_relaxed_cases.h): its
// hull is never wider than the reference's, for q below, at and above the
// true outlier count, and holds the known solution whenever q is at least
// that count.
#include <gtest/gtest.h>

#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "algorithms/q_relaxed/q_relaxed.h"
#include "algorithms/q_relaxed/q_relaxed_testing.h"
#include "core/relaxed_intersection.h"
#include "tests/q_relaxed_cases.h"

namespace icp {
namespace {

std::string Show(const Box& box) {
  std::string out;
  for (std::size_t d = 0; d < box.size(); ++d)
    out += "[" + testing::Number(box[d].lo()) + ", " + testing::Number(box[d].hi()) + "]";
  return out;
}

TEST(QRelaxedFixpointTest, NeverWiderThanTheReferenceAndKeepsTheTruth) {
  int compared = 0, equal = 0;
  for (const testing::QRelaxedCase& c : testing::QRelaxedCases()) {
    const MeasurementSetView& set = *c.views.measurement_set;
    const int m = static_cast<int>(set.measurements.size());
    for (const int q : {c.outliers - 1, c.outliers, c.outliers + 2}) {
      if (q < 0 || q >= m) continue;
      const StepResult r = MakeQRelaxed({{"q", std::to_string(q)}, {"auto_q", "false"}}, 0)
                               ->Step(c.views, StopCondition());
      const Box ours = r.estimate->Hull();
      const Box reference = testing::ReferenceQRelaxedFixpoint(set.prior, set.measurements, q);
      EXPECT_TRUE(ours.IsSubsetOf(reference)) << c.name << " q=" << q << ": " << Show(ours) << " vs " << Show(reference);
      if (q >= c.outliers) {
        EXPECT_TRUE(r.estimate->Contains(c.truth)) << c.name << " q=" << q;
      }
      ++compared;
      equal += ours == reference ? 1 : 0;
    }
  }
  // Both are the same fixpoint iteration over the exact intersection: equal.
  EXPECT_EQ(equal, compared);
  EXPECT_GE(compared, 100);
}

// The thesis' q-relaxed intersection of boxes (§3.6.2, Fig. 3.5): per
// dimension, the q-relaxed intersection of the components.
Box PerDimension(std::span<const Box> boxes, int q, std::size_t n) {
  Box out(n);
  std::vector<Interval> components(boxes.size());
  for (std::size_t d = 0; d < n; ++d) {
    for (std::size_t i = 0; i < boxes.size(); ++i)
      components[i] = boxes[i].IsEmpty() ? Interval::Empty() : boxes[i][d];
    out[d] = RelaxedIntersection(components, q);
  }
  if (out.IsEmpty()) out.SetEmpty();
  return out;
}

// True when a is wider than b by more than 1 % of b's width in some
// component (or b is empty and a is not).
bool ClearlyWider(const Box& a, const Box& b) {
  if (b.IsEmpty()) return !a.IsEmpty();
  for (std::size_t d = 0; d < a.size(); ++d)
    if (a[d].Width() > 1.01 * b[d].Width()) return true;
  return false;
}

TEST(QRelaxedFixpointTest, ThePerDimensionIntersectionGivesWiderFixpoints) {
  // What made q-relaxed wider than IBEX's fixpoint: the comparison above
  // would fail with it on some of the sets (3 of 129 when written, all
  // with q above the true outliers, where the set has pieces). Both fixpoints stop at the
  // same ratio, so where they converge to one box they differ by no more
  // than that stop rule's residue: only clear differences are counted.
  int wider = 0, compared = 0, narrower = 0;
  for (const testing::QRelaxedCase& c : testing::QRelaxedCases()) {
    const MeasurementSetView& set = *c.views.measurement_set;
    for (const int q : {c.outliers - 1, c.outliers, c.outliers + 2}) {
      if (q < 0 || q >= static_cast<int>(set.measurements.size())) continue;
      const Box exact = testing::ReferenceQRelaxedFixpoint(set.prior, set.measurements, q);
      const Box per_dimension = testing::ReferenceQRelaxedFixpoint(set.prior, set.measurements, q, PerDimension);
      ++compared;
      wider += ClearlyWider(per_dimension, exact) ? 1 : 0;
      narrower += ClearlyWider(exact, per_dimension) ? 1 : 0;
    }
  }
  std::printf("per-dimension fixpoint clearly wider on %d of %d, narrower on %d\n", wider, compared, narrower);
  EXPECT_EQ(narrower, 0);
  EXPECT_GT(wider, 0);
}

}  // namespace
}  // namespace icp
