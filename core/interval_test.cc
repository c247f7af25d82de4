// Unit tests of icp::Interval semantics: the empty value, division by
// intervals holding 0, 0 * inf, Width/Mid/Mag, powers and roots, hull and
// intersection, ParseDecimal, and the dependency example of paper 000 §2.3.
// Random soundness against MPFR is in core/interval_oracle_test.cc.
#include "core/interval.h"

#include "core/random.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>

namespace icp {
namespace {

constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Exact bounds.
void ExpectBounds(const Interval& x, double lo, double hi) {
  EXPECT_FALSE(x.IsEmpty()) << x;
  EXPECT_EQ(x.lo(), lo) << x;
  EXPECT_EQ(x.hi(), hi) << x;
}

// x holds [lo, hi] and is at most a few ulps wider on each side.
void ExpectTightAround(const Interval& x, double lo, double hi, int ulps = 8) {
  EXPECT_LE(x.lo(), lo) << x;
  EXPECT_GE(x.hi(), hi) << x;
  EXPECT_GE(x.lo(), StepDown(lo, ulps)) << x;
  EXPECT_LE(x.hi(), StepUp(hi, ulps)) << x;
}

// ---------------------------------------------------------------------------
// The empty set is a value.

TEST(IntervalEmpty, IsInfinitiesNotNaN) {
  Interval e = Interval::Empty();
  EXPECT_TRUE(e.IsEmpty());
  EXPECT_EQ(e.lo(), kInf);
  EXPECT_EQ(e.hi(), -kInf);
  EXPECT_FALSE(std::isnan(e.lo()));
  EXPECT_FALSE(std::isnan(e.hi()));
  EXPECT_FALSE(e.Contains(0.0));
  EXPECT_EQ(e.Width(), 0);
  EXPECT_EQ(e.Mag(), 0);
  EXPECT_EQ(e, Interval(3, 1));
}

TEST(IntervalEmpty, ConstructionThatHoldsNoReal) {
  EXPECT_TRUE(Interval(kInf, kInf).IsEmpty());
  EXPECT_TRUE(Interval(-kInf, -kInf).IsEmpty());
  EXPECT_TRUE(Interval(kInf).IsEmpty());
  EXPECT_TRUE(Interval(kNaN).IsEmpty());
  EXPECT_TRUE(Interval(kNaN, 1).IsEmpty());
  EXPECT_TRUE(Interval(1, kNaN).IsEmpty());
  EXPECT_TRUE(Interval(2, 1).IsEmpty());
  EXPECT_FALSE(Interval(-kInf, kInf).IsEmpty());
  EXPECT_FALSE(Interval(kMax, kInf).IsEmpty());
  EXPECT_TRUE(Interval::Entire() == Interval());
  EXPECT_FALSE(Interval::Entire().IsBounded());
}

TEST(IntervalEmpty, EveryOperationOnEmptyGivesEmpty) {
  const Interval e = Interval::Empty();
  const Interval x(1, 2);
  for (const Interval& r :
       {e + x,      x + e,      e - x,     x - e,     e * x,           x * e,
        e / x,      x / e,      -e,        Sqr(e),    Pow(e, 3),       Pow(e, 0),
        Pow(e, -2), Root(e, 3), Sqrt(e),   Exp(e),    Log(e),          Sin(e),
        Cos(e),     Tan(e),     Asin(e),   Acos(e),   Atan(e),         Sinh(e),
        Cosh(e),    Tanh(e),    Asinh(e),  Acosh(e),  Atanh(e),        Abs(e),
        Min(e, x),  Min(x, e),  Max(e, x), Max(x, e), Intersect(e, x), Intersect(x, e)}) {
    EXPECT_TRUE(r.IsEmpty()) << r;
    EXPECT_FALSE(std::isnan(r.lo()) || std::isnan(r.hi()));
  }
  EXPECT_EQ(Hull(e, x), x);
  EXPECT_EQ(Hull(x, e), x);
  EXPECT_TRUE(e.IsSubsetOf(x));
  EXPECT_FALSE(x.IsSubsetOf(e));
  std::ostringstream os;
  os << e;
  EXPECT_EQ(os.str(), "[empty]");
}

TEST(IntervalEmpty, OutsideTheDomainGivesEmpty) {
  EXPECT_TRUE(Sqrt(Interval(-4, -1)).IsEmpty());
  EXPECT_TRUE(Log(Interval(-2, -1)).IsEmpty());
  EXPECT_TRUE(Log(Interval(0, 0)).IsEmpty());
  EXPECT_TRUE(Asin(Interval(2, 3)).IsEmpty());
  EXPECT_TRUE(Acos(Interval(-3, -2)).IsEmpty());
  EXPECT_TRUE(Acosh(Interval(0, 0.5)).IsEmpty());
  EXPECT_TRUE(Atanh(Interval(2, 3)).IsEmpty());
  EXPECT_TRUE(Root(Interval(-4, -1), 2).IsEmpty());
}

// ---------------------------------------------------------------------------
// Arithmetic.

TEST(IntervalArithmetic, ExactWhereRepresentable) {
  ExpectBounds(Interval(1, 2) + Interval(3, 4), 4, 6);
  ExpectBounds(Interval(1, 2) - Interval(3, 4), -3, -1);
  ExpectBounds(Interval(-1, 2) * Interval(3, 4), -4, 8);
  ExpectBounds(Interval(-2, -1) * Interval(-3, 4), -8, 6);
  ExpectBounds(Interval(1, 2) / Interval(2, 4), 0.25, 1);
  ExpectBounds(-Interval(1, 2), -2, -1);
}

TEST(IntervalArithmetic, RoundsOutward) {
  Interval third = Interval(1.0) / Interval(3.0);
  EXPECT_EQ(third.hi(), NextUp(third.lo()));
  EXPECT_TRUE(third.Contains(1.0 / 3.0));
  Interval sum = Interval(0.1) + Interval(0.2);  // the doubles nearest 0.1, 0.2
  EXPECT_EQ(sum.hi(), NextUp(sum.lo()));
  EXPECT_TRUE(sum.Contains(0.30000000000000004) || sum.Contains(0.3));
  // Overflow goes to inf on the outer side, DBL_MAX on the inner one.
  ExpectBounds(Interval(kMax) + Interval(kMax), kMax, kInf);
  ExpectBounds(Interval(-kMax) * Interval(kMax), -kInf, -kMax);
}

// operator+, operator- and Widths take a two-lane SSE2 path for finite
// operands below 2^1020 and the scalar ExactRounding calls otherwise: both give
// the same bits (signed zeros included) on each side of that boundary.
double AnyBound(RandomEngine& g) {
  const auto pick = UniformInt(g, 0, 9);
  const double sign = UniformInt(g, 0, 1) ? 1.0 : -1.0;
  if (pick < 4) return sign * std::ldexp(1 + UniformReal(g, 0, 1), UniformInt(g, -60, 60));
  if (pick < 6) return sign * std::ldexp(1 + UniformReal(g, 0, 1), UniformInt(g, 1015, 1023));
  if (pick < 7) return sign * std::bit_cast<double>(UniformInt(g, 1, (std::int64_t{1} << 53)));
  if (pick < 8) return sign * 0.0;
  // 2^1020 +- 2 ulps
  if (pick < 9) return sign * StepUp(StepDown(0x1p1020, 2), UniformInt(g, 0, 4));
  return sign * UniformInt(g, 0, 8);
}

Interval AnyInterval(RandomEngine& g) {
  if (UniformInt(g, 0, 49) == 0) return Interval::Empty();
  double a = AnyBound(g), b = UniformInt(g, 0, 3) ? AnyBound(g) : a;
  if (UniformInt(g, 0, 19) == 0) (UniformInt(g, 0, 1) ? a : b) = kInf;
  return Interval(std::fmin(a, b), std::fmax(a, b));
}

void ExpectSameBits(const Interval& got, const Interval& want) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.lo()), std::bit_cast<std::uint64_t>(want.lo()))
      << got << " vs " << want;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.hi()), std::bit_cast<std::uint64_t>(want.hi()))
      << got << " vs " << want;
}

TEST(IntervalArithmetic, PairedPathsMatchTheScalarRoundingBitForBit) {
  RandomEngine g(20261204);
  ExactRounding rnd;
  for (int i = 0; i < 200000; ++i) {
    const Interval x = AnyInterval(g), y = AnyInterval(g);
    const bool empty = x.IsEmpty() || y.IsEmpty();
    ExpectSameBits(PairedSum(x, y), x + y);
    ExpectSameBits(PairedDifference(x, y), x - y);
    ExpectSameBits(x + y, empty ? Interval::Empty()
                                : Interval(rnd.add_down(x.lo(), y.lo()),
                                           rnd.add_up(x.hi(), y.hi())));
    ExpectSameBits(x - y, empty ? Interval::Empty()
                                : Interval(rnd.sub_down(x.lo(), y.hi()),
                                           rnd.sub_up(x.hi(), y.lo())));
    const auto [wx, wy] = Widths(x, y);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(wx), std::bit_cast<std::uint64_t>(x.Width())) << x;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(wy), std::bit_cast<std::uint64_t>(y.Width())) << y;
    if (HasFailure()) break;
  }
}

TEST(IntervalDivision, ZeroInTheInterior) {
  EXPECT_EQ(Interval(1, 2) / Interval(-1, 1), Interval::Entire());
  EXPECT_EQ(Interval(-1, 2) / Interval(-1, 1), Interval::Entire());
  ExpectBounds(Interval(0, 0) / Interval(-1, 1), 0, 0);
}

TEST(IntervalDivision, ZeroAsABoundGivesAHalfLine) {
  ExpectBounds(Interval(1, 2) / Interval(0, 4), 0.25, kInf);
  ExpectBounds(Interval(1, 2) / Interval(-4, 0), -kInf, -0.25);
  ExpectBounds(Interval(-2, -1) / Interval(0, 4), -kInf, -0.25);
  ExpectBounds(Interval(-2, -1) / Interval(-4, 0), 0.25, kInf);
  ExpectBounds(Interval(0, 0) / Interval(0, 4), 0, 0);
  // A numerator holding 0 in its interior: every real is a quotient.
  EXPECT_EQ(Interval(-1, 2) / Interval(0, 4), Interval::Entire());
}

TEST(IntervalDivision, ByExactZeroIsEmpty) {
  EXPECT_TRUE((Interval(1, 2) / Interval(0, 0)).IsEmpty());
  EXPECT_TRUE((Interval(0, 0) / Interval(0, 0)).IsEmpty());
  EXPECT_TRUE((Interval(-1, 1) / Interval(-0.0, 0.0)).IsEmpty());
  EXPECT_TRUE(Pow(Interval(0, 0), -1).IsEmpty());
}

TEST(IntervalDivision, InfiniteBounds) {
  ExpectBounds(Interval(1, 2) / Interval(1, kInf), 0, 2);
  ExpectBounds(Interval(1, kInf) / Interval(1, 2), 0.5, kInf);
  ExpectBounds(Interval(1, kInf) / Interval(1, kInf), 0, kInf);
}

TEST(IntervalMultiplication, ZeroTimesInfinityIsZero) {
  // Bounds are limits of real values: 0 * x = 0 for every real x.
  ExpectBounds(Interval(0, 0) * Interval(1, kInf), 0, 0);
  ExpectBounds(Interval(1, kInf) * Interval(0, 0), 0, 0);
  ExpectBounds(Interval(0, 0) * Interval::Entire(), 0, 0);
  ExpectBounds(Interval(0, 1) * Interval(1, kInf), 0, kInf);
  ExpectBounds(Interval(-1, 0) * Interval(1, kInf), -kInf, 0);
  EXPECT_EQ(Interval(-1, 1) * Interval(1, kInf), Interval::Entire());
  ExpectBounds(Sqr(Interval(0, kInf)), 0, kInf);
}

// ---------------------------------------------------------------------------
// Width, Mid, Mag.

TEST(IntervalMeasures, Width) {
  EXPECT_EQ(Interval(1, 3).Width(), 2);
  EXPECT_EQ(Interval(5).Width(), 0);
  EXPECT_EQ(Interval(0, kInf).Width(), kInf);
  EXPECT_EQ(Interval::Entire().Width(), kInf);
  EXPECT_EQ(Interval(-kMax, kMax).Width(), kInf);  // rounded up past DBL_MAX
  // Rounded up: 1 - (-1e-30) is not a double.
  EXPECT_EQ(Interval(-1e-30, 1).Width(), NextUp(1.0));
}

TEST(IntervalMeasures, Mid) {
  EXPECT_EQ(Interval(1, 3).Mid(), 2);
  EXPECT_EQ(Interval(7).Mid(), 7);
  EXPECT_EQ(Interval::Entire().Mid(), 0);
  EXPECT_EQ(Interval(-kMax, kMax).Mid(), 0);  // no overflow
  EXPECT_EQ(Interval(kMax, kMax).Mid(), kMax);
  for (const Interval& x :
       {Interval(0, kInf), Interval(5, kInf), Interval(-5, kInf), Interval(-kInf, 0),
        Interval(-kInf, -5), Interval(-kInf, 5), Interval(kMax, kInf),
        Interval(DBL_MIN, NextUp(DBL_MIN)), Interval(-kInf, -kMax)}) {
    double m = x.Mid();
    EXPECT_TRUE(x.Contains(m)) << x << " mid " << m;
    EXPECT_TRUE(std::isfinite(m)) << x;
  }
}

TEST(IntervalMeasures, Mag) {
  EXPECT_EQ(Interval(-3, 2).Mag(), 3);
  EXPECT_EQ(Interval(1, 4).Mag(), 4);
  EXPECT_EQ(Interval(-kInf, 1).Mag(), kInf);
  EXPECT_EQ(Interval(0, 0).Mag(), 0);
}

// ---------------------------------------------------------------------------
// Powers and roots.

TEST(IntervalPow, EvenExponents) {
  ExpectBounds(Pow(Interval(-2, 3), 2), 0, 9);
  ExpectBounds(Pow(Interval(-3, 2), 4), 0, 81);
  ExpectBounds(Pow(Interval(-2, -1), 2), 1, 4);
  ExpectBounds(Pow(Interval(1, 2), 4), 1, 16);
  ExpectBounds(Sqr(Interval(-2, 3)), 0, 9);
  ExpectBounds(Sqr(Interval(-3, -2)), 4, 9);
}

TEST(IntervalPow, OddExponents) {
  ExpectBounds(Pow(Interval(-2, 3), 3), -8, 27);
  ExpectBounds(Pow(Interval(-2, -1), 3), -8, -1);
  ExpectBounds(Pow(Interval(-2, 1), 5), -32, 1);
  ExpectBounds(Pow(Interval(-kInf, 2), 3), -kInf, 8);
}

TEST(IntervalPow, ZeroAndOne) {
  ExpectBounds(Pow(Interval(-2, 3), 0), 1, 1);
  ExpectBounds(Pow(Interval(0, 0), 0), 1, 1);  // x^0 is 1
  ExpectBounds(Pow(Interval(-2, 3), 1), -2, 3);
}

TEST(IntervalPow, NegativeExponents) {
  ExpectBounds(Pow(Interval(2, 4), -1), 0.25, 0.5);
  ExpectBounds(Pow(Interval(-4, -2), -1), -0.5, -0.25);
  ExpectBounds(Pow(Interval(-2, -1), -3), -1, -0.125);
  ExpectBounds(Pow(Interval(1, 2), -2), 0.25, 1);
  ExpectBounds(Pow(Interval(0, 2), -2), 0.25, kInf);
  ExpectBounds(Pow(Interval(-2, 0), -2), 0.25, kInf);
  ExpectBounds(Pow(Interval(-2, 0), -1), -kInf, -0.5);
  ExpectBounds(Pow(Interval(-1, 2), -2), 0.25, kInf);  // x^2 in [0, 4]
  EXPECT_EQ(Pow(Interval(-1, 2), -1), Interval::Entire());
  EXPECT_EQ(Pow(Interval(-1, 2), -3), Interval::Entire());
}

TEST(IntervalRoot, ExactPowersGiveExactRoots) {
  ExpectBounds(Root(Interval(8, 27), 3), 2, 3);
  ExpectBounds(Root(Interval(-8, 27), 3), -2, 3);
  ExpectBounds(Root(Interval(-27, -8), 3), -3, -2);
  ExpectBounds(Root(Interval(16, 81), 4), 2, 3);
  ExpectBounds(Root(Interval(-4, 16), 2), 0, 4);
  ExpectBounds(Root(Interval(-16, 16), 4), 0, 2);
  ExpectBounds(Root(Interval(32, 243), 5), 2, 3);
  ExpectBounds(Root(Interval(0, kInf), 3), 0, kInf);
  ExpectBounds(Root(Interval(-kInf, 0), 3), -kInf, 0);
}

TEST(IntervalRoot, TightAndVerified) {
  // Verification rounds c^n up (down), so the bounds may sit one ulp outside
  // the tightest pair: at most two ulps apart.
  Interval r = Root(Interval(2), 3);
  EXPECT_LE(r.hi(), NextUp(NextUp(r.lo()))) << r;
  EXPECT_LE(Pow(Interval(r.lo()), 3).hi(), 2);
  EXPECT_GE(Pow(Interval(r.hi()), 3).lo(), 2);
  // Large arguments, where libm's pow(v, 1 / n) is off by many ulps.
  Interval big = Root(Interval(1e300), 7);
  EXPECT_LE(big.hi(), NextUp(NextUp(big.lo()))) << big;
  EXPECT_LE(Pow(Interval(big.lo()), 7).hi(), 1e300);
  EXPECT_GE(Pow(Interval(big.hi()), 7).lo(), 1e300);
}

TEST(IntervalRoot, SpecialArguments) {
  EXPECT_EQ(Root(Interval(-3, 5), 1), Interval(-3, 5));
  EXPECT_TRUE(Root(Interval(1, 2), 0).IsEmpty());
  EXPECT_TRUE(Root(Interval(1, 2), -2).IsEmpty());
  ExpectBounds(Sqrt(Interval(-4, 4)), 0, 2);
}

// ---------------------------------------------------------------------------
// Hull and intersection.

TEST(IntervalSetOps, HullAndIntersect) {
  ExpectBounds(Intersect(Interval(1, 3), Interval(2, 4)), 2, 3);
  ExpectBounds(Intersect(Interval(1, 2), Interval(2, 4)), 2, 2);
  EXPECT_TRUE(Intersect(Interval(1, 2), Interval(3, 4)).IsEmpty());
  ExpectBounds(Intersect(Interval::Entire(), Interval(-1, kInf)), -1, kInf);
  ExpectBounds(Hull(Interval(1, 2), Interval(5, 6)), 1, 6);
  ExpectBounds(Hull(Interval(-kInf, 0), Interval(5, 6)), -kInf, 6);
  EXPECT_TRUE(Interval(2, 3).IsSubsetOf(Interval(1, 4)));
  EXPECT_FALSE(Interval(0, 3).IsSubsetOf(Interval(1, 4)));
}

// ---------------------------------------------------------------------------
// Elementary functions: ranges and exact values.

TEST(IntervalElementary, ExactAtKnownPoints) {
  ExpectBounds(Exp(Interval(0.0)), 1, 1);
  ExpectBounds(Log(Interval(1.0)), 0, 0);
  ExpectBounds(Sin(Interval(0.0)), 0, 0);
  ExpectBounds(Cos(Interval(0.0)), 1, 1);
  ExpectBounds(Tan(Interval(0.0)), 0, 0);
  ExpectBounds(Cosh(Interval(0.0)), 1, 1);
  ExpectBounds(Acosh(Interval(1.0)), 0, 0);
  ExpectBounds(Acos(Interval(1.0)), 0, 0);
  ExpectBounds(Atan(Interval(0.0)), 0, 0);
}

TEST(IntervalElementary, MonotoneRanges) {
  ExpectTightAround(Exp(Interval(0, 1)), 1, std::numbers::e);
  ExpectBounds(Exp(Interval(-kInf, 0)), 0, 1);
  Interval big = Exp(Interval(1000));
  EXPECT_EQ(big.hi(), kInf);
  EXPECT_GT(big.lo(), 1e300);
  ExpectBounds(Log(Interval(0, 1)), -kInf, 0);
  ExpectBounds(Log(Interval(-1, 1)), -kInf, 0);
  ExpectTightAround(Atan(Interval::Entire()), -std::numbers::pi / 2, std::numbers::pi / 2);
  ExpectBounds(Tanh(Interval::Entire()), -1, 1);
  ExpectBounds(Atanh(Interval(-1, 1)), -kInf, kInf);
  ExpectTightAround(Asin(Interval(-2, 2)), -std::numbers::pi / 2, std::numbers::pi / 2);
  ExpectTightAround(Acos(Interval(-2, 2)), 0, std::numbers::pi);
  Interval ch = Cosh(Interval(-1, 2));
  EXPECT_EQ(ch.lo(), 1);
  ExpectTightAround(ch, 1, std::cosh(2.0));
  ExpectBounds(Abs(Interval(-3, 2)), 0, 3);
  ExpectBounds(Abs(Interval(-3, -2)), 2, 3);
  ExpectBounds(Min(Interval(1, 5), Interval(2, 3)), 1, 3);
  ExpectBounds(Max(Interval(1, 5), Interval(2, 3)), 2, 5);
}

TEST(IntervalElementary, Trigonometric) {
  constexpr double pi = std::numbers::pi;
  ExpectBounds(Sin(Interval(-kInf, 0)), -1, 1);
  ExpectBounds(Cos(Interval::Entire()), -1, 1);
  EXPECT_EQ(Tan(Interval(0, kInf)), Interval::Entire());
  ExpectBounds(Sin(Interval(0, 7)), -1, 1);  // a full period
  // [0, 3] holds pi/2: the maximum is exactly 1; the minimum is sin 0 = 0.
  Interval s = Sin(Interval(0, 3));
  EXPECT_EQ(s.hi(), 1);
  EXPECT_EQ(s.lo(), 0);
  // [2, 4] holds pi: cos reaches -1.
  Interval c = Cos(Interval(2, 4));
  EXPECT_EQ(c.lo(), -1);
  ExpectTightAround(c, -1, std::cos(2.0));
  // Monotone piece: tight.
  ExpectTightAround(Sin(Interval(0.5, 1.0)), std::sin(0.5), std::sin(1.0));
  ExpectTightAround(Tan(Interval(-1, 1)), std::tan(-1.0), std::tan(1.0));
  // A pole inside: tan takes every value.
  EXPECT_EQ(Tan(Interval(1, 2)), Interval::Entire());
  EXPECT_EQ(Tan(Interval(-2, -1)), Interval::Entire());
  EXPECT_EQ(Tan(Interval(0, 4)), Interval::Entire());
  // Close to, but below, the pole: finite and huge. (The double nearest pi/2
  // is the lower bound of HalfPi(), so an interval reaching it may hold the
  // pole as far as the enclosure can tell.)
  Interval near = Tan(Interval(1.5, NextDown(pi / 2)));
  EXPECT_TRUE(near.IsBounded()) << near;
  EXPECT_GT(near.hi(), 1e15);
  // Far from 0 a point stays a few ulps wide.
  Interval far = Sin(Interval(1e15));
  ExpectTightAround(far, std::sin(1e15), std::sin(1e15));
}

// ---------------------------------------------------------------------------
// Paper 000 §2.3, the dependency problem.
//
// The paper writes eq. (2) as f(x) = x^2 + 2x + 4, but its numbers
// f_[](I) = [-8, 36] and f_[],2(I) = [0, 36] on I = [-3, 4] are those of
// x^2 + 4x + 4, whose factored form (x + 2)^2 is eq. (4). Both polynomials
// are checked; x^2 is the square (Sqr), not x * x.

TEST(PaperDependency, NaturalVersusFactored) {
  const Interval x(-3, 4);
  ExpectBounds(Sqr(x) + Interval(4) * x + Interval(4), -8, 36);
  ExpectBounds(Sqr(x + Interval(2)), 0, 36);
  // As printed: x^2 + 2x + 4 gives [0, 16] + [-6, 8] + 4.
  ExpectBounds(Sqr(x) + Interval(2) * x + Interval(4), -2, 28);
  // With x * x instead of Sqr the natural extension is even wider.
  ExpectBounds(x * x + Interval(4) * x + Interval(4), -20, 36);
}

// ---------------------------------------------------------------------------
// ParseDecimal.

TEST(ParseDecimal, InexactDecimalGivesAdjacentDoubles) {
  Interval x;
  ASSERT_TRUE(ParseDecimal("0.1", &x));
  EXPECT_LT(x.lo(), x.hi());
  EXPECT_EQ(x.hi(), NextUp(x.lo()));
  EXPECT_TRUE(x.Contains(0.1));  // the double nearest 0.1 is one of the bounds
  // 0.1 = 0x1.999...9ap-4 rounded to nearest (up): the lower bound is below.
  EXPECT_EQ(x.hi(), 0.1);
  EXPECT_EQ(x.lo(), NextDown(0.1));
  ASSERT_TRUE(ParseDecimal("-0.1", &x));
  EXPECT_EQ(x.lo(), -0.1);
  EXPECT_EQ(x.hi(), NextUp(-0.1));
}

TEST(ParseDecimal, ExactDecimalGivesAPoint) {
  Interval x;
  ASSERT_TRUE(ParseDecimal("0.5", &x));
  ExpectBounds(x, 0.5, 0.5);
  ASSERT_TRUE(ParseDecimal("-3e2", &x));
  ExpectBounds(x, -300, -300);
  ASSERT_TRUE(ParseDecimal("0", &x));
  ExpectBounds(x, 0, 0);
  ASSERT_TRUE(ParseDecimal("1.25E-1", &x));
  ExpectBounds(x, 0.125, 0.125);
}

TEST(ParseDecimal, OverflowAndUnderflow) {
  Interval x;
  ASSERT_TRUE(ParseDecimal("1e400", &x));
  ExpectBounds(x, kMax, kInf);
  ASSERT_TRUE(ParseDecimal("-1e400", &x));
  ExpectBounds(x, -kInf, -kMax);
  ASSERT_TRUE(ParseDecimal("1e-400", &x));
  ExpectBounds(x, 0, std::numeric_limits<double>::denorm_min());
}

TEST(ParseDecimal, RejectsNonNumbers) {
  Interval x(7);
  EXPECT_FALSE(ParseDecimal("abc", &x));
  EXPECT_FALSE(ParseDecimal("inf", &x));
  EXPECT_FALSE(ParseDecimal("-inf", &x));
  EXPECT_FALSE(ParseDecimal("infinity", &x));
  EXPECT_FALSE(ParseDecimal("nan", &x));
  EXPECT_FALSE(ParseDecimal("", &x));
  EXPECT_FALSE(ParseDecimal("1.5x", &x));
  EXPECT_FALSE(ParseDecimal("1e", &x));
  ExpectBounds(x, 7, 7);  // untouched on failure
}

TEST(ParseDecimal, LeavesTheRoundingModeAlone) {
  Interval x;
  ASSERT_TRUE(ParseDecimal("0.3", &x));
  volatile double a = 1.0, b = 3.0;  // divided at run time, round-to-nearest
  EXPECT_EQ(a / b, 0x1.5555555555555p-2);
}

}  // namespace
}  // namespace icp
