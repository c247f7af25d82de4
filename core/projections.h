// Backward projections: given z = f(x[, y]) and domains for z, x, y, shrink x
// (and y) to the values that can still produce some z. Each projection is sound
// (it never removes a point (x, y) with f(x, y) in z) and returns the operands
// possibly empty. These are the backward sweep of HC4Revise (paper 000 §3.2)
// and the primitive narrowing of HC3 (paper 002 §2.2).
#ifndef ICPBENCH_CORE_PROJECTIONS_H_
#define ICPBENCH_CORE_PROJECTIONS_H_

#include "core/interval.h"

namespace icp {

// The hull of x ∩ {t : t * b = c for some b in y, c in z}: relational
// division, tighter than x ∩ z / y when 0 lies in y.
Interval DivideRelational(const Interval& x, const Interval& z, const Interval& y);

// (BwdAdd, BwdSub and BwdNeg are inline: they run in every revise.)
// kPaired: the differences and sums through PairedDifference and PairedSum,
// the same bits (interval.h says where that is faster).
template <bool kPaired = false>
inline void BwdAdd(const Interval& z, Interval& x, Interval& y) {
  x = Intersect(x, kPaired ? PairedDifference(z, y) : z - y);
  y = Intersect(y, kPaired ? PairedDifference(z, x) : z - x);
}
template <bool kPaired = false>
inline void BwdSub(const Interval& z, Interval& x, Interval& y) {
  x = Intersect(x, kPaired ? PairedSum(z, y) : z + y);
  y = Intersect(y, kPaired ? PairedDifference(x, z) : x - z);
}
void BwdMul(const Interval& z, Interval& x, Interval& y);
void BwdDiv(const Interval& z, Interval& x, Interval& y);
inline void BwdNeg(const Interval& z, Interval& x) { x = Intersect(x, -z); }
void BwdSqr(const Interval& z, Interval& x);
void BwdPow(const Interval& z, Interval& x, int n);
void BwdSqrt(const Interval& z, Interval& x);
void BwdExp(const Interval& z, Interval& x);
void BwdLog(const Interval& z, Interval& x);
void BwdSin(const Interval& z, Interval& x);
void BwdCos(const Interval& z, Interval& x);
void BwdTan(const Interval& z, Interval& x);
void BwdAtan(const Interval& z, Interval& x);
void BwdSinh(const Interval& z, Interval& x);
void BwdCosh(const Interval& z, Interval& x);
void BwdTanh(const Interval& z, Interval& x);
void BwdAbs(const Interval& z, Interval& x);
void BwdMin(const Interval& z, Interval& x, Interval& y);
void BwdMax(const Interval& z, Interval& x, Interval& y);

}  // namespace icp

#endif  // ICPBENCH_CORE_PROJECTIONS_H_
