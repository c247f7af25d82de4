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

// Every integer m with m * pi / 2 in x lies in [*first, *last] (x bounded,
// |x| < kTrigFar), and so does every m that MayContainHalfPiMultiple accepts
// (its enclosure of m * pi / 2 is within 5e-16 relative of the exact value);
// the range is empty (first > last) when x is far from every multiple, the
// usual case for a narrow x. The quotient x / kHalfPiApprox is within 2.5e-16
// of the exact x / (pi / 2) in relative terms (one rounding of pi / 2, one of
// the division; no overflow below kTrigFar and an absolute error under 1e-300
// if it underflows), so a margin of 1e-15 relative, which also covers the
// rounding of the subtraction, is safe. Below 2^51 the integers are exact
// in an int64.
void HalfPiMultiplesIn(const Interval& x, std::int64_t* first, std::int64_t* last) {
  const double q_lo = x.lo() / kHalfPiApprox;
  const double q_hi = x.hi() / kHalfPiApprox;
  *first = static_cast<std::int64_t>(std::ceil(q_lo - (1e-15 * std::fabs(q_lo) + 1e-300)));
  *last = static_cast<std::int64_t>(std::floor(q_hi + (1e-15 * std::fabs(q_hi) + 1e-300)));
}

// Whether x may contain m * pi / 2 (m an integer): the enclosure of
// m * pi / 2 that Interval(m) * HalfPi() gives, computed on the bounds.
bool MayContainHalfPiMultiple(const Interval& x, double m) {
  ExactRounding rnd;
  const Interval& half_pi = HalfPi();
  const double t_lo = rnd.mul_down(m, m >= 0 ? half_pi.lo() : half_pi.hi());
  const double t_hi = rnd.mul_up(m, m >= 0 ? half_pi.hi() : half_pi.lo());
  return t_hi >= x.lo() && t_lo <= x.hi();
}

// sin (shift 1) or cos (shift 0): the extrema are at m * pi / 2 with m of the
// parity of shift, where the value is (-1)^((m - shift) / 2).
Interval SinCos(const Interval& x, int shift) {
  if (x.IsEmpty()) return x;
  if (!x.IsBounded()) return Interval(-1, 1);
  ExactRounding rnd;
  auto both = [&](double t, double* down, double* up) {
    if (shift) {
      rnd.sin_both(t, down, up);
    } else {
      rnd.cos_both(t, down, up);
    }
  };
  double lo_down, lo_up;
  both(x.lo(), &lo_down, &lo_up);
  if (x.IsPoint()) return Interval(lo_down, lo_up);
  if (x.Width() >= TwoPi().lo() || x.Mag() >= kTrigFar) return Interval(-1, 1);
  double hi_down, hi_up;
  both(x.hi(), &hi_down, &hi_up);
  double lo = lo_down < hi_down ? lo_down : hi_down;
  double hi = lo_up < hi_up ? hi_up : lo_up;
  std::int64_t first, last;
  HalfPiMultiplesIn(x, &first, &last);
  for (std::int64_t m = first + ((first - shift) & 1); m <= last; m += 2) {
    if (!MayContainHalfPiMultiple(x, static_cast<double>(m))) continue;
    if ((((m - shift) / 2) & 1) == 0) {
      hi = 1;
    } else {
      lo = -1;
    }
  }
  return Interval(lo, hi);
}
}  // namespace

double Interval::Mid() const {
  if (IsEmpty()) return 0;
  if (lo() == -kInf && hi() == kInf) return 0;
  if (lo() == -kInf) return hi() >= 0 ? -kMaxDouble / 2 : std::fmax(2 * hi(), -kMaxDouble);
  if (hi() == kInf) return lo() <= 0 ? kMaxDouble / 2 : std::fmin(2 * lo(), kMaxDouble);
  double m = lo() / 2 + hi() / 2;
  return std::fmin(std::fmax(m, lo()), hi());
}


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
  std::int64_t first, last;
  HalfPiMultiplesIn(x, &first, &last);
  for (std::int64_t m = first + ((first + 1) & 1); m <= last; m += 2) {
    if (MayContainHalfPiMultiple(x, static_cast<double>(m))) return Interval();
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
