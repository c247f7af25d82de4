// Minibex parser tests of operators and functions: powers and exponents,
// logarithms, atan2, IBEX's inverse functions, and constraints in
// parentheses, by what the parsed constraints evaluate to.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/minibex_parser.h"
#include "core/minibex_parser_testing.h"

namespace icp {
namespace {

using testing::Eval;
using testing::PointBox;

TEST(MinibexParserTest, PowersAndUnaryMinus) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants k = 2;
    Variables x in [1, 3];
    Constraints
      x^-1 = 0;
      x^(-2) = 0;
      -x^2 = 0;
      x^2^3 = 0;      // left-associative, as IBEX's parser: (x^2)^3
      x^(k+1) = 0;
      x^0 = 0;
      2^-1 * x = 0;
      - - x = 0;
      x^-1^2 = 0;     // a signed exponent takes the chain: x^(-(1^2))
      2^3^2 * x = 0;  // (2^3)^2 = 64, IBEX's reading (not 2^9)
    end)");
  ASSERT_EQ(csp.constraints().size(), 10u);
  const Box two = PointBox({2});
  EXPECT_EQ(Eval(csp, 0, two), Interval(0.5));
  EXPECT_EQ(Eval(csp, 1, two), Interval(0.25));
  EXPECT_EQ(Eval(csp, 2, two), Interval(-4.0));
  EXPECT_EQ(Eval(csp, 3, two), Interval(64.0));
  EXPECT_EQ(Eval(csp, 4, two), Interval(8.0));
  EXPECT_EQ(Eval(csp, 5, two), Interval(1.0));
  EXPECT_EQ(Eval(csp, 6, two), Interval(1.0));
  EXPECT_EQ(Eval(csp, 7, two), Interval(2.0));
  EXPECT_EQ(Eval(csp, 8, two), Interval(0.5));
  EXPECT_EQ(Eval(csp, 9, two), Interval(128.0));
  // -x^2 on [1, 3] is [-9, -1], not (-x)^2 = [1, 9].
  EXPECT_EQ(Eval(csp, 2, csp.domains()), Interval(-9, -1));
}

// Any exponent other than an integer constant reads as IBEX reads it:
// e1^e2 = exp(e2 * ln(e1)), so it encloses the real power where e1 > 0
// and is undefined (an empty enclosure) where e1 <= 0.
TEST(MinibexParserTest, ARealOrVariableExponentIsExpOfTheProductWithTheLog) {
  ConstraintSystem csp = ParseMinibex(R"(
    Variables x in [1, 3]; y in [0.5, 2];
    Constraints
      x^0.5 = 0;
      x^y = 0;
      2^0.5 * x = 0;
      x^[2, 3] = 0;
      x^(y + 1)^2 = 0;  // left-associative: (x^(y + 1))^2
      x^2.0 = 0;        // an integer: a power
    end)");
  ASSERT_EQ(csp.constraints().size(), 6u);
  EXPECT_EQ(csp.graph().node(csp.constraints()[0].root).op, Op::kExp);
  EXPECT_EQ(csp.graph().node(csp.constraints()[5].root).op, Op::kSqr);
  const Box point = PointBox({2, 1.5});
  auto encloses = [](const Interval& x, double v, double tolerance) {
    return x.Contains(v) && x.Width() < tolerance;
  };
  EXPECT_TRUE(encloses(Eval(csp, 0, point), std::sqrt(2.0), 1e-14)) << Eval(csp, 0, point);
  EXPECT_TRUE(encloses(Eval(csp, 1, point), std::pow(2.0, 1.5), 1e-14)) << Eval(csp, 1, point);
  EXPECT_TRUE(encloses(Eval(csp, 2, point), 2 * std::sqrt(2.0), 1e-14)) << Eval(csp, 2, point);
  EXPECT_TRUE(encloses(Eval(csp, 4, point), std::pow(2.0, 5.0), 1e-12)) << Eval(csp, 4, point);
  const Interval thick = Eval(csp, 3, point);  // [2^2, 2^3]
  EXPECT_TRUE(thick.Contains(4) && thick.Contains(8) && thick.Width() < 4 + 1e-12) << thick;
  // On the whole domain: every real power of the box is inside.
  const Interval whole = Eval(csp, 1, csp.domains());
  for (double x : {1.0, 1.7, 3.0})
    for (double y : {0.5, 1.2, 2.0}) EXPECT_TRUE(whole.Contains(std::pow(x, y))) << x << "^" << y;
  // A base that is never positive leaves nothing.
  const ConstraintSystem negative = ParseMinibex("Variables x in [-3, -1]; Constraints x^0.5 = 0; end");
  EXPECT_TRUE(Eval(negative, 0, negative.domains()).IsEmpty());
}

// IBEX's inverse trigonometric and hyperbolic functions: at points their
// enclosures hold libm's values (to a few ulps, which the tolerance allows
// for), over intervals every sampled value, and outside the domain nothing.
TEST(MinibexParserTest, InverseTrigonometricAndHyperbolicFunctionsEncloseTheirValues) {
  struct Case {
    const char* name;
    double (*f)(double);
    double lo, hi;  // inside the domain
    double outside;
  };
  const Case cases[] = {{"asin", std::asin, -1, 1, 1.5},      {"acos", std::acos, -1, 1, -1.5},
                        {"asinh", std::asinh, -30, 40, NAN},  {"acosh", std::acosh, 1, 50, 0.5},
                        {"atanh", std::atanh, -0.99, 0.99, 2}};
  for (const Case& c : cases) {
    const ConstraintSystem csp = ParseMinibex(std::string("Variables x in [") + std::to_string(c.lo) + ", " +
                                              std::to_string(c.hi) + "]; Constraints " + c.name +
                                              "(x) = 0; end");
    const Interval whole = Eval(csp, 0, csp.domains());
    for (int i = 0; i <= 40; ++i) {
      const double x = c.lo + (c.hi - c.lo) * i / 40;
      const double v = c.f(x);
      const Interval at = Eval(csp, 0, PointBox({x}));
      const double slack = 4e-15 * std::max(1.0, std::fabs(v));
      EXPECT_TRUE(at.lo() <= v + slack && v - slack <= at.hi()) << c.name << "(" << x << ") = " << v << ": " << at;
      EXPECT_LT(at.Width(), 1e-7 * std::max(1.0, std::fabs(v))) << c.name << "(" << x << "): " << at;
      EXPECT_TRUE(whole.lo() <= v + slack && v - slack <= whole.hi()) << c.name << " over the domain";
    }
    if (!std::isnan(c.outside)) {
      EXPECT_TRUE(Eval(csp, 0, PointBox({c.outside})).IsEmpty()) << c.name << "(" << c.outside << ")";
    }
  }
}

// IBEX's '(' ctr ')': a constraint may stand in parentheses, which a
// parenthesised expression on the left of a relation is not.
TEST(MinibexParserTest, AConstraintMayStandInParentheses) {
  const ConstraintSystem csp = ParseMinibex(R"(
    Variables x in [0, 3]; y in [0, 3];
    Constraints
      (x <= 1);
      ((y >= 2));
      (x + 1)^2 <= 3;
      (x in [0.5, 2]);
      ((x) + (y) = 2);
      (max(x, y) < 2.5);
    end)");
  ASSERT_EQ(csp.constraints().size(), 6u);
  EXPECT_EQ(csp.constraints()[0].range, Interval(-kInf, 1));
  EXPECT_EQ(csp.constraints()[1].range, Interval(2, kInf));
  EXPECT_EQ(csp.constraints()[2].range, Interval(-kInf, 3));
  EXPECT_EQ(Eval(csp, 2, PointBox({1, 0})), Interval(4.0));  // (x + 1)^2
  EXPECT_EQ(csp.constraints()[3].range, Interval(0.5, 2));
  EXPECT_EQ(Eval(csp, 4, PointBox({0.5, 1})), Interval(1.5));
  EXPECT_EQ(csp.constraints()[5].range, Interval(-kInf, 2.5));
  EXPECT_THROW(ParseMinibex("Variables x; Constraints (x <= 1; end"), MinibexError);
}

TEST(MinibexParserTest, LnIsLog) {
  ConstraintSystem csp = ParseMinibex(
      "Variables x in [1, 2]; Constraints ln(x) = 0; log(x) = 0; end");
  ASSERT_EQ(csp.constraints().size(), 2u);
  // Hash-consing makes equal expressions one node.
  EXPECT_EQ(csp.constraints()[0].root, csp.constraints()[1].root);
  EXPECT_EQ(csp.graph().node(csp.constraints()[0].root).op, Op::kLog);
}

}  // namespace
}  // namespace icp
