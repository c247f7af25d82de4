// Interval: a closed set of reals [lo, hi] with outward-rounded arithmetic.
//
// Built on boost::numeric::interval with the ExactRounding policy (every bound
// is the tightest double enclosing the exact result) and a checking policy in
// which the empty set is the ordinary value [+inf, -inf]: never NaN, never an
// exception. Bounds may be infinite; [+inf, +inf] and [-inf, -inf] are empty
// (no real number lies in them).
#ifndef ICPBENCH_CORE_INTERVAL_H_
#define ICPBENCH_CORE_INTERVAL_H_

#include <boost/numeric/interval.hpp>
#include <iosfwd>
#include <string>

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
      b_ = detail::BoostInterval::empty();
    } else {
      b_.assign(lo, hi);
    }
  }
  explicit Interval(const detail::BoostInterval& b) : Interval(b.lower(), b.upper()) {}

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

}  // namespace icp

#endif  // ICPBENCH_CORE_INTERVAL_H_
