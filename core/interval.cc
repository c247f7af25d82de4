#include "core/interval.h"

#include <bit>
#include <cfenv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
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

// Given ok(good) and !ok(bad) for a monotone predicate on doubles >= 0,
// bisects on the bit patterns (ordered like the values) down to two adjacent
// doubles and returns the one that passes.
template <class Ok>
double Bisect(double good, double bad, Ok ok) {
  auto g = std::bit_cast<std::uint64_t>(good);
  auto b = std::bit_cast<std::uint64_t>(bad);
  while (g + 1 < b || b + 1 < g) {
    std::uint64_t m = g < b ? g + (b - g) / 2 : b + (g - b) / 2;
    if (ok(std::bit_cast<double>(m))) {
      g = m;
    } else {
      b = m;
    }
  }
  return std::bit_cast<double>(g);
}

// A lower bound of the n-th root of v >= 0: the largest double c with c^n
// (rounded up) at most v, so the bound is verified, not trusted. libm's
// estimate is bracketed by steps of 1, 2, 4, ... ulps, then bisected (a libm
// pow(v, 1 / n) may be ~100 ulps off for large v, and stopping at the first
// verified step lost up to that much again).
double RootDown(double v, int n) {
  if (v <= 0) return 0;
  if (v == kInf) return kMaxDouble;
  if (n == 2) return ExactRounding().sqrt_down(v);
  auto ok = [&](double c) { return PowUpNonNegative(c, n) <= v; };
  double r = n == 3 ? std::cbrt(v) : std::pow(v, 1.0 / n);
  double ulp = NextUp(r) - r;
  ExactRounding rnd;
  if (ok(r)) {
    for (double k = 1;; k *= 2) {
      double c = rnd.add_up(r, k * ulp);
      if (!ok(c)) return Bisect(r, c, ok);  // ok(inf) is false: v < inf
    }
  }
  for (double k = 1;; k *= 2) {
    double c = rnd.sub_down(r, k * ulp);
    if (c <= 0) return Bisect(0.0, r, ok);
    if (ok(c)) return Bisect(c, r, ok);
  }
}

// An upper bound of the n-th root of v >= 0: the smallest double c with c^n
// (rounded down) at least v, found the same way.
double RootUp(double v, int n) {
  if (v <= 0) return 0;
  if (v == kInf) return kInf;
  if (n == 2) return ExactRounding().sqrt_up(v);
  auto ok = [&](double c) { return PowDownNonNegative(c, n) >= v; };
  double r = n == 3 ? std::cbrt(v) : std::pow(v, 1.0 / n);
  double ulp = NextUp(r) - r;
  ExactRounding rnd;
  if (ok(r)) {
    for (double k = 1;; k *= 2) {
      double c = rnd.sub_down(r, k * ulp);
      if (c <= 0) return Bisect(r, 0.0, ok);  // ok(0) is false: v > 0
      if (!ok(c)) return Bisect(r, c, ok);
    }
  }
  for (double k = 1;; k *= 2) {
    double c = rnd.add_up(r, k * ulp);
    if (ok(c)) return Bisect(c, r, ok);  // ok(inf) is true
  }
}

// Sin, cos and tan evaluate libm at the bounds (glibc reduces arguments
// exactly, so this stays accurate for huge bounds) and locate interior extrema
// and poles with an enclosure of pi / 2. Boost's versions reduce the argument
// with an enclosure of 2 pi, which costs about |x| * 1e-16 of width (3e-10 at
// |x| = 1e6) and made sin(0.5) 40 ulps wide.
//
// Beyond kTrigFar a non-point interval is at least 0.25 wide and multiples of
// pi / 2 are too coarse to locate; such bounds give the whole range.
constexpr double kTrigFar = 0x1p50;
constexpr double kHalfPiApprox = std::numbers::pi / 2;  // only to count multiples

// Whether x may contain m * pi / 2 (m an integer).
bool MayContainHalfPiMultiple(const Interval& x, double m) {
  Interval t = Interval(m) * HalfPi();
  return t.hi() >= x.lo() && t.lo() <= x.hi();
}

// sin (shift 1) or cos (shift 0): the extrema are at m * pi / 2 with m of the
// parity of shift, where the value is (-1)^((m - shift) / 2).
Interval SinCos(const Interval& x, int shift) {
  if (x.IsEmpty()) return x;
  if (!x.IsBounded()) return Interval(-1, 1);
  ExactRounding rnd;
  auto down = [&](double t) { return shift ? rnd.sin_down(t) : rnd.cos_down(t); };
  auto up = [&](double t) { return shift ? rnd.sin_up(t) : rnd.cos_up(t); };
  if (x.IsPoint()) return Interval(down(x.lo()), up(x.lo()));
  if (x.Width() >= TwoPi().lo() || x.Mag() >= kTrigFar) return Interval(-1, 1);
  double lo = std::fmin(down(x.lo()), down(x.hi()));
  double hi = std::fmax(up(x.lo()), up(x.hi()));
  // The quotients are within 1 of the exact ones below kTrigFar.
  for (double m = std::floor(x.lo() / kHalfPiApprox) - 2;
       m <= std::ceil(x.hi() / kHalfPiApprox) + 2; ++m) {
    if (std::fabs(std::fmod(m, 2)) != shift || !MayContainHalfPiMultiple(x, m)) continue;
    if (std::fmod((m - shift) / 2, 2) == 0) {
      hi = 1;
    } else {
      lo = -1;
    }
  }
  return Interval(lo, hi);
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
Interval Sin(const Interval& x) { return SinCos(x, 1); }
Interval Cos(const Interval& x) { return SinCos(x, 0); }
Interval Tan(const Interval& x) {
  if (x.IsEmpty()) return x;  // (the empty set counts as bounded)
  if (!x.IsBounded()) return Interval();
  ExactRounding rnd;
  if (x.IsPoint()) return Interval(rnd.tan_down(x.lo()), rnd.tan_up(x.lo()));
  if (x.Width() >= Pi().lo() || x.Mag() >= kTrigFar) return Interval();
  // A pole (an odd multiple of pi/2) inside x: tan takes every value.
  for (double m = std::floor(x.lo() / kHalfPiApprox) - 2;
       m <= std::ceil(x.hi() / kHalfPiApprox) + 2; ++m) {
    if (std::fabs(std::fmod(m, 2)) == 1 && MayContainHalfPiMultiple(x, m)) return Interval();
  }
  return Interval(rnd.tan_down(x.lo()), rnd.tan_up(x.hi()));
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
