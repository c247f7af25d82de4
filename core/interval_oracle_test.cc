// MPFR oracle for icp::Interval and the backward projections.
//
// Every forward operation is evaluated on random intervals; random points
// inside are mapped exactly (up to a rigorous 256-bit enclosure) by MPFR and
// must lie in the interval result. Every backward projection is run on a z
// domain that holds the exact image of a random point, and must keep that
// point. ParseDecimal is checked against MPFR's exact decimal conversion.
//
// The exact value v of f(p) is enclosed as [vd, vu]: vd is MPFR's result
// rounded down at 256 bits and vu is vd when MPFR reports it exact, else the
// next 256-bit number. A double interval [lo, hi] holds v if and only if
// lo <= vd and vu <= hi (both bounds are 256-bit numbers), so the check has
// neither false alarms nor misses.
//
// Seeds are fixed: a failure prints its inputs with %.17g and reproduces.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <bit>
#include <cfloat>
#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/interval.h"
#include "core/projections.h"
#include "core/random.h"

namespace icp {
namespace {

constexpr mpfr_prec_t kPrec = 256;
constexpr double kMax = std::numeric_limits<double>::max();
constexpr int kMaxReportedFailures = 10;

// Samples (checked points) per forward operation and per projection.
constexpr int kForwardSamples = 100000;
constexpr int kBackwardSamples = 100000;

std::string Fmt(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Fmt(const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return buf;
}

std::string Str(const Interval& x) {
  if (x.IsEmpty()) return "[empty]";
  return Fmt("[%.17g, %.17g]", x.lo(), x.hi());
}

// A seed per test name that does not depend on the standard library.
uint64_t Fnv1a(const std::string& text) {
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
bool Enclose(const MpfrFn& f, double p, double q, Exact* e) {
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

bool Holds(const Interval& r, const Exact& e) {
  return !r.IsEmpty() && mpfr_cmp_d(e.lo.v, r.lo()) >= 0 && mpfr_cmp_d(e.hi.v, r.hi()) <= 0;
}

// Doubles in increasing order mapped to consecutive integers (-0 and +0 meet).
int64_t Ord(double d) {
  int64_t b = std::bit_cast<int64_t>(d);
  return b >= 0 ? b : -(b & std::numeric_limits<int64_t>::max());
}
double FromOrd(int64_t o) {
  return o >= 0 ? std::bit_cast<double>(o)
                : std::bit_cast<double>(static_cast<uint64_t>(-o) | (uint64_t{1} << 63));
}
// Number of doubles from a up to b (b >= a, both finite).
int64_t UlpDistance(double a, double b) { return Ord(b) - Ord(a); }

// What kind of numbers an operation should see most.
enum class Dist { kAny, kTrig, kExp, kUnit, kAboveOne, kPositive, kSmall };

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

// ---------------------------------------------------------------------------
// Forward operations.

struct ForwardOp {
  std::string name;
  int arity;
  Dist dist;
  std::function<Interval(const Interval&, const Interval&)> eval;
  MpfrFn exact;
  // Largest width in ulps of the result for point inputs whose exact result
  // is a normal double; 0 skips the check.
  int64_t point_ulps;
};

template <int (*F)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t)>
int Unary(mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr, mpfr_rnd_t rnd) {
  return F(r, x, rnd);
}
template <int (*F)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t)>
int Binary(mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr y, mpfr_rnd_t rnd) {
  return F(r, x, y, rnd);
}

int MpfrSqr(mpfr_ptr r, mpfr_srcptr x, mpfr_rnd_t rnd) { return mpfr_sqr(r, x, rnd); }
int MpfrAbs(mpfr_ptr r, mpfr_srcptr x, mpfr_rnd_t rnd) { return mpfr_abs(r, x, rnd); }
int MpfrNeg(mpfr_ptr r, mpfr_srcptr x, mpfr_rnd_t rnd) { return mpfr_neg(r, x, rnd); }

std::vector<ForwardOp> ForwardOps() {
  using I = const Interval&;
  std::vector<ForwardOp> ops = {
      {"add", 2, Dist::kAny, [](I x, I y) { return x + y; }, Binary<mpfr_add>, 1},
      {"sub", 2, Dist::kAny, [](I x, I y) { return x - y; }, Binary<mpfr_sub>, 1},
      {"mul", 2, Dist::kAny, [](I x, I y) { return x * y; }, Binary<mpfr_mul>, 1},
      {"div", 2, Dist::kAny, [](I x, I y) { return x / y; }, Binary<mpfr_div>, 1},
      {"neg", 1, Dist::kAny, [](I x, I) { return -x; }, Unary<MpfrNeg>, 0},
      {"sqr", 1, Dist::kAny, [](I x, I) { return Sqr(x); }, Unary<MpfrSqr>, 1},
      {"sqrt", 1, Dist::kPositive, [](I x, I) { return Sqrt(x); }, Unary<mpfr_sqrt>, 1},
      {"exp", 1, Dist::kExp, [](I x, I) { return Exp(x); }, Unary<mpfr_exp>, 16},
      {"log", 1, Dist::kPositive, [](I x, I) { return Log(x); }, Unary<mpfr_log>, 16},
      {"sin", 1, Dist::kTrig, [](I x, I) { return Sin(x); }, Unary<mpfr_sin>, 16},
      {"cos", 1, Dist::kTrig, [](I x, I) { return Cos(x); }, Unary<mpfr_cos>, 16},
      {"tan", 1, Dist::kTrig, [](I x, I) { return Tan(x); }, Unary<mpfr_tan>, 16},
      {"asin", 1, Dist::kUnit, [](I x, I) { return Asin(x); }, Unary<mpfr_asin>, 16},
      {"acos", 1, Dist::kUnit, [](I x, I) { return Acos(x); }, Unary<mpfr_acos>, 16},
      {"atan", 1, Dist::kAny, [](I x, I) { return Atan(x); }, Unary<mpfr_atan>, 16},
      {"sinh", 1, Dist::kExp, [](I x, I) { return Sinh(x); }, Unary<mpfr_sinh>, 16},
      {"cosh", 1, Dist::kExp, [](I x, I) { return Cosh(x); }, Unary<mpfr_cosh>, 16},
      {"tanh", 1, Dist::kSmall, [](I x, I) { return Tanh(x); }, Unary<mpfr_tanh>, 16},
      {"asinh", 1, Dist::kAny, [](I x, I) { return Asinh(x); }, Unary<mpfr_asinh>, 16},
      {"acosh", 1, Dist::kAboveOne, [](I x, I) { return Acosh(x); }, Unary<mpfr_acosh>, 16},
      {"atanh", 1, Dist::kUnit, [](I x, I) { return Atanh(x); }, Unary<mpfr_atanh>, 16},
      {"abs", 1, Dist::kAny, [](I x, I) { return Abs(x); }, Unary<MpfrAbs>, 0},
      {"min", 2, Dist::kAny, [](I x, I y) { return Min(x, y); }, Binary<mpfr_min>, 0},
      {"max", 2, Dist::kAny, [](I x, I y) { return Max(x, y); }, Binary<mpfr_max>, 0},
  };
  for (int n = -3; n <= 5; ++n) {
    // Each multiplication of pow's repeated squaring rounds once.
    int64_t ulps = n == 0 ? 0 : 8;
    ops.push_back({"pow" + std::string(n < 0 ? "_m" : "") + std::to_string(std::abs(n)), 1,
                   Dist::kAny, [n](I x, I) { return Pow(x, n); },
                   [n](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr, mpfr_rnd_t rnd) {
                     return mpfr_pow_si(r, x, n, rnd);
                   },
                   ulps});
  }
  for (int n = 1; n <= 6; ++n) {
    ops.push_back({"root" + std::to_string(n), 1, Dist::kAny, [n](I x, I) { return Root(x, n); },
                   [n](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr, mpfr_rnd_t rnd) {
                     return mpfr_rootn_ui(r, x, n, rnd);
                   },
                   16});
  }
  return ops;
}

void PrintTo(const ForwardOp& op, std::ostream* os) { *os << op.name; }

class ForwardOracle : public testing::TestWithParam<ForwardOp> {};

TEST_P(ForwardOracle, ContainsExactImage) {
  const ForwardOp& op = GetParam();
  Sampler s(Fnv1a(op.name) ^ 0x1c9be5d3a0f4ULL);
  Exact e;
  int failures = 0;
  int checked = 0;
  int tight_checked = 0;
  while (checked < kForwardSamples && failures < kMaxReportedFailures) {
    Interval x = s.RandomInterval(op.dist);
    Interval y = op.arity == 2 ? s.RandomInterval(op.dist) : Interval(0.0);
    Interval r = op.eval(x, y);
    // Two points per input draw; a point outside the domain is skipped.
    for (int k = 0; k < 2; ++k) {
      double p = s.PointIn(x);
      double q = s.PointIn(y);
      if (!Enclose(op.exact, p, q, &e)) continue;
      ++checked;
      if (!Holds(r, e)) {
        ++failures;
        ADD_FAILURE() << op.name
                      << Fmt(" x=[%.17g, %.17g] y=[%.17g, %.17g] p=%.17g q=%.17g", x.lo(), x.hi(),
                             y.lo(), y.hi(), p, q)
                      << " result=" << Str(r) << Fmt(" exact=%.17g", e.Approx());
        continue;
      }
      if (op.point_ulps == 0 || !x.IsPoint() || !y.IsPoint()) continue;
      // Ordinary inputs (zero or normal) and a normal result.
      double v = std::fabs(e.Approx());
      if (!(v >= DBL_MIN && v < kMax / 2)) continue;
      if ((p != 0 && std::fabs(p) < DBL_MIN) || (q != 0 && std::fabs(q) < DBL_MIN)) continue;
      // ExactRounding widens by one more ulp where an FMA residual may
      // underflow (kResidualExactThreshold).
      int64_t allowed = op.point_ulps;
      if (std::fmin(v, std::fmin(std::fabs(p), std::fabs(q))) < 0x1p-900) ++allowed;
      if (op.arity == 1 && std::fmin(v, std::fabs(p)) < 0x1p-900) ++allowed;
      ++tight_checked;
      if (UlpDistance(r.lo(), r.hi()) > allowed) {
        ++failures;
        ADD_FAILURE() << op.name << " too loose"
                      << Fmt(" x=%.17g y=%.17g result=[%.17g, %.17g] (%" PRId64 " ulps)", p, q,
                             r.lo(), r.hi(), UlpDistance(r.lo(), r.hi()));
      }
    }
  }
  EXPECT_GE(checked, kForwardSamples);
  if (op.point_ulps > 0) {
    EXPECT_GT(tight_checked, 1000);
  }
}

// The empty set in, the empty set out, whatever the other operand.
TEST_P(ForwardOracle, EmptyInEmptyOut) {
  const ForwardOp& op = GetParam();
  Sampler s(Fnv1a(op.name) + 1);
  for (int i = 0; i < 1000; ++i) {
    Interval x = s.RandomInterval(op.dist);
    Interval r = op.eval(Interval::Empty(), x);
    EXPECT_TRUE(r.IsEmpty()) << op.name << "(empty, " << Str(x) << ") = " << Str(r);
    if (op.arity == 2) {
      r = op.eval(x, Interval::Empty());
      EXPECT_TRUE(r.IsEmpty()) << op.name << "(" << Str(x) << ", empty) = " << Str(r);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllOps, ForwardOracle, testing::ValuesIn(ForwardOps()),
                         [](const testing::TestParamInfo<ForwardOp>& info) {
                           return info.param.name;
                         });

// Monotone functions on ordinary non-point intervals: the result lies within
// 16 ulps of the exact images of the bounds (no needless widening).
TEST(ForwardOracleTightness, MonotoneHull) {
  struct Case {
    const char* name;
    std::function<Interval(const Interval&)> eval;
    int (*exact)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
    double lo, hi;  // domain to draw from
  };
  const Case cases[] = {
      {"exp", Exp, mpfr_exp, -700, 700},           {"log", Log, mpfr_log, 1e-300, 1e300},
      {"atan", Atan, mpfr_atan, -1e10, 1e10},      {"sinh", Sinh, mpfr_sinh, -700, 700},
      {"tanh", Tanh, mpfr_tanh, -15, 15},          {"asinh", Asinh, mpfr_asinh, -1e300, 1e300},
      {"sqrt", Sqrt, mpfr_sqrt, 1e-300, 1e300},    {"asin", Asin, mpfr_asin, -0.999, 0.999},
      {"atanh", Atanh, mpfr_atanh, -0.999, 0.999},
  };
  Sampler s(7);
  Mp a, fa, fb;
  for (const Case& c : cases) {
    int failures = 0;
    for (int i = 0; i < 5000 && failures < kMaxReportedFailures; ++i) {
      double u = s.Unit(), v = s.Unit();
      bool log_scale = c.lo > 0;
      auto pick = [&](double t) {
        return log_scale ? std::exp(std::log(c.lo) + t * (std::log(c.hi) - std::log(c.lo)))
                         : c.lo + t * (c.hi - c.lo);
      };
      double lo = pick(std::fmin(u, v));
      double hi = pick(std::fmax(u, v));
      Interval r = c.eval(Interval(lo, hi));
      mpfr_set_d(a.v, lo, MPFR_RNDN);
      c.exact(fa.v, a.v, MPFR_RNDD);
      mpfr_set_d(a.v, hi, MPFR_RNDN);
      c.exact(fb.v, a.v, MPFR_RNDU);
      double want_lo = mpfr_get_d(fa.v, MPFR_RNDD);
      double want_hi = mpfr_get_d(fb.v, MPFR_RNDU);
      if (std::fabs(want_lo) < DBL_MIN || std::fabs(want_hi) < DBL_MIN) continue;
      if (UlpDistance(r.lo(), want_lo) > 16 || UlpDistance(want_hi, r.hi()) > 16) {
        ++failures;
        ADD_FAILURE() << c.name << Fmt(" x=[%.17g, %.17g]", lo, hi) << " result=" << Str(r)
                      << Fmt(" exact hull=[%.17g, %.17g]", want_lo, want_hi);
      }
    }
  }
}

// Sin and cos on non-point bounded intervals narrower than a period: within
// 16 ulps (absolute, at scale 1) of the exact range.
TEST(ForwardOracleTightness, TrigRange) {
  Sampler s(11);
  Mp a, f;
  int failures = 0;
  for (int i = 0; i < 20000 && failures < kMaxReportedFailures; ++i) {
    double c = s.Coin(0.5) ? s.NearHalfPiMultiple(40) : 40 * (2 * s.Unit() - 1);
    double w = std::ldexp(s.Unit(), -s.Int(0, 30));
    Interval x(c - w, c + w);
    for (int which = 0; which < 2; ++which) {
      Interval r = which == 0 ? Sin(x) : Cos(x);
      // Exact range: extremes at the bounds or at interior critical points.
      double want_lo = 1, want_hi = -1;
      for (double t : {x.lo(), x.hi()}) {
        mpfr_set_d(a.v, t, MPFR_RNDN);
        which == 0 ? mpfr_sin(f.v, a.v, MPFR_RNDN) : mpfr_cos(f.v, a.v, MPFR_RNDN);
        double d = mpfr_get_d(f.v, MPFR_RNDN);
        want_lo = std::fmin(want_lo, d);
        want_hi = std::fmax(want_hi, d);
      }
      // Critical points k pi/2 (sin: odd k, cos: even k) inside x.
      double offset = which == 0 ? 0.5 : 0.0;
      for (double k = std::floor(x.lo() / std::numbers::pi - offset) - 1;
           k <= std::ceil(x.hi() / std::numbers::pi) + 1; ++k) {
        double t = (k + offset) * std::numbers::pi;
        if (t > x.lo() + 1e-12 && t < x.hi() - 1e-12) {
          double val = std::fmod(std::fabs(k), 2) == 0 ? 1 : -1;
          want_lo = std::fmin(want_lo, val);
          want_hi = std::fmax(want_hi, val);
        }
      }
      const double slack = 32 * DBL_EPSILON;
      if (r.lo() < want_lo - slack || r.hi() > want_hi + slack) {
        ++failures;
        ADD_FAILURE() << (which == 0 ? "sin" : "cos") << " x=" << Str(x) << " result=" << Str(r)
                      << Fmt(" exact=[%.17g, %.17g]", want_lo, want_hi);
      }
    }
  }
}

// ---------------------------------------------------------------------------
// Backward projections.

struct BackwardOp {
  std::string name;
  int arity;
  Dist dist;
  MpfrFn exact;
  std::function<void(const Interval& z, Interval& x, Interval& y)> project;
};

std::vector<BackwardOp> BackwardOps() {
  using I = const Interval&;
  std::vector<BackwardOp> ops = {
      {"add", 2, Dist::kAny, Binary<mpfr_add>,
       [](I z, Interval& x, Interval& y) { BwdAdd(z, x, y); }},
      {"sub", 2, Dist::kAny, Binary<mpfr_sub>,
       [](I z, Interval& x, Interval& y) { BwdSub(z, x, y); }},
      {"mul", 2, Dist::kAny, Binary<mpfr_mul>,
       [](I z, Interval& x, Interval& y) { BwdMul(z, x, y); }},
      {"div", 2, Dist::kAny, Binary<mpfr_div>,
       [](I z, Interval& x, Interval& y) { BwdDiv(z, x, y); }},
      {"divide_relational", 2, Dist::kAny, Binary<mpfr_mul>,
       [](I z, Interval& x, Interval& y) { x = DivideRelational(x, z, y); }},
      {"neg", 1, Dist::kAny, Unary<MpfrNeg>, [](I z, Interval& x, Interval&) { BwdNeg(z, x); }},
      {"sqr", 1, Dist::kAny, Unary<MpfrSqr>, [](I z, Interval& x, Interval&) { BwdSqr(z, x); }},
      {"sqrt", 1, Dist::kPositive, Unary<mpfr_sqrt>,
       [](I z, Interval& x, Interval&) { BwdSqrt(z, x); }},
      {"exp", 1, Dist::kExp, Unary<mpfr_exp>, [](I z, Interval& x, Interval&) { BwdExp(z, x); }},
      {"log", 1, Dist::kPositive, Unary<mpfr_log>,
       [](I z, Interval& x, Interval&) { BwdLog(z, x); }},
      {"sin", 1, Dist::kTrig, Unary<mpfr_sin>, [](I z, Interval& x, Interval&) { BwdSin(z, x); }},
      {"cos", 1, Dist::kTrig, Unary<mpfr_cos>, [](I z, Interval& x, Interval&) { BwdCos(z, x); }},
      {"tan", 1, Dist::kTrig, Unary<mpfr_tan>, [](I z, Interval& x, Interval&) { BwdTan(z, x); }},
      {"atan", 1, Dist::kAny, Unary<mpfr_atan>, [](I z, Interval& x, Interval&) { BwdAtan(z, x); }},
      {"sinh", 1, Dist::kExp, Unary<mpfr_sinh>, [](I z, Interval& x, Interval&) { BwdSinh(z, x); }},
      {"cosh", 1, Dist::kExp, Unary<mpfr_cosh>, [](I z, Interval& x, Interval&) { BwdCosh(z, x); }},
      {"tanh", 1, Dist::kSmall, Unary<mpfr_tanh>,
       [](I z, Interval& x, Interval&) { BwdTanh(z, x); }},
      {"abs", 1, Dist::kAny, Unary<MpfrAbs>, [](I z, Interval& x, Interval&) { BwdAbs(z, x); }},
      {"min", 2, Dist::kAny, Binary<mpfr_min>,
       [](I z, Interval& x, Interval& y) { BwdMin(z, x, y); }},
      {"max", 2, Dist::kAny, Binary<mpfr_max>,
       [](I z, Interval& x, Interval& y) { BwdMax(z, x, y); }},
  };
  for (int n = -3; n <= 5; ++n) {
    ops.push_back({"pow" + std::string(n < 0 ? "_m" : "") + std::to_string(std::abs(n)), 1,
                   Dist::kAny,
                   [n](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr, mpfr_rnd_t rnd) {
                     return mpfr_pow_si(r, x, n, rnd);
                   },
                   [n](I z, Interval& x, Interval&) { BwdPow(z, x, n); }});
  }
  return ops;
}

// A z domain holding the exact value enclosed by e: its rounded-out hull,
// sometimes widened by a random amount on either side.
Interval ZDomain(const Exact& e, Sampler& s) {
  double lo = mpfr_get_d(e.lo.v, MPFR_RNDD);
  double hi = mpfr_get_d(e.hi.v, MPFR_RNDU);
  auto widen = [&](double b, double dir) {
    if (!std::isfinite(b)) return b;
    switch (s.Int(0, 5)) {
      case 0:
        return dir * kInf;
      case 1:
        return dir > 0 ? StepUp(b, s.Int(0, 4)) : StepDown(b, s.Int(0, 4));
      case 2:  // to the nearest of -1, 0, 1 beyond b (range edges of sin, cos, tanh)
        for (double edge : {-1.0, 0.0, 1.0}) {
          if (dir > 0 && edge >= b) return edge;
        }
        for (double edge : {1.0, 0.0, -1.0}) {
          if (dir < 0 && edge <= b) return edge;
        }
        return b;
      default:
        return b + dir * std::fabs(b == 0 ? 1 : b) * std::ldexp(s.Unit(), -s.Int(0, 60));
    }
  };
  if (s.Coin(0.5)) lo = widen(lo, -1);
  if (s.Coin(0.5)) hi = widen(hi, +1);
  return Interval(lo, hi);
}

void PrintTo(const BackwardOp& op, std::ostream* os) { *os << op.name; }

class BackwardOracle : public testing::TestWithParam<BackwardOp> {};

TEST_P(BackwardOracle, KeepsEverySolution) {
  const BackwardOp& op = GetParam();
  Sampler s(Fnv1a(op.name) ^ 0x5eed0bacULL);
  Exact e;
  int failures = 0;
  int checked = 0;
  int contracted = 0;
  while (checked < kBackwardSamples && failures < kMaxReportedFailures) {
    Interval x = s.RandomInterval(op.dist);
    Interval y = op.arity == 2 ? s.RandomInterval(op.dist) : Interval(0.0);
    double p = s.PointIn(x);
    double q = s.PointIn(y);
    if (!Enclose(op.exact, p, q, &e)) continue;
    ++checked;
    Interval z = ZDomain(e, s);
    Interval x2 = x;
    Interval y2 = y;
    op.project(z, x2, y2);
    if (!(x2 == x) || !(y2 == y)) ++contracted;
    bool kept = x2.Contains(p) && (op.arity == 1 || y2.Contains(q));
    bool shrunk = x2.IsSubsetOf(x) && y2.IsSubsetOf(y);
    if (!kept || !shrunk) {
      ++failures;
      ADD_FAILURE() << "Bwd" << op.name << (kept ? " grew a domain" : " lost a solution")
                    << Fmt(" z=[%.17g, %.17g] x=[%.17g, %.17g] y=[%.17g, %.17g] p=%.17g q=%.17g",
                           z.lo(), z.hi(), x.lo(), x.hi(), y.lo(), y.hi(), p, q)
                    << " x'=" << Str(x2) << " y'=" << Str(y2) << Fmt(" exact z=%.17g", e.Approx());
    }
  }
  EXPECT_GE(checked, kBackwardSamples);
  // Sound by doing nothing is not the goal: most draws must contract.
  if (op.name != "pow0") {  // z = x^0 = 1 says nothing about x
    EXPECT_GT(contracted, checked / 4);
  }
}

INSTANTIATE_TEST_SUITE_P(AllProjections, BackwardOracle, testing::ValuesIn(BackwardOps()),
                         [](const testing::TestParamInfo<BackwardOp>& info) {
                           return info.param.name;
                         });

// Periodic projections far from 0: points up to 1e6 and a few up to 1e15 in
// narrow and wide domains, with z the tight enclosure of the exact value
// (often near +-1, where the two branches meet).
TEST(BackwardOracleTrig, FarFromZero) {
  Sampler s(13);
  Exact e;
  const MpfrFn fns[] = {Unary<mpfr_sin>, Unary<mpfr_cos>, Unary<mpfr_tan>};
  const char* names[] = {"sin", "cos", "tan"};
  int failures = 0;
  int contracted = 0;
  for (int i = 0; i < 30000 && failures < kMaxReportedFailures; ++i) {
    int which = i % 3;
    double p = s.Coin(0.9) ? s.NearHalfPiMultiple(s.Coin(0.8) ? 1000000 : 1000000000000000)
                           : s.Sign() * std::ldexp(1 + s.Unit(), s.Int(0, 50));
    double w1 = s.Coin(0.2) ? 0 : std::ldexp(s.Unit(), s.Int(-30, 5));
    double w2 = s.Coin(0.2) ? 0 : std::ldexp(s.Unit(), s.Int(-30, 5));
    Interval x(p - w1, p + w2);
    Enclose(fns[which], p, 0, &e);
    Interval z = s.Coin(0.7)
                     ? Interval(mpfr_get_d(e.lo.v, MPFR_RNDD), mpfr_get_d(e.hi.v, MPFR_RNDU))
                     : ZDomain(e, s);
    Interval x2 = x;
    if (which == 0) BwdSin(z, x2);
    if (which == 1) BwdCos(z, x2);
    if (which == 2) BwdTan(z, x2);
    if (x2.Width() < x.Width()) ++contracted;
    if (!x2.Contains(p) || !x2.IsSubsetOf(x)) {
      ++failures;
      ADD_FAILURE() << "Bwd" << names[which]
                    << Fmt(" z=[%.17g, %.17g] x=[%.17g, %.17g] p=%.17g", z.lo(), z.hi(), x.lo(),
                           x.hi(), p)
                    << " x'=" << Str(x2) << Fmt(" exact z=%.17g", e.Approx());
    }
  }
  // The projections must also do their job, not only stay sound.
  EXPECT_GT(contracted, 5000);
}

// Unary projections with a tight z on ordinary points contract x to a few
// ulps around the point (where the function is invertible and well
// conditioned).
TEST(BackwardOracleTightness, InvertibleUnary) {
  struct Case {
    const char* name;
    MpfrFn exact;
    std::function<void(const Interval&, Interval&)> project;
    double lo, hi;
  };
  const Case cases[] = {
      {"exp", Unary<mpfr_exp>, BwdExp, -700, 700},
      {"log", Unary<mpfr_log>, BwdLog, 1e-300, 1e300},
      {"sinh", Unary<mpfr_sinh>, BwdSinh, -700, 700},
      {"tanh", Unary<mpfr_tanh>, BwdTanh, -5, 5},
      {"atan", Unary<mpfr_atan>, BwdAtan, -1e3, 1e3},
      {"sqrt", Unary<mpfr_sqrt>, BwdSqrt, 1e-300, 1e300},
      {"pow3",
       [](mpfr_ptr r, mpfr_srcptr x, mpfr_srcptr, mpfr_rnd_t rnd) {
         return mpfr_pow_si(r, x, 3, rnd);
       },
       [](const Interval& z, Interval& x) { BwdPow(z, x, 3); }, -1e100, 1e100},
  };
  Sampler s(17);
  Exact e;
  for (const Case& c : cases) {
    int failures = 0;
    for (int i = 0; i < 3000 && failures < kMaxReportedFailures; ++i) {
      double t = s.Unit();
      double p = c.lo > 0 ? std::exp(std::log(c.lo) + t * (std::log(c.hi) - std::log(c.lo)))
                          : c.lo + t * (c.hi - c.lo);
      if (std::fabs(p) < 1e-3) continue;  // relative conditioning breaks down near 0
      Enclose(c.exact, p, 0, &e);
      Interval z(mpfr_get_d(e.lo.v, MPFR_RNDD), mpfr_get_d(e.hi.v, MPFR_RNDU));
      Interval x = Interval::Entire();
      c.project(z, x);
      double rel = x.Width() / std::fabs(p);
      if (!x.Contains(p) || !(rel <= 1e-12)) {
        ++failures;
        ADD_FAILURE() << "Bwd" << c.name << Fmt(" p=%.17g", p) << " z=" << Str(z)
                      << " x'=" << Str(x);
      }
    }
  }
}

// ---------------------------------------------------------------------------
// ParseDecimal.

TEST(ParseDecimalOracle, TightestEnclosureOfRandomDecimals) {
  Sampler s(19);
  Mp lo, hi;
  int failures = 0;
  for (int i = 0; i < 100000 && failures < kMaxReportedFailures; ++i) {
    std::string text;
    if (s.Coin(0.5)) text += s.Coin(0.5) ? "-" : "+";
    int digits = s.Int(1, 30);
    int point = s.Coin(0.6) ? s.Int(0, digits) : -1;
    for (int d = 0; d < digits; ++d) {
      if (d == point) text += '.';
      text += static_cast<char>('0' + s.Int(0, 9));
    }
    if (s.Coin(0.8)) text += (s.Coin(0.5) ? "e" : "E") + std::to_string(s.Int(-320, 320));
    Interval r;
    if (!ParseDecimal(text, &r)) {
      ++failures;
      ADD_FAILURE() << "ParseDecimal rejected \"" << text << "\"";
      continue;
    }
    char* end = nullptr;
    int ternary = mpfr_strtofr(lo.v, text.c_str(), &end, 10, MPFR_RNDD);
    ASSERT_EQ(*end, '\0') << text;
    mpfr_set(hi.v, lo.v, MPFR_RNDN);
    if (ternary != 0) mpfr_nextabove(hi.v);
    Exact e;
    mpfr_set(e.lo.v, lo.v, MPFR_RNDN);
    mpfr_set(e.hi.v, hi.v, MPFR_RNDN);
    bool tight = r.lo() == r.hi() || NextUp(r.lo()) == r.hi();
    // A point only when the decimal is exactly that double.
    if (r.lo() == r.hi()) tight = tight && ternary == 0 && mpfr_cmp_d(lo.v, r.lo()) == 0;
    if (!Holds(r, e) || !tight) {
      ++failures;
      ADD_FAILURE() << "ParseDecimal(\"" << text << "\") = " << Str(r)
                    << Fmt(" exact=%.17g", e.Approx());
    }
  }
}

}  // namespace
}  // namespace icp
