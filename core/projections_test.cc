// Worked examples of the backward projections: exact answers where the
// arithmetic is exact, tight enclosures of the known solution sets otherwise.
// Random soundness against MPFR is in core/interval_oracle_test.cc.
#include "core/projections.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace icp {
namespace {

constexpr double kPi = std::numbers::pi;  // just below the real pi

void ExpectBounds(const Interval& x, double lo, double hi) {
  EXPECT_FALSE(x.IsEmpty()) << x;
  EXPECT_EQ(x.lo(), lo) << x;
  EXPECT_EQ(x.hi(), hi) << x;
}

// x holds the real interval [lo, hi] (given to within 1e-15 relative) and is
// wider by at most tol on each side.
void ExpectNear(const Interval& x, double lo, double hi, double tol = 1e-12) {
  EXPECT_FALSE(x.IsEmpty()) << x;
  EXPECT_LE(x.lo(), lo + std::fabs(lo) * 1e-15) << x;
  EXPECT_GE(x.hi(), hi - std::fabs(hi) * 1e-15) << x;
  EXPECT_GE(x.lo(), lo - tol) << x;
  EXPECT_LE(x.hi(), hi + tol) << x;
}

// ---------------------------------------------------------------------------
// Paper 002 §2: x3 = x1 + x2 with x1 in [1, 4], x2 in [1, 2], x3 in [5, 7].

TEST(PaperExample, AdditionFixedPoint) {
  Interval x1(1, 4), x2(1, 2), x3(5, 7);
  // The backward step alone (HC-style projection onto x1 and x2).
  BwdAdd(x3, x1, x2);
  ExpectBounds(x1, 3, 4);
  ExpectBounds(x2, 1, 2);
  // The paper's fixed point [3, 4], [1, 2], [5, 6] needs the forward step:
  x3 = Intersect(x3, x1 + x2);
  ExpectBounds(x3, 5, 6);
  // and one more round changes nothing.
  BwdAdd(x3, x1, x2);
  ExpectBounds(x1, 3, 4);
  ExpectBounds(x2, 1, 2);
  ExpectBounds(Intersect(x3, x1 + x2), 5, 6);
}

TEST(BwdAddSub, ContractBothOperands) {
  Interval x(0, 10), y(5, 6);
  BwdSub(Interval(0, 1), x, y);  // z = x - y
  ExpectBounds(x, 5, 7);
  ExpectBounds(y, 5, 6);
  Interval a(0, 10), b(0, 10);
  BwdAdd(Interval(-3, -1), a, b);  // no non-negative pair sums below 0
  EXPECT_TRUE(a.IsEmpty());
  EXPECT_TRUE(b.IsEmpty());
  Interval n(-10, 10);
  BwdNeg(Interval(2, 3), n);
  ExpectBounds(n, -3, -2);
}

// ---------------------------------------------------------------------------
// Even functions keep both branches.

TEST(BwdSqr, BothBranchesOrOne) {
  Interval x(-10, 10);
  BwdSqr(Interval(1, 4), x);
  ExpectBounds(x, -2, 2);
  x = Interval(0, 10);
  BwdSqr(Interval(1, 4), x);
  ExpectBounds(x, 1, 2);
  x = Interval(-10, -1.5);
  BwdSqr(Interval(1, 4), x);
  ExpectBounds(x, -2, -1.5);
  x = Interval(-10, 10);
  BwdSqr(Interval(-2, -1), x);
  EXPECT_TRUE(x.IsEmpty());
}

TEST(BwdPow, EvenExponent) {
  Interval x(-10, 10);
  BwdPow(Interval(16, 81), x, 4);
  ExpectBounds(x, -3, 3);
  x = Interval(0, 10);
  BwdPow(Interval(16, 81), x, 4);
  ExpectBounds(x, 2, 3);
  x = Interval(-2.5, 10);  // the negative branch [-3, -2] is cut to [-2.5, -2]
  BwdPow(Interval(16, 81), x, 4);
  ExpectBounds(x, -2.5, 3);
}

TEST(BwdPow, OddExponent) {
  Interval x = Interval::Entire();
  BwdPow(Interval(-8, 27), x, 3);
  ExpectBounds(x, -2, 3);
  x = Interval(0, 10);
  BwdPow(Interval(-8, -1), x, 5);
  EXPECT_TRUE(x.IsEmpty());
}

TEST(BwdPow, NegativeExponent) {
  // z = x^-2 in [1/4, 1]: x^2 in [1, 4].
  Interval x(-10, 10);
  BwdPow(Interval(0.25, 1), x, -2);
  ExpectBounds(x, -2, 2);
  x = Interval(0, 10);
  BwdPow(Interval(0.25, 1), x, -2);
  ExpectBounds(x, 1, 2);
  // z = 1 / x in [1/2, 1]: x in [1, 2].
  x = Interval(-10, 10);
  BwdPow(Interval(0.5, 1), x, -1);
  ExpectBounds(x, 1, 2);
  // z = 1 / x in [-1, 1]: |x| >= 1, which on [0.1, 10] leaves [1, 10].
  x = Interval(0.1, 10);
  BwdPow(Interval(-1, 1), x, -1);
  ExpectBounds(x, 1, 10);
  // x^-2 is never negative.
  x = Interval(-10, 10);
  BwdPow(Interval(-2, -1), x, -2);
  EXPECT_TRUE(x.IsEmpty());
}

TEST(BwdPow, ZeroExponent) {
  Interval x(-10, 10);
  BwdPow(Interval(0, 2), x, 0);  // x^0 = 1 for every x
  ExpectBounds(x, -10, 10);
  BwdPow(Interval(2, 3), x, 0);
  EXPECT_TRUE(x.IsEmpty());
}

TEST(BwdAbs, Branches) {
  Interval x(-5, 5);
  BwdAbs(Interval(1, 2), x);
  ExpectBounds(x, -2, 2);
  x = Interval(-5, 0.5);
  BwdAbs(Interval(1, 2), x);
  ExpectBounds(x, -2, -1);
  x = Interval(-5, 5);
  BwdAbs(Interval(-2, -1), x);
  EXPECT_TRUE(x.IsEmpty());
}

TEST(BwdCosh, Branches) {
  Interval x(-10, 10);
  BwdCosh(Interval(1, 1), x);
  ExpectBounds(x, 0, 0);  // acosh(1) = 0 exactly
  x = Interval(-10, 10);
  BwdCosh(Interval(1, std::cosh(2.0)), x);
  ExpectNear(x, -2, 2);
  x = Interval(-10, 10);
  BwdCosh(Interval(0, 0.5), x);
  EXPECT_TRUE(x.IsEmpty());
}

// ---------------------------------------------------------------------------
// Monotone functions.

TEST(BwdMonotone, ExpLogSqrt) {
  Interval x = Interval::Entire();
  BwdExp(Interval(1, std::numbers::e), x);
  ExpectNear(x, 0, 1);
  x = Interval::Entire();
  BwdExp(Interval(-2, -1), x);
  EXPECT_TRUE(x.IsEmpty());
  x = Interval::Entire();
  BwdExp(Interval(-1, 1), x);  // exp > 0 covers only the part (0, 1]
  ExpectBounds(x, -kInf, 0);
  x = Interval::Entire();
  BwdLog(Interval(0, 1), x);
  ExpectNear(x, 1, std::numbers::e);
  x = Interval::Entire();
  BwdSqrt(Interval(2, 3), x);
  ExpectBounds(x, 4, 9);
  x = Interval::Entire();
  BwdSqrt(Interval(-2, -1), x);
  EXPECT_TRUE(x.IsEmpty());
}

TEST(BwdMonotone, HyperbolicAndAtan) {
  Interval x = Interval::Entire();
  BwdSinh(Interval(0, std::sinh(1.0)), x);
  ExpectNear(x, 0, 1);
  x = Interval::Entire();
  BwdTanh(Interval(0, 0.5), x);
  ExpectNear(x, 0, std::atanh(0.5));
  x = Interval::Entire();
  BwdTanh(Interval(2, 3), x);
  EXPECT_TRUE(x.IsEmpty());
  x = Interval::Entire();
  BwdAtan(Interval(0, kPi / 4), x);
  ExpectNear(x, 0, 1);
  // z reaches past pi/2: x is unbounded above.
  x = Interval(-10, 1e300);
  BwdAtan(Interval(1, 2), x);
  EXPECT_NEAR(x.lo(), std::tan(1.0), 1e-14);
  EXPECT_LE(x.lo(), std::tan(1.0) + 1e-15);
  EXPECT_EQ(x.hi(), 1e300);
  x = Interval::Entire();
  BwdAtan(Interval(2, 3), x);
  EXPECT_TRUE(x.IsEmpty());
}

// ---------------------------------------------------------------------------
// Periodic functions.

TEST(BwdSin, PeakOfTwoPeriods) {
  // sin x = 1 on [0, 10]: x in {pi/2, 5 pi/2}, hull [pi/2, 5 pi/2].
  Interval x(0, 10);
  BwdSin(Interval(1, 1), x);
  ExpectNear(x, kPi / 2, 5 * kPi / 2);
  // sin x in [1/2, 1] on [0, 10]: [pi/6, 5 pi/6] and [13 pi/6, 17 pi/6].
  x = Interval(0, 10);
  BwdSin(Interval(0.5, 1), x);
  ExpectNear(x, kPi / 6, 17 * kPi / 6);
  // sin x = 0 on [0.5, 10]: x in {pi, 2 pi, 3 pi}.
  x = Interval(0.5, 10);
  BwdSin(Interval(0, 0), x);
  ExpectNear(x, kPi, 3 * kPi);
  // Out of range.
  x = Interval(0, 10);
  BwdSin(Interval(2, 3), x);
  EXPECT_TRUE(x.IsEmpty());
  // sin >= 0.93 on [1.2, 1.9]: no solution with sin in [-1, 0.5].
  x = Interval(1.2, 1.9);
  BwdSin(Interval(-1, 0.5), x);
  EXPECT_TRUE(x.IsEmpty());
}

TEST(BwdSin, FarFromZero) {
  // sin x = 0 on [1e6, 1e6 + 10]: the multiples of pi from ceil(1e6 / pi).
  Interval x(1e6, 1e6 + 10);
  BwdSin(Interval(0, 0), x);
  double k = std::ceil(1e6 / kPi);
  ExpectNear(x, k * kPi, (k + 3) * kPi, 1e-8);
  EXPECT_GT((k + 4) * kPi, 1e6 + 10);  // (k + 3) pi is the last one in x
}

TEST(BwdCos, PeaksAndTroughs) {
  Interval x(0, 10);
  BwdCos(Interval(1, 1), x);  // x in {0, 2 pi}
  ExpectNear(x, 0, 2 * kPi);
  x = Interval(0, 10);
  BwdCos(Interval(-1, -1), x);  // x in {pi, 3 pi}
  ExpectNear(x, kPi, 3 * kPi);
  x = Interval(-1, 1);
  BwdCos(Interval(0.5, 1), x);  // |x| <= pi/3, all of [-1, 1]
  ExpectBounds(x, -1, 1);
  x = Interval(0.5, 3);
  BwdCos(Interval(0.5, 1), x);  // [0.5, pi/3]
  ExpectNear(x, 0.5, kPi / 3);
}

TEST(BwdTan, BranchesOfPi) {
  Interval x(0, 10);
  BwdTan(Interval(0, 0), x);  // x in {0, pi, 2 pi, 3 pi}
  ExpectNear(x, 0, 3 * kPi);
  x = Interval(0, 3);
  BwdTan(Interval(1, 1), x);  // pi/4 only (5 pi/4 > 3)
  ExpectNear(x, kPi / 4, kPi / 4);
  x = Interval(2, 10);
  BwdTan(Interval(1, kInf), x);  // [5 pi/4, 3 pi/2) and [9 pi/4, 5 pi/2)
  ExpectNear(x, 5 * kPi / 4, 5 * kPi / 2, 1e-9);
}

// ---------------------------------------------------------------------------
// Multiplication and division, including relational division by 0.

TEST(BwdMul, DivisorWithoutZero) {
  Interval x(-10, 10), y(2, 4);
  BwdMul(Interval(4, 8), x, y);  // x = z / y in [1, 4]
  ExpectBounds(x, 1, 4);
  ExpectBounds(y, 2, 4);
}

TEST(BwdMul, ZeroInsideTheOtherFactor) {
  // x * y in [1, 2] with y in [-1, 1]: x = c / b has |x| >= 1; on x in
  // [0.5, 10] only the positive half [1, 10] survives, while z / y alone is
  // the whole line and would not contract x.
  Interval x(0.5, 10), y(-1, 1);
  EXPECT_EQ(Intersect(x, Interval(1, 2) / y), x);
  BwdMul(Interval(1, 2), x, y);
  ExpectBounds(x, 1, 10);
  // y = z / x with x in [1, 10]: [0.1, 2] cut to [0.1, 1].
  ExpectNear(y, 0.1, 1, 1e-16);
}

TEST(BwdMul, AsymmetricDivisor) {
  // y in [-4, 0.25]: c / b lies in (-inf, -0.25] for b < 0 and [4, inf) for
  // b > 0; x in [-0.1, 10] meets only [4, 10].
  EXPECT_EQ(DivideRelational(Interval(-0.1, 10), Interval(1, 2), Interval(-4, 0.25)),
            Interval(4, 10));
  // With x in [-10, 10] both halves meet it and the hull stays [-10, 10].
  EXPECT_EQ(DivideRelational(Interval(-10, 10), Interval(1, 2), Interval(-4, 0.25)),
            Interval(-10, 10));
  // A gap that swallows x entirely.
  EXPECT_TRUE(DivideRelational(Interval(-0.1, 3), Interval(1, 2), Interval(-4, 0.25)).IsEmpty());
}

TEST(BwdMul, ZeroDivisorPoint) {
  // t * 0 = c: only c = 0 has solutions, and then every t is one.
  EXPECT_TRUE(DivideRelational(Interval(-1, 1), Interval(1, 2), Interval(0, 0)).IsEmpty());
  EXPECT_EQ(DivideRelational(Interval(-1, 1), Interval(-1, 2), Interval(0, 0)), Interval(-1, 1));
  Interval x(-1, 1), y(0, 0);
  BwdMul(Interval(1, 2), x, y);
  EXPECT_TRUE(x.IsEmpty());
}

TEST(BwdDiv, BothOperands) {
  Interval x(-10, 10), y(1, 2);
  BwdDiv(Interval(3, 4), x, y);  // x = z * y in [3, 8]
  ExpectBounds(x, 3, 8);
  ExpectBounds(y, 1, 2);
  // y = x / z: x in [2, 3], z in [2, 3] gives y in [2/3, 3/2].
  Interval a(2, 3), b(0, 10);
  BwdDiv(Interval(2, 3), a, b);
  ExpectNear(b, 2.0 / 3, 1.5, 1e-15);
  // z = x / y never 0 unless x is: x in [1, 2] and z in [-1, 0].
  Interval c(1, 2), d(-10, 10);
  BwdDiv(Interval(-1, 0), c, d);
  ExpectBounds(c, 1, 2);
  ExpectBounds(d, -10, -1);
}

// ---------------------------------------------------------------------------
// Min and max.

TEST(BwdMinMax, OneOperandMustBeTheExtremum) {
  Interval x(0, 5), y(3, 6);
  BwdMin(Interval(1, 2), x, y);  // y >= 3 > 2: the min is x
  ExpectBounds(x, 1, 2);
  ExpectBounds(y, 3, 6);
  x = Interval(0, 5);
  y = Interval(-3, 0.5);
  BwdMax(Interval(1, 2), x, y);  // y <= 0.5 < 1: the max is x
  ExpectBounds(x, 1, 2);
  ExpectBounds(y, -3, 0.5);
  // Either could be the min: both only lose what lies below z.
  x = Interval(0, 5);
  y = Interval(-1, 6);
  BwdMin(Interval(1, 2), x, y);
  ExpectBounds(x, 1, 5);
  ExpectBounds(y, 1, 6);
  // min(x, y) >= 10 is impossible with x <= 5.
  x = Interval(0, 5);
  y = Interval(0, 20);
  BwdMin(Interval(10, 11), x, y);
  EXPECT_TRUE(x.IsEmpty());
  EXPECT_TRUE(y.IsEmpty());
}

// ---------------------------------------------------------------------------
// An empty z empties every operand.

TEST(Projections, EmptyZEmptiesOperands) {
  const Interval e = Interval::Empty();
  auto unary = {BwdNeg, BwdSqr,  BwdSqrt, BwdExp,  BwdLog,  BwdSin, BwdCos,
                BwdTan, BwdAtan, BwdSinh, BwdCosh, BwdTanh, BwdAbs};
  for (auto f : unary) {
    Interval x(-1, 1);
    f(e, x);
    EXPECT_TRUE(x.IsEmpty()) << x;
  }
  for (int n = -3; n <= 5; ++n) {
    Interval x(-1, 1);
    BwdPow(e, x, n);
    EXPECT_TRUE(x.IsEmpty()) << "n = " << n << " " << x;
  }
  auto binary = {BwdAdd, BwdSub, BwdMul, BwdDiv, BwdMin, BwdMax};
  for (auto f : binary) {
    Interval x(-1, 1), y(-1, 1);
    f(e, x, y);
    EXPECT_TRUE(x.IsEmpty()) << x;
  }
}

}  // namespace
}  // namespace icp
