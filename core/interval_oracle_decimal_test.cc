// MPFR oracle for ParseDecimal: random decimals must get the tightest
// enclosure, checked against MPFR's exact decimal conversion.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <string>

#include "core/interval.h"
#include "core/interval_oracle_testing.h"

namespace icp::oracle {
namespace {

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
}  // namespace icp::oracle
