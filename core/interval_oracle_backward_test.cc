// MPFR oracle for the backward projections: run on a z domain that holds
// the exact image of a random point, each must keep that point.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "core/interval.h"
#include "core/argument_contractor.h"
#include "core/interval_oracle_testing.h"
#include "core/projections.h"

namespace icp::oracle {
namespace {

// Samples (checked points) per projection.
constexpr int kBackwardSamples = 100000;

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
      {"atan2", 2, Dist::kAny, Binary<mpfr_atan2>,
       [](I z, Interval& y, Interval& x) { BwdAtan2(z, y, x); }},
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
  Exact e;
  Tally tally;
  int contracted = 0;
  auto check = [&](Sampler& s, const Interval& x, const Interval& y) {
    double p = s.PointIn(x);
    double q = s.PointIn(y);
    if (!Enclose(op.exact, p, q, &e)) return;
    ++tally.checked;
    Interval z = ZDomain(e, s);
    Interval x2 = x;
    Interval y2 = y;
    op.project(z, x2, y2);
    if (!(x2 == x) || !(y2 == y)) ++contracted;
    bool kept = x2.Contains(p) && (op.arity == 1 || y2.Contains(q));
    bool shrunk = x2.IsSubsetOf(x) && y2.IsSubsetOf(y);
    if (!kept || !shrunk) {
      ++tally.failures;
      ADD_FAILURE() << "Bwd" << op.name << (kept ? " grew a domain" : " lost a solution")
                    << Fmt(" z=[%.17g, %.17g] x=[%.17g, %.17g] y=[%.17g, %.17g] p=%.17g q=%.17g",
                           z.lo(), z.hi(), x.lo(), x.hi(), y.lo(), y.hi(), p, q)
                    << " x'=" << Str(x2) << " y'=" << Str(y2) << Fmt(" exact z=%.17g", e.Approx());
    }
  };
  SampleOperands(op, 0x5eed0bacULL, kBackwardSamples, tally, check);
  EXPECT_GE(tally.checked, kBackwardSamples);
  // Sound by doing nothing is not the goal: most draws must contract.
  if (op.name != "pow0") {  // z = x^0 = 1 says nothing about x
    EXPECT_GT(contracted, tally.checked / 4);
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

}  // namespace
}  // namespace icp::oracle
