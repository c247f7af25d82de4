// The q-relaxed intersection (paper 003 §2.4.3, §3.6.2): the points that
// belong to all of m sets but at most q of them, i.e. to at least m - q.
// Here q counts the sets allowed to miss (the thesis' convention); IBEX's
// CtcQInter(list, q) and Codac count the sets that must hold instead, so
// their q is m minus ours.
//
// Both overloads return the exact hull of that set, for intervals and for
// boxes (what IBEX's qinter computes), not the thesis' per-dimension hull of
// Fig. 3.5, which may hold points that lie in fewer than m - q boxes. Every
// bound returned is one of the inputs' bounds: no arithmetic, no rounding.
#ifndef ICPBENCH_CORE_RELAXED_INTERSECTION_H_
#define ICPBENCH_CORE_RELAXED_INTERSECTION_H_

#include <span>

#include "core/box.h"

namespace icp {

// The hull of the points that lie in at least m - q of the m closed
// intervals (an empty interval holds no point): sorted bounds, O(m log m).
// q >= m: every point qualifies, the result is the entire line; q < 0 is
// std::invalid_argument.
Interval RelaxedIntersection(std::span<const Interval> intervals, int q);

// The hull of the points that lie in at least m - q of m closed boxes of one
// dimension n (an empty box holds no point). Each bound is found by a sweep
// along its dimension that stops at the first box bound where m - q boxes
// share a point: O(m log m) per bound for n = 2 (a max-add segment tree over
// the other coordinate), O(m^(n-1) log m) for larger n; O(m n) when at
// most one of the non-empty boxes may be left out. With m = 0 or
// q >= m, the entire space of dimension n; q < 0 is std::invalid_argument.
Box RelaxedIntersection(std::span<const Box> boxes, int q, std::size_t n);

}  // namespace icp

#endif  // ICPBENCH_CORE_RELAXED_INTERSECTION_H_
