// MPFR oracle for icp::Interval's forward operations: evaluated on random
// intervals, each must hold the exact images (up to a rigorous 256-bit
// enclosure by MPFR) of random points inside.
//
// The same executable checks the backward projections
// (interval_oracle_backward_test.cc) and ParseDecimal
// (interval_oracle_decimal_test.cc), with the tools of interval_oracle_testing.h.
//
// Seeds are fixed: a failure prints its inputs with %.17g and reproduces.
#include <gtest/gtest.h>

#include <cfloat>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "core/interval.h"
#include "core/argument_contractor.h"
#include "core/interval_oracle_testing.h"

namespace icp::oracle {
namespace {

// Samples (checked points) per forward operation.
constexpr int kForwardSamples = 100000;

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
      // atan2(y, x): every quadrant, both zeros and the cut along the
      // negative x axis come from kAny's draws (signed zeros included).
      {"atan2", 2, Dist::kAny, [](I y, I x) { return Atan2(y, x); }, Binary<mpfr_atan2>, 0},
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
  Exact e;
  Tally tally;
  int tight_checked = 0;
  auto check = [&](Sampler& s, const Interval& x, const Interval& y) {
    Interval r = op.eval(x, y);
    // Two points per input draw; a point outside the domain is skipped.
    for (int k = 0; k < 2; ++k) {
      double p = s.PointIn(x);
      double q = s.PointIn(y);
      if (!Enclose(op.exact, p, q, &e)) continue;
      ++tally.checked;
      if (!Holds(r, e)) {
        ++tally.failures;
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
        ++tally.failures;
        ADD_FAILURE() << op.name << " too loose"
                      << Fmt(" x=%.17g y=%.17g result=[%.17g, %.17g] (%" PRId64 " ulps)", p, q,
                             r.lo(), r.hi(), UlpDistance(r.lo(), r.hi()));
      }
    }
  };
  SampleOperands(op, 0x1c9be5d3a0f4ULL, kForwardSamples, tally, check);
  EXPECT_GE(tally.checked, kForwardSamples);
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

}  // namespace
}  // namespace icp::oracle
