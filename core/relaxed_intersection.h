// The q-relaxed intersection (paper 003 §2.4.3, §3.6.2): the points that
// belong to all of m sets but at most q of them, i.e. to at least m - q.
// Here q counts the sets allowed to miss (the thesis' convention); IBEX's
// CtcQInter(list, q) and Codac count the sets that must hold instead, so
// their q is m minus ours.
//
// Of intervals it is computed exactly as the hull of that union of pieces
// (sorted bounds, O(m log m)); of boxes, per dimension (the hull of the
// q-relaxed intersection of the components, which may hold points that lie
// in fewer than m - q boxes: Fig. 3.5's pessimism, sound).
#ifndef ICPBENCH_CORE_RELAXED_INTERSECTION_H_
#define ICPBENCH_CORE_RELAXED_INTERSECTION_H_

#include <span>

#include "core/box.h"

namespace icp {

// The hull of the points that lie in at least m - q of the m intervals (an
// empty interval holds no point). q >= m: every point qualifies, the result
// is the entire line; q < 0 is std::invalid_argument.
Interval RelaxedIntersection(std::span<const Interval> intervals, int q);

// The per-dimension q-relaxed intersection of m boxes of one dimension n (an
// empty box holds no point in any dimension); empty in every component when
// some component is. With m = 0 or q >= m, the entire space of dimension n.
Box RelaxedIntersection(std::span<const Box> boxes, int q, std::size_t n);

}  // namespace icp

#endif  // ICPBENCH_CORE_RELAXED_INTERSECTION_H_
