#include "core/interval.h"

#include <cfenv>
#include <cstdio>
#include <cstdlib>
#include <ostream>

namespace icp {

namespace bn = boost::numeric;
using detail::BoostInterval;

namespace {
constexpr double kMaxDouble = std::numeric_limits<double>::max();

Interval Wrap(const BoostInterval& b) { return Interval(b); }

// x^n rounded up for x >= 0, n >= 1.
double PowUpNonNegative(double x, int n) {
  ExactRounding rnd;
  return bn::interval_lib::detail::pow_up(x, n, rnd);
}
double PowDownNonNegative(double x, int n) {
  ExactRounding rnd;
  return bn::interval_lib::detail::pow_dn(x, n, rnd);
}

// A lower bound of the n-th root of v >= 0: libm's estimate, lowered until its
// n-th power (rounded up) is at most v, so the bound is verified, not trusted.
double RootDown(double v, int n) {
  if (v <= 0) return 0;
  if (v == kInf) return kMaxDouble;
  if (n == 2) return ExactRounding().sqrt_down(v);
  double r = n == 3 ? std::cbrt(v) : std::pow(v, 1.0 / n);
  double ulp = NextUp(r) - r;
  ExactRounding rnd;
  for (double k = 1;; k *= 2) {
    double c = rnd.sub_down(r, k * ulp);
    if (c <= 0) return 0;
    if (PowUpNonNegative(c, n) <= v) return c;
  }
}

// An upper bound of the n-th root of v >= 0, verified the same way.
double RootUp(double v, int n) {
  if (v <= 0) return 0;
  if (v == kInf) return kInf;
  if (n == 2) return ExactRounding().sqrt_up(v);
  double r = n == 3 ? std::cbrt(v) : std::pow(v, 1.0 / n);
  double ulp = NextUp(r) - r;
  ExactRounding rnd;
  for (double k = 1;; k *= 2) {
    double c = rnd.add_up(r, k * ulp);
    if (c == kInf) return kInf;
    if (PowDownNonNegative(c, n) >= v) return c;
  }
}
}  // namespace

double Interval::Width() const {
  if (IsEmpty()) return 0;
  return ExactRounding().sub_up(hi(), lo());
}

double Interval::Mid() const {
  if (IsEmpty()) return 0;
  if (lo() == -kInf && hi() == kInf) return 0;
  if (lo() == -kInf) return hi() >= 0 ? -kMaxDouble / 2 : std::fmax(2 * hi(), -kMaxDouble);
  if (hi() == kInf) return lo() <= 0 ? kMaxDouble / 2 : std::fmin(2 * lo(), kMaxDouble);
  double m = lo() / 2 + hi() / 2;
  return std::fmin(std::fmax(m, lo()), hi());
}

double Interval::Mag() const {
  if (IsEmpty()) return 0;
  return std::fmax(std::fabs(lo()), std::fabs(hi()));
}

Interval operator+(const Interval& x, const Interval& y) { return Wrap(x.boost() + y.boost()); }
Interval operator-(const Interval& x, const Interval& y) { return Wrap(x.boost() - y.boost()); }
Interval operator*(const Interval& x, const Interval& y) { return Wrap(x.boost() * y.boost()); }
Interval operator/(const Interval& x, const Interval& y) {
  if (x.IsEmpty() || y.IsEmpty() || (y.lo() == 0 && y.hi() == 0)) return Interval::Empty();
  return Wrap(x.boost() / y.boost());
}
Interval operator-(const Interval& x) { return Wrap(-x.boost()); }

Interval Sqr(const Interval& x) { return Wrap(bn::square(x.boost())); }

Interval Pow(const Interval& x, int n) {
  if (x.IsEmpty()) return x;
  if (n == 0) return Interval(1.0);
  if (n == 1) return x;
  if (n == 2) return Sqr(x);
  if (n < 0) return Interval(1.0) / Pow(x, -n);
  return Wrap(bn::pow(x.boost(), n));
}

Interval Root(const Interval& x, int n) {
  if (x.IsEmpty() || n < 1) return Interval::Empty();
  if (n == 1) return x;
  if (n % 2 == 0) {
    if (x.hi() < 0) return Interval::Empty();
    return Interval(RootDown(std::fmax(x.lo(), 0.0), n), RootUp(x.hi(), n));
  }
  double lo = x.lo() < 0 ? -RootUp(-x.lo(), n) : RootDown(x.lo(), n);
  double hi = x.hi() < 0 ? -RootDown(-x.hi(), n) : RootUp(x.hi(), n);
  return Interval(lo, hi);
}

Interval Sqrt(const Interval& x) { return Wrap(bn::sqrt(x.boost())); }
Interval Exp(const Interval& x) { return Wrap(bn::exp(x.boost())); }
Interval Log(const Interval& x) { return Wrap(bn::log(x.boost())); }
Interval Sin(const Interval& x) {
  if (!x.IsBounded()) return x.IsEmpty() ? x : Interval(-1, 1);
  return Wrap(bn::sin(x.boost()));
}
Interval Cos(const Interval& x) {
  if (!x.IsBounded()) return x.IsEmpty() ? x : Interval(-1, 1);
  return Wrap(bn::cos(x.boost()));
}
Interval Tan(const Interval& x) {
  if (!x.IsBounded()) return x.IsEmpty() ? x : Interval();
  return Wrap(bn::tan(x.boost()));
}
Interval Asin(const Interval& x) { return Wrap(bn::asin(x.boost())); }
Interval Acos(const Interval& x) { return Wrap(bn::acos(x.boost())); }
Interval Atan(const Interval& x) { return Wrap(bn::atan(x.boost())); }
Interval Sinh(const Interval& x) { return Wrap(bn::sinh(x.boost())); }
Interval Cosh(const Interval& x) { return Wrap(bn::cosh(x.boost())); }
Interval Tanh(const Interval& x) { return Wrap(bn::tanh(x.boost())); }
Interval Asinh(const Interval& x) { return Wrap(bn::asinh(x.boost())); }
Interval Acosh(const Interval& x) { return Wrap(bn::acosh(x.boost())); }
Interval Atanh(const Interval& x) { return Wrap(bn::atanh(x.boost())); }
Interval Abs(const Interval& x) { return Wrap(bn::abs(x.boost())); }
Interval Min(const Interval& x, const Interval& y) {
  if (x.IsEmpty() || y.IsEmpty()) return Interval::Empty();
  return Interval(std::fmin(x.lo(), y.lo()), std::fmin(x.hi(), y.hi()));
}
Interval Max(const Interval& x, const Interval& y) {
  if (x.IsEmpty() || y.IsEmpty()) return Interval::Empty();
  return Interval(std::fmax(x.lo(), y.lo()), std::fmax(x.hi(), y.hi()));
}

Interval Intersect(const Interval& x, const Interval& y) {
  if (x.IsEmpty() || y.IsEmpty()) return Interval::Empty();
  return Interval(std::fmax(x.lo(), y.lo()), std::fmin(x.hi(), y.hi()));
}
Interval Hull(const Interval& x, const Interval& y) {
  if (x.IsEmpty()) return y;
  if (y.IsEmpty()) return x;
  return Interval(std::fmin(x.lo(), y.lo()), std::fmax(x.hi(), y.hi()));
}

Interval Pi() { return Wrap(bn::interval_lib::pi<BoostInterval>()); }
Interval HalfPi() { return Wrap(bn::interval_lib::pi_half<BoostInterval>()); }
Interval TwoPi() { return Wrap(bn::interval_lib::pi_twice<BoostInterval>()); }

bool ParseDecimal(const std::string& text, Interval* out) {
  if (text.empty()) return false;
  // glibc's strtod rounds correctly in the current rounding mode, so parsing
  // once downward and once upward gives the tightest enclosing interval.
  const int saved = std::fegetround();
  char* end = nullptr;
  std::fesetround(FE_DOWNWARD);
  double lo = std::strtod(text.c_str(), &end);
  const bool whole_text = end == text.c_str() + text.size();
  std::fesetround(FE_UPWARD);
  double hi = std::strtod(text.c_str(), nullptr);
  std::fesetround(saved);
  if (!whole_text || std::isnan(lo) || std::isnan(hi)) return false;
  if (std::isinf(lo) && lo == hi) return false;  // "inf" is not a real number
  *out = Interval(lo, hi);
  return true;
}

std::ostream& operator<<(std::ostream& os, const Interval& x) {
  if (x.IsEmpty()) return os << "[empty]";
  char buf[80];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g]", x.lo(), x.hi());
  return os << buf;
}

}  // namespace icp
