// One place that maps an operation of the expression DAG to its interval
// evaluation and its backward projection; the tape (HC4Revise) and the
// primitive constraints of HC3 both dispatch through here.
#ifndef ICPBENCH_CORE_OPS_H_
#define ICPBENCH_CORE_OPS_H_

#include "core/argument_contractor.h"
#include "core/expr.h"
#include "core/interval.h"
#include "core/projections.h"

namespace icp {

// z = op(a, b) (b ignored for unary ops, n is kPow's exponent). Not for
// kConst and kVar, which have no operands. kPaired: sums and differences
// through PairedSum and PairedDifference (the same bits; see interval.h for
// which sweeps gain from them).
template <bool kPaired = false>
inline Interval EvalOp(Op op, const Interval& a, const Interval& b, int n) {
  switch (op) {
    case Op::kAdd: return kPaired ? PairedSum(a, b) : a + b;
    case Op::kSub: return kPaired ? PairedDifference(a, b) : a - b;
    case Op::kMul: return a * b;
    case Op::kDiv: return a / b;
    case Op::kMin: return Min(a, b);
    case Op::kMax: return Max(a, b);
    case Op::kAtan2: return Atan2(a, b);
    case Op::kNeg: return -a;
    case Op::kSqr: return Sqr(a);
    case Op::kPow: return Pow(a, n);
    case Op::kSqrt: return Sqrt(a);
    case Op::kExp: return Exp(a);
    case Op::kLog: return Log(a);
    case Op::kSin: return Sin(a);
    case Op::kCos: return Cos(a);
    case Op::kTan: return Tan(a);
    case Op::kAtan: return Atan(a);
    case Op::kSinh: return Sinh(a);
    case Op::kCosh: return Cosh(a);
    case Op::kTanh: return Tanh(a);
    case Op::kAbs: return Abs(a);
    case Op::kConst: case Op::kVar: break;
  }
  return Interval();
}

// Contracts a (and b for binary ops) to the values that can produce some
// value in z. The b argument of a unary op is left untouched. kPaired: as
// EvalOp's.
template <bool kPaired = false>
inline void ProjectOp(Op op, const Interval& z, Interval& a, Interval& b, int n) {
  switch (op) {
    case Op::kAdd: BwdAdd<kPaired>(z, a, b); break;
    case Op::kSub: BwdSub<kPaired>(z, a, b); break;
    case Op::kMul: BwdMul(z, a, b); break;
    case Op::kDiv: BwdDiv(z, a, b); break;
    case Op::kMin: BwdMin(z, a, b); break;
    case Op::kMax: BwdMax(z, a, b); break;
    case Op::kAtan2: BwdAtan2(z, a, b); break;
    case Op::kNeg: BwdNeg(z, a); break;
    case Op::kSqr: BwdSqr(z, a); break;
    case Op::kPow: BwdPow(z, a, n); break;
    case Op::kSqrt: BwdSqrt(z, a); break;
    case Op::kExp: BwdExp(z, a); break;
    case Op::kLog: BwdLog(z, a); break;
    case Op::kSin: BwdSin(z, a); break;
    case Op::kCos: BwdCos(z, a); break;
    case Op::kTan: BwdTan(z, a); break;
    case Op::kAtan: BwdAtan(z, a); break;
    case Op::kSinh: BwdSinh(z, a); break;
    case Op::kCosh: BwdCosh(z, a); break;
    case Op::kTanh: BwdTanh(z, a); break;
    case Op::kAbs: BwdAbs(z, a); break;
    case Op::kConst: case Op::kVar: break;
  }
}

// Whether z = op(a, b) may jump inside the operands' box: a pole of tan,
// of a / b or of a^n (n < 0) inside it, or atan2's branch cut (x <= 0,
// y = 0; atan2(y, x) is a = y, b = x) crossed. There no derivative bounds
// the secants: tan goes from +inf to -inf across a pole, atan2 from pi to
// -pi across the cut.
inline bool MayJump(Op op, const Interval& a, const Interval& b, const Interval& z, int n) {
  switch (op) {
    case Op::kTan: return !z.IsBounded();
    case Op::kDiv: return b.ContainsZero();
    case Op::kPow: return n < 0 && a.ContainsZero();
    case Op::kAtan2: return a.ContainsZero() && b.lo() <= 0;
    default: return false;
  }
}

// Whether a may reach outside the domain of op (sqrt below 0, log at or
// below 0): there f holds values for some points of the box and none for
// others, and the mean-value form that BC3's Newton step rests on (f(t) -
// f(m) = f'(xi) (t - m)) relates no two of them.
inline bool MayLeaveDomain(Op op, const Interval& a) {
  switch (op) {
    case Op::kSqrt: return a.lo() < 0;
    case Op::kLog: return a.lo() <= 0;
    default: return false;
  }
}

// Forward-mode interval differentiation: the derivative of z = op(a, b)
// given the operands' derivatives da, db. At the kinks of abs, min and max
// the result is the hull of the one-sided derivatives, which still bounds
// every slope (what the interval Newton step of BC3 needs). Where z may
// jump (MayJump) or leave its domain (MayLeaveDomain) and depends on the
// variable, any slope is possible: the result is the whole line, so that a
// mean-value step removes nothing.
// (A unary op gets db = da.)
inline Interval RawDerivOp(Op op, const Interval& a, const Interval& b, const Interval& z,
                        const Interval& da, const Interval& db, int n) {
  static const Interval kZero(0.0);
  if ((MayJump(op, a, b, z, n) || MayLeaveDomain(op, a)) && !(da == kZero && db == kZero)) return Interval();
  switch (op) {
    case Op::kAdd: return da + db;
    case Op::kSub: return da - db;
    case Op::kMul: return da * b + a * db;
    case Op::kDiv: return (da - z * db) / b;
    case Op::kMin:
      if (a.hi() < b.lo()) return da;
      if (b.hi() < a.lo()) return db;
      return Hull(da, db);
    case Op::kMax:
      if (a.lo() > b.hi()) return da;
      if (b.lo() > a.hi()) return db;
      return Hull(da, db);
    case Op::kAtan2: return (b * da - a * db) / (Sqr(a) + Sqr(b));
    case Op::kNeg: return -da;
    case Op::kSqr: return Interval(2.0) * a * da;
    case Op::kPow: return Interval(n) * Pow(a, n - 1) * da;
    case Op::kSqrt: return da / (Interval(2.0) * z);
    case Op::kExp: return z * da;
    case Op::kLog: return da / a;
    case Op::kSin: return Cos(a) * da;
    case Op::kCos: return -Sin(a) * da;
    case Op::kTan: return (Interval(1.0) + Sqr(z)) * da;
    case Op::kAtan: return da / (Interval(1.0) + Sqr(a));
    case Op::kSinh: return Cosh(a) * da;
    case Op::kCosh: return Sinh(a) * da;
    case Op::kTanh: return (Interval(1.0) - Sqr(z)) * da;
    case Op::kAbs:
      if (a.lo() >= 0) return da;
      if (a.hi() <= 0) return -da;
      return Interval(-1.0, 1.0) * da;
    case Op::kConst: case Op::kVar: break;
  }
  return Interval();
}

// As RawDerivOp, but never empty: where the derivative is undefined on the
// whole operand (e.g. sqrt at [0, 0]) any slope is possible.
inline Interval DerivOp(Op op, const Interval& a, const Interval& b, const Interval& z,
                        const Interval& da, const Interval& db, int n) {
  Interval d = RawDerivOp(op, a, b, z, da, db, n);
  return d.IsEmpty() ? Interval() : d;
}

}  // namespace icp

#endif  // ICPBENCH_CORE_OPS_H_
