// Interval: a closed set of reals [lo, hi] with outward-rounded arithmetic.
//
// Built on boost::numeric::interval with the ExactRounding policy (every bound
// is the tightest double enclosing the exact result) and a checking policy in
// which the empty set is the ordinary value [+inf, -inf]: never NaN, never an
// exception. Bounds may be infinite; [+inf, +inf] and [-inf, -inf] are empty
// (no real number lies in them).
#ifndef ICPBENCH_CORE_INTERVAL_H_
#define ICPBENCH_CORE_INTERVAL_H_

#include <bit>
#include <boost/numeric/interval.hpp>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <utility>

#include "core/rounding.h"

namespace icp {

namespace detail {
struct EmptyIsInfinities : boost::numeric::interval_lib::checking_base<double> {
  static double empty_lower() { return kInf; }
  static double empty_upper() { return -kInf; }
  static bool is_empty(double lo, double hi) { return !(lo <= hi); }
};
using BoostInterval = boost::numeric::interval<
    double, boost::numeric::interval_lib::policies<ExactRounding, EmptyIsInfinities>>;
}  // namespace detail

class Interval {
 public:
  // The whole real line.
  Interval() : b_(-kInf, kInf, true) {}
  // The point x (empty if x is NaN or infinite).
  Interval(double x) : Interval(x, x) {}  // NOLINT: implicit on purpose
  // [lo, hi]; empty if lo > hi, a bound is NaN, or it holds no real number.
  Interval(double lo, double hi) {
    if (!(lo <= hi) || lo == kInf || hi == -kInf) {
      b_ = detail::BoostInterval(kInf, -kInf, true);  // Boost's empty() for this policy
    } else {
      b_ = detail::BoostInterval(lo, hi, true);  // checked above: no NaN, lo <= hi
    }
  }
  explicit Interval(const detail::BoostInterval& b) : Interval(b.lower(), b.upper()) {}
  // [lo, hi] where the caller knows that lo <= hi, both finite: no checks.
  enum Ordered { kOrdered };
  Interval(double lo, double hi, Ordered) : b_(lo, hi, true) {}

  static Interval Empty() { return Interval(kInf, -kInf); }
  static Interval Entire() { return Interval(); }

  double lo() const { return b_.lower(); }
  double hi() const { return b_.upper(); }
  bool IsEmpty() const { return !(b_.lower() <= b_.upper()); }
  bool IsPoint() const { return b_.lower() == b_.upper(); }
  bool IsBounded() const { return -kInf < lo() && hi() < kInf; }
  bool Contains(double x) const { return lo() <= x && x <= hi(); }
  bool ContainsZero() const { return Contains(0.0); }
  // Subset of other (the empty set is a subset of everything).
  bool IsSubsetOf(const Interval& other) const {
    return IsEmpty() || (other.lo() <= lo() && hi() <= other.hi());
  }
  // Width rounded up; 0 for the empty set, +inf when unbounded.
  double Width() const;
  // A point inside the interval (0 for the entire line; for half-unbounded
  // intervals, the finite bound moved by a large step).
  double Mid() const;
  // Largest absolute value of a point (0 for the empty set).
  double Mag() const;

  const detail::BoostInterval& boost() const { return b_; }

  friend bool operator==(const Interval& a, const Interval& b) {
    return (a.IsEmpty() && b.IsEmpty()) || (a.lo() == b.lo() && a.hi() == b.hi());
  }

 private:
  detail::BoostInterval b_;
};

// The arithmetic operators, Sqr, Intersect, Hull and the pi constants sit on
// the hot path of every revise; they are inline (definitions below).
Interval operator+(const Interval& x, const Interval& y);
Interval operator-(const Interval& x, const Interval& y);
Interval operator*(const Interval& x, const Interval& y);
// The hull of {a / b : a in x, b in y, b != 0}: the whole line when 0 lies
// inside both, half lines when 0 is a bound of y.
Interval operator/(const Interval& x, const Interval& y);
Interval operator-(const Interval& x);
inline Interval& operator+=(Interval& x, const Interval& y) { return x = x + y; }
inline Interval& operator-=(Interval& x, const Interval& y) { return x = x - y; }
inline Interval& operator*=(Interval& x, const Interval& y) { return x = x * y; }
inline Interval& operator/=(Interval& x, const Interval& y) { return x = x / y; }

Interval Sqr(const Interval& x);
// x^n for any integer n (n < 0 is 1 / x^-n, x^0 is 1).
Interval Pow(const Interval& x, int n);
// The real n-th root, n >= 1: for even n the non-negative root of x ∩ [0, +inf].
Interval Root(const Interval& x, int n);
Interval Sqrt(const Interval& x);
Interval Exp(const Interval& x);
Interval Log(const Interval& x);
Interval Sin(const Interval& x);
Interval Cos(const Interval& x);
Interval Tan(const Interval& x);
Interval Asin(const Interval& x);
Interval Acos(const Interval& x);
Interval Atan(const Interval& x);
Interval Sinh(const Interval& x);
Interval Cosh(const Interval& x);
Interval Tanh(const Interval& x);
Interval Asinh(const Interval& x);
Interval Acosh(const Interval& x);
Interval Atanh(const Interval& x);
Interval Abs(const Interval& x);
Interval Min(const Interval& x, const Interval& y);
Interval Max(const Interval& x, const Interval& y);

Interval Intersect(const Interval& x, const Interval& y);
Interval Hull(const Interval& x, const Interval& y);

// Enclosures of pi, pi/2 and 2 pi.
Interval Pi();
Interval HalfPi();
Interval TwoPi();

// The tightest interval holding the decimal number written in text (e.g.
// "0.1", "-3e-5", "1e400"). Returns false unless text is a real number.
bool ParseDecimal(const std::string& text, Interval* out);

std::ostream& operator<<(std::ostream& os, const Interval& x);

inline double Interval::Width() const {
  if (IsEmpty()) return 0;
  return ExactRounding().sub_up(hi(), lo());
}

// x.Width() and y.Width(), bit for bit, in one SSE2 register where both are
// finite below 2^1020 (propagation compares a variable's widths before and
// after each revise that moved it).
inline std::pair<double, double> Widths(const Interval& x, const Interval& y) {
#if defined(__SSE2__)
  __m128d w;
  if (AddUpPair(_mm_set_pd(y.hi(), x.hi()), _mm_set_pd(-y.lo(), -x.lo()), w))
    return {_mm_cvtsd_f64(w), _mm_cvtsd_f64(_mm_unpackhi_pd(w, w))};
#endif
  return {x.Width(), y.Width()};
}

inline double Interval::Mag() const {
  if (IsEmpty()) return 0;
  const double a = std::fabs(lo()), b = std::fabs(hi());  // not NaN when non-empty
  return a < b ? b : a;
}

// As Boost's operators with the ExactRounding policy, without the wrapper's
// second round of checks.
inline Interval operator+(const Interval& x, const Interval& y) {
  if (x.IsEmpty() || y.IsEmpty()) return Interval::Empty();
  ExactRounding rnd;
  return Interval(rnd.add_down(x.lo(), y.lo()), rnd.add_up(x.hi(), y.hi()));
}
inline Interval operator-(const Interval& x, const Interval& y) {
  if (x.IsEmpty() || y.IsEmpty()) return Interval::Empty();
  ExactRounding rnd;
  return Interval(rnd.sub_down(x.lo(), y.hi()), rnd.sub_up(x.hi(), y.lo()));
}

// x + y and x - y bit for bit, both bounds at once in one SSE2 register
// where AddUpPair can (finite operands below 2^1020, so never an empty
// one's infinite bounds), the lower one as -add_up(-a, -b); the result of
// such operands is ordered and finite, so it needs no check either. Fewer
// instructions than the operators but a longer chain of dependent ones:
// the sweeps over many independent lanes (BC3's, 3B's incremental ones)
// gain from them, HC4's single dependent chain loses (docs/benchmarks.md,
// "HC4 on single windows"), so only those sweeps use them (EvalOp<true>).
#if defined(__SSE2__)
namespace detail {
inline __m128d NegatedLoAndHi(const Interval& x) { return _mm_set_pd(x.hi(), -x.lo()); }
inline __m128d HiAndNegatedLo(const Interval& x) { return _mm_set_pd(-x.lo(), x.hi()); }
inline Interval FromNegatedLoAndHi(__m128d v) {
  return Interval(-_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)), Interval::kOrdered);
}
}  // namespace detail
#endif
inline Interval PairedSum(const Interval& x, const Interval& y) {
#if defined(__SSE2__)
  __m128d sum;
  if (AddUpPair(detail::NegatedLoAndHi(x), detail::NegatedLoAndHi(y), sum))
    return detail::FromNegatedLoAndHi(sum);
#endif
  return x + y;
}
inline Interval PairedDifference(const Interval& x, const Interval& y) {
#if defined(__SSE2__)
  __m128d sum;
  if (AddUpPair(detail::NegatedLoAndHi(x), detail::HiAndNegatedLo(y), sum))
    return detail::FromNegatedLoAndHi(sum);
#endif
  return x - y;
}
inline Interval operator*(const Interval& x, const Interval& y) {
  return Interval(x.boost() * y.boost());
}
inline Interval operator/(const Interval& x, const Interval& y) {
  if (x.IsEmpty() || y.IsEmpty() || (y.lo() == 0 && y.hi() == 0)) return Interval::Empty();
  return Interval(x.boost() / y.boost());
}
inline Interval operator-(const Interval& x) { return Interval(-x.boost()); }
inline Interval Sqr(const Interval& x) { return Interval(boost::numeric::square(x.boost())); }

// Equal bounds, bit for bit (so -0 and +0 differ, as they can in 1 / x): for
// checking that a computation gives the very same result, or may be skipped.
inline bool SameBits(const Interval& a, const Interval& b) {
  return std::bit_cast<std::uint64_t>(a.lo()) == std::bit_cast<std::uint64_t>(b.lo()) &&
         std::bit_cast<std::uint64_t>(a.hi()) == std::bit_cast<std::uint64_t>(b.hi());
}

// Bounds of non-empty intervals are never NaN, so plain comparisons do what
// fmin / fmax would, without the libm call.
inline Interval Intersect(const Interval& x, const Interval& y) {
  if (x.IsEmpty() || y.IsEmpty()) return Interval::Empty();
  return Interval(x.lo() < y.lo() ? y.lo() : x.lo(), x.hi() < y.hi() ? x.hi() : y.hi());
}
inline Interval Hull(const Interval& x, const Interval& y) {
  if (x.IsEmpty()) return y;
  if (y.IsEmpty()) return x;
  return Interval(x.lo() < y.lo() ? x.lo() : y.lo(), x.hi() < y.hi() ? y.hi() : x.hi());
}

inline Interval Pi() {
  static const Interval pi(boost::numeric::interval_lib::pi<detail::BoostInterval>());
  return pi;
}
inline Interval HalfPi() {
  static const Interval half_pi(boost::numeric::interval_lib::pi_half<detail::BoostInterval>());
  return half_pi;
}
inline Interval TwoPi() {
  static const Interval two_pi(boost::numeric::interval_lib::pi_twice<detail::BoostInterval>());
  return two_pi;
}

}  // namespace icp

#endif  // ICPBENCH_CORE_INTERVAL_H_
