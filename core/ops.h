// One place that maps an operation of the expression DAG to its interval
// evaluation and its backward projection; the tape (HC4Revise) and the
// primitive constraints of HC3 both dispatch through here.
#ifndef ICPBENCH_CORE_OPS_H_
#define ICPBENCH_CORE_OPS_H_

#include "core/expr.h"
#include "core/interval.h"
#include "core/projections.h"

namespace icp {

// z = op(a, b) (b ignored for unary ops, n is kPow's exponent). Not for
// kConst and kVar, which have no operands.
inline Interval EvalOp(Op op, const Interval& a, const Interval& b, int n) {
  switch (op) {
    case Op::kAdd: return a + b;
    case Op::kSub: return a - b;
    case Op::kMul: return a * b;
    case Op::kDiv: return a / b;
    case Op::kMin: return Min(a, b);
    case Op::kMax: return Max(a, b);
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
// value in z. The b argument of a unary op is left untouched.
inline void ProjectOp(Op op, const Interval& z, Interval& a, Interval& b, int n) {
  switch (op) {
    case Op::kAdd: BwdAdd(z, a, b); break;
    case Op::kSub: BwdSub(z, a, b); break;
    case Op::kMul: BwdMul(z, a, b); break;
    case Op::kDiv: BwdDiv(z, a, b); break;
    case Op::kMin: BwdMin(z, a, b); break;
    case Op::kMax: BwdMax(z, a, b); break;
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

}  // namespace icp

#endif  // ICPBENCH_CORE_OPS_H_
