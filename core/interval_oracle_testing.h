// Shared pieces of the MPFR oracle tests (interval_oracle*_test.cc): exact
// enclosures of real values by MPFR, and a sampler of hard doubles and intervals.
//
// The exact value v of f(p) is enclosed as [vd, vu]: vd is MPFR's result
// rounded down at 256 bits and vu is vd when MPFR reports it exact, else the
// next 256-bit number. A double interval [lo, hi] holds v if and only if
// lo <= vd and vu <= hi (both bounds are 256-bit numbers), so the check has
// neither false alarms nor misses.
#ifndef ICPBENCH_CORE_INTERVAL_ORACLE_TESTING_H_
#define ICPBENCH_CORE_INTERVAL_ORACLE_TESTING_H_

#include <mpfr.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

#include "core/interval.h"
#include "core/random.h"

namespace icp::oracle {

inline constexpr mpfr_prec_t kPrec = 256;
inline constexpr double kMax = std::numeric_limits<double>::max();
inline constexpr int kMaxReportedFailures = 10;

inline std::string Fmt(const char* format, ...) __attribute__((format(printf, 1, 2)));
inline std::string Fmt(const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return buf;
}

inline std::string Str(const Interval& x) {
  if (x.IsEmpty()) return "[empty]";
  return Fmt("[%.17g, %.17g]", x.lo(), x.hi());
}

// A seed per test name that does not depend on the standard library.
inline uint64_t Fnv1a(const std::string& text) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : text) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return h;
}

// An MPFR number at kPrec bits.
struct Mp {
  Mp() { mpfr_init2(v, kPrec); }
  ~Mp() { mpfr_clear(v); }
  Mp(const Mp&) = delete;
  Mp& operator=(const Mp&) = delete;
  mpfr_t v;
};

// A rigorous enclosure [lo, hi] of an exact real value.
struct Exact {
  Mp lo, hi;
  double Approx() const { return mpfr_get_d(lo.v, MPFR_RNDN); }
};

// f(rop, x, y, rnd) -> MPFR ternary value.
using MpfrFn = std::function<int(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t)>;

// Encloses f(p, q); false when f is undefined there.
inline bool Enclose(const MpfrFn& f, double p, double q, Exact* e) {
  Mp x, y;
  mpfr_set_d(x.v, p, MPFR_RNDN);  // exact: 256 > 53 bits
  mpfr_set_d(y.v, q, MPFR_RNDN);
  mpfr_clear_flags();
  int ternary = f(e->lo.v, x.v, y.v, MPFR_RNDD);
  // NaN: outside the domain; division by zero: a pole (log 0, 1 / 0).
  if (mpfr_nan_p(e->lo.v) || mpfr_divby0_p()) return false;
  mpfr_set(e->hi.v, e->lo.v, MPFR_RNDN);
  if (ternary != 0) mpfr_nextabove(e->hi.v);
  return true;
}

inline bool Holds(const Interval& r, const Exact& e) {
  return !r.IsEmpty() && mpfr_cmp_d(e.lo.v, r.lo()) >= 0 && mpfr_cmp_d(e.hi.v, r.hi()) <= 0;
}

// Doubles in increasing order mapped to consecutive integers (-0 and +0 meet).
inline int64_t Ord(double d) {
  int64_t b = std::bit_cast<int64_t>(d);
  return b >= 0 ? b : -(b & std::numeric_limits<int64_t>::max());
}
inline double FromOrd(int64_t o) {
  return o >= 0 ? std::bit_cast<double>(o)
                : std::bit_cast<double>(static_cast<uint64_t>(-o) | (uint64_t{1} << 63));
}
// Number of doubles from a up to b (b >= a, both finite).
inline int64_t UlpDistance(double a, double b) { return Ord(b) - Ord(a); }

// What kind of numbers an operation should see most.
enum class Dist { kAny, kTrig, kExp, kUnit, kAboveOne, kPositive, kSmall };

// Random doubles and intervals, biased towards the hard cases (huge, tiny,
// subnormal, near multiples of pi/2, near the edges of exp's range).
class Sampler {
 public:
  explicit Sampler(uint64_t seed) : g_(seed) {
    mpfr_const_pi(half_pi_.v, MPFR_RNDN);
    mpfr_div_2ui(half_pi_.v, half_pi_.v, 1, MPFR_RNDN);
  }

  double Unit() { return UniformReal(g_, 0, 1); }
  int Int(int lo, int hi) { return static_cast<int>(UniformInt(g_, lo, hi)); }
  int64_t Int64(int64_t lo, int64_t hi) { return UniformInt(g_, lo, hi); }
  bool Coin(double p) { return Unit() < p; }
  double Sign() { return Coin(0.5) ? 1.0 : -1.0; }

  // Mantissa in [1, 2) times 2^e, random sign.
  double Scaled(int e_lo, int e_hi) { return Sign() * std::ldexp(1 + Unit(), Int(e_lo, e_hi)); }

  // Moves x by up to n ulps either way (stays finite).
  double Nudge(double x, int n) {
    int k = Int(-n, n);
    for (; k > 0; --k) x = NextUp(x);
    for (; k < 0; ++k) x = NextDown(x);
    return std::fmin(std::fmax(x, -kMax), kMax);
  }

  // The double nearest to k * pi / 2 for a random |k| <= k_max, nudged.
  double NearHalfPiMultiple(int64_t k_max) {
    Mp t;
    mpfr_mul_si(t.v, half_pi_.v, static_cast<long>(Int64(-k_max, k_max)), MPFR_RNDN);
    double x = mpfr_get_d(t.v, MPFR_RNDN);
    return Coin(0.7) ? Nudge(x, 3) : x * (1 + Sign() * std::ldexp(Unit(), -Int(10, 50)));
  }

  // Any finite double, from a mixture of magnitudes.
  double Generic() {
    int r = Int(0, 99);
    if (r < 40) return Scaled(-30, 30);
    if (r < 48) return Scaled(960, 1023);
    if (r < 56) return Scaled(-1022, -960);
    if (r < 62) {  // subnormal
      double d = std::bit_cast<double>(Int64(1, (int64_t{1} << 52) - 1));
      return Sign() * d;
    }
    if (r < 67) return Coin(0.5) ? 0.0 : -0.0;
    if (r < 75) return Int(-10, 10);
    if (r < 80) {
      const double special[] = {kMax, DBL_MIN, std::numeric_limits<double>::denorm_min(),
                                NextDown(kMax), 1.0};
      return Sign() * special[Int(0, 4)];
    }
    if (r < 90) return NearHalfPiMultiple(Coin(0.8) ? 10 : 1000000);
    return Sign() * Unit();
  }

  double Special(Dist d) {
    switch (d) {
      case Dist::kAny:
        return Generic();
      case Dist::kTrig: {
        int r = Int(0, 9);
        if (r < 5) return NearHalfPiMultiple(16);
        if (r < 8) return NearHalfPiMultiple(1000000);
        if (r < 9) return NearHalfPiMultiple(1000000000000000);
        return Sign() * std::ldexp(1 + Unit(), Int(20, 52));
      }
      case Dist::kExp: {
        // log(DBL_MAX), log(DBL_MIN), log(denorm_min) and a general range.
        const double edges[] = {709.782712893384, -708.3964185322641, -744.4400719213812,
                                -745.1332191019411, 0.0};
        int r = Int(0, 9);
        if (r < 5) return Nudge(edges[Int(0, 4)], 8);
        if (r < 7) return edges[Int(0, 3)] + Sign() * Unit();
        return Sign() * 750 * Unit();
      }
      case Dist::kUnit: {
        int r = Int(0, 9);
        if (r < 3) return Sign() * Nudge(1.0, 4);
        if (r < 5) return Sign() * (1 - std::ldexp(Unit(), -Int(1, 52)));
        if (r < 8) return Sign() * 1.2 * Unit();
        return Scaled(-1074, -1);
      }
      case Dist::kAboveOne: {
        int r = Int(0, 9);
        if (r < 3) return Nudge(1.0, 4);
        if (r < 6) return 1 + std::ldexp(Unit(), -Int(0, 60));
        if (r < 8) return std::ldexp(1 + Unit(), Int(0, 1023));
        return 2 * Unit();
      }
      case Dist::kPositive: {
        double x = std::fabs(Generic());
        return Coin(0.2) ? Nudge(1.0, 8) : x;
      }
      case Dist::kSmall:
        return Coin(0.5) ? Scaled(-30, 30) : Int(-10, 10);
    }
    return 0;
  }

  double Draw(Dist d) { return Coin(0.5) ? Generic() : Special(d); }

  // A random non-empty interval built from numbers of kind d.
  Interval RandomInterval(Dist d) {
    double a = Draw(d);
    switch (Int(0, 9)) {
      case 0:
      case 1:
      case 2:
        return Interval(a);
      case 3:
      case 4: {  // narrow
        double w = a == 0 ? std::ldexp(Unit(), -Int(0, 1074))
                          : std::fabs(a) * std::ldexp(Unit(), -Int(1, 52));
        return Coin(0.5) ? Interval(a, a + w) : Interval(a - w, a);
      }
      case 5:
      case 6: {
        double b = Draw(d);
        return Interval(std::fmin(a, b), std::fmax(a, b));
      }
      case 7:
        return Coin(0.5) ? Interval(a, kInf) : Interval(-kInf, a);
      case 8:
        return Coin(0.5) ? Interval(0.0, std::fabs(a)) : Interval(-std::fabs(a), 0.0);
      default:
        return Coin(0.3) ? Interval::Entire() : Interval(-std::fabs(a), std::fabs(a));
    }
  }

  // A random real point of the non-empty interval x.
  double PointIn(const Interval& x) {
    double lo = x.lo();
    double hi = x.hi();
    for (int attempt = 0; attempt < 8; ++attempt) {
      double c = 0;
      switch (Int(0, 5)) {
        case 0:
          c = lo;
          break;
        case 1:
          c = hi;
          break;
        case 2:
          c = lo + Unit() * (hi - lo);
          break;
        case 3:
          c = Generic();
          break;
        default: {  // uniform over the doubles between the bounds
          int64_t a = Ord(std::fmax(lo, -kMax));
          int64_t b = Ord(std::fmin(hi, kMax));
          c = FromOrd(Int64(a, b));
        }
      }
      if (std::isfinite(c) && lo <= c && c <= hi) return c;
    }
    if (std::isfinite(lo)) return lo;
    if (std::isfinite(hi)) return hi;
    return 0;
  }

 private:
  RandomEngine g_;
  Mp half_pi_;
};

// MPFR's functions of one or two arguments as MpfrFn.
template <int (*F)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t)>
int Unary(mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr, mpfr_rnd_t rnd) {
  return F(r, x, rnd);
}
template <int (*F)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t)>
int Binary(mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr y, mpfr_rnd_t rnd) {
  return F(r, x, y, rnd);
}

inline int MpfrSqr(mpfr_ptr r, mpfr_srcptr x, mpfr_rnd_t rnd) { return mpfr_sqr(r, x, rnd); }
inline int MpfrAbs(mpfr_ptr r, mpfr_srcptr x, mpfr_rnd_t rnd) { return mpfr_abs(r, x, rnd); }
inline int MpfrNeg(mpfr_ptr r, mpfr_srcptr x, mpfr_rnd_t rnd) { return mpfr_neg(r, x, rnd); }

// Counts of a sampling oracle.
struct Tally {
  int checked = 0;   // points compared with MPFR
  int failures = 0;  // failures reported
};

// The loop of a sampling oracle on an operation op (with a name, an arity
// and a Dist): draws operands x and y (y is the point 0 for a unary op) from
// a sampler seeded by op's name and salt, and calls check(s, x, y), which
// counts in tally, until tally has `samples` checked points or
// kMaxReportedFailures failures.
template <typename Op, typename Check>
void SampleOperands(const Op& op, uint64_t salt, int samples, const Tally& tally,
                    const Check& check) {
  Sampler s(Fnv1a(op.name) ^ salt);
  while (tally.checked < samples && tally.failures < kMaxReportedFailures) {
    const Interval x = s.RandomInterval(op.dist);
    const Interval y = op.arity == 2 ? s.RandomInterval(op.dist) : Interval(0.0);
    check(s, x, y);
  }
}

}  // namespace icp::oracle

#endif  // ICPBENCH_CORE_INTERVAL_ORACLE_TESTING_H_
