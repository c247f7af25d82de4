// Minibex parser tests on valid input: declarations, constants, loops,
// relations, layout and printing, and what the parsed constraints evaluate
// to (operators and functions: minibex_functions_test.cc).
#include "core/minibex_parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/minibex_parser_testing.h"
#include "core/random.h"
#include "core/tape.h"

namespace icp {
namespace {

using testing::Decimal;
using testing::Eval;
using testing::PointBox;

std::vector<int> VariablesOf(const ConstraintSystem& csp, int c) {
  return Tape(csp.graph(), csp.constraints()[c]).variables();
}

TEST(MinibexParserTest, PaperExample) {
  ConstraintSystem csp = ParseMinibex(
      "Variables x in [-2,4]; y in [-1,1]; Constraints x*x+y^2=2; end");
  ASSERT_EQ(csp.num_variables(), 2);
  EXPECT_EQ(csp.names(), (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(csp.domains()[0], Interval(-2, 4));
  EXPECT_EQ(csp.domains()[1], Interval(-1, 1));
  ASSERT_EQ(csp.constraints().size(), 1u);
  EXPECT_EQ(csp.constraints()[0].range, Interval(2.0));
  EXPECT_EQ(VariablesOf(csp, 0), (std::vector<int>{0, 1}));
  EXPECT_EQ(Eval(csp, 0, PointBox({1, -1})), Interval(2.0));
  // x*x is not sqr(x): on [-2, 4] it gives [-8, 16].
  EXPECT_EQ(Eval(csp, 0, csp.domains()), Interval(-8, 17));
}

// What IBEX's optimisation benchmarks use: an empty Constants section, a
// Minimize goal (read, then dropped: solve contracts constraints only), the
// thick constraint 'e in X', and max/min of more than two arguments.
TEST(MinibexParserTest, ReadsIbexOptimisationFiles) {
  ConstraintSystem csp = ParseMinibex(R"(
    constants
    variables x in [0,3]; y in [0,3]; z in [0,3];
    minimize x + y*z;
    constraints
      x + y in [1,2];
      max(x, y, z) <= 3;
      min(x, y, z, 0.5) >= 0;
    end)");
  ASSERT_EQ(csp.num_variables(), 3);
  ASSERT_EQ(csp.constraints().size(), 3u);
  EXPECT_EQ(csp.constraints()[0].range, Interval(1, 2));
  EXPECT_EQ(Eval(csp, 0, PointBox({0.25, 1, 0})), Interval(1.25));
  // Every argument counts, the last ones too.
  EXPECT_EQ(Eval(csp, 1, PointBox({1, 2, 2.5})), Interval(2.5));
  EXPECT_EQ(Eval(csp, 1, PointBox({2.75, 2, 1})), Interval(2.75));
  EXPECT_EQ(Eval(csp, 2, PointBox({1, 2, 2.5})), Interval(0.5));
  EXPECT_EQ(Eval(csp, 2, PointBox({1, 0.25, 2.5})), Interval(0.25));
  EXPECT_EQ(VariablesOf(csp, 2), (std::vector<int>{0, 1, 2}));
  // Without constraints, and with constant arguments folded.
  ConstraintSystem goal_only = ParseMinibex("Variables x in [0,1]; Minimize max(x, 2, 3) end");
  EXPECT_TRUE(goal_only.constraints().empty());
  EXPECT_EQ(ParseMinibex("Variables x in [0,9]; Constraints x = max(1, 4, 2); end")
                .constraints()[0]
                .range,
            Interval(4));
}

TEST(MinibexParserTest, LeadingUtf8ByteOrderMarkIsSkipped) {
  ConstraintSystem csp = ParseMinibex("\xEF\xBB\xBFVariables x in [0,2]; Constraints x^2=1; end");
  ASSERT_EQ(csp.num_variables(), 1);
  EXPECT_EQ(csp.names(), (std::vector<std::string>{"x"}));
  EXPECT_EQ(csp.domains()[0], Interval(0, 2));
}

TEST(MinibexParserTest, DecimalConstantIsEnclosedNotRounded) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants
      c = 0.1;
    Variables
      x in [0, 1];
    Constraints
      x = c;
      x = 0.1;
    end)");
  ASSERT_EQ(csp.constraints().size(), 2u);
  for (const Constraint& c : csp.constraints()) {
    EXPECT_LE(c.range.lo(), 0.1);
    EXPECT_GE(c.range.hi(), 0.1);
    EXPECT_NE(c.range.lo(), c.range.hi());
    EXPECT_EQ(c.range, Decimal("0.1"));
  }
}

TEST(MinibexParserTest, ConstantForms) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants
      a = -3e-5;
      b = [1, 2];
      c in [1, 2];
      d = 2*pi;
      e = a * 2 + b;     // constants may use earlier constants
      n = 3;
    Variables
      x;
    Constraints
      x = a; x = b; x = c; x = d; x = e; x = n^2;
    end)");
  ASSERT_EQ(csp.constraints().size(), 6u);
  EXPECT_EQ(csp.constraints()[0].range, -Decimal("3e-5"));
  EXPECT_EQ(csp.constraints()[1].range, Interval(1, 2));
  EXPECT_EQ(csp.constraints()[2].range, Interval(1, 2));
  const Interval two_pi = csp.constraints()[3].range;
  EXPECT_TRUE(two_pi.Contains(6.283185307179586));
  EXPECT_FALSE(two_pi.IsPoint());
  EXPECT_LT(two_pi.Width(), 1e-14);
  EXPECT_TRUE(TwoPi().IsSubsetOf(two_pi));
  const Interval e = csp.constraints()[4].range;
  EXPECT_TRUE(e.Contains(1 - 6e-5));
  EXPECT_TRUE(e.Contains(2 - 6e-5));
  EXPECT_EQ(csp.constraints()[5].range, Interval(9.0));
}

TEST(MinibexParserTest, VariableDomains) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants n = 2;
    Variables
      a in [-oo, +oo];
      b in [0, oo];
      c in [-oo, -1];
      d;
      e in [0.1, 0.2];
      f in [-n, 2*n + 1];
      g in [1e400, +oo];
      h in 3;
    end)");
  ASSERT_EQ(csp.num_variables(), 8);
  EXPECT_EQ(csp.domains()[0], Interval::Entire());
  EXPECT_EQ(csp.domains()[1], Interval(0, kInf));
  EXPECT_EQ(csp.domains()[2], Interval(-kInf, -1));
  EXPECT_EQ(csp.domains()[3], Interval::Entire());
  // Decimal bounds widen outward.
  EXPECT_EQ(csp.domains()[4].lo(), Decimal("0.1").lo());
  EXPECT_EQ(csp.domains()[4].hi(), Decimal("0.2").hi());
  EXPECT_LT(csp.domains()[4].lo(), 0.1);
  EXPECT_FALSE(Decimal("0.2").IsPoint());
  EXPECT_EQ(csp.domains()[5], Interval(-2, 5));
  EXPECT_EQ(csp.domains()[6], Interval(1.7976931348623157e308, kInf));
  EXPECT_EQ(csp.domains()[7], Interval(3.0));
  EXPECT_TRUE(csp.constraints().empty());
}

TEST(MinibexParserTest, CommaSeparatesDeclarationsAsInIbex) {
  // IBEX reads "x, y in [0,1]" as two declarations: x is unbounded.
  ConstraintSystem csp = ParseMinibex("Variables x, y in [0,1], z in [2,3]; end");
  ASSERT_EQ(csp.num_variables(), 3);
  EXPECT_EQ(csp.domains()[0], Interval::Entire());
  EXPECT_EQ(csp.domains()[1], Interval(0, 1));
  EXPECT_EQ(csp.domains()[2], Interval(2, 3));
}

TEST(MinibexParserTest, VectorComponentsOneAndZeroBased) {
  ConstraintSystem csp = ParseMinibex(R"(
    Variables
      x[3] in [0, 1];
      y;
    Constraints
      x(1) - x[0] = 0;
      x(3) + x[2] = 1;
      x(2) * y <= 0;
    end)");
  EXPECT_EQ(csp.names(), (std::vector<std::string>{"x[0]", "x[1]", "x[2]", "y"}));
  for (int i = 0; i < 3; ++i) EXPECT_EQ(csp.domains()[i], Interval(0, 1));
  ASSERT_EQ(csp.constraints().size(), 3u);
  EXPECT_EQ(VariablesOf(csp, 0), (std::vector<int>{0}));
  EXPECT_EQ(VariablesOf(csp, 1), (std::vector<int>{2}));
  EXPECT_EQ(VariablesOf(csp, 2), (std::vector<int>{1, 3}));
  // x(1) - x[0] is the same node minus itself: 0 at every point.
  EXPECT_EQ(Eval(csp, 0, PointBox({0.25, 0.5, 0.75, 2})), Interval(0.0));
  EXPECT_EQ(Eval(csp, 1, PointBox({0.25, 0.5, 0.75, 2})), Interval(1.5));
}

TEST(MinibexParserTest, ForLoopExpandsOneConstraintPerIndex) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants n = 4;
    Variables x[n] in [-10, 10];
    Constraints
      for i=1:n;
        x(i) = i*0.5;
      end;
      for k = 0:n-2; x[k+1] - x[k] >= 1; end
    end)");
  ASSERT_EQ(csp.constraints().size(), 7u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(VariablesOf(csp, i), (std::vector<int>{i}));
    EXPECT_EQ(csp.constraints()[i].range, Interval((i + 1) * 0.5));
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(VariablesOf(csp, 4 + k), (std::vector<int>{k, k + 1}));
    EXPECT_EQ(csp.constraints()[4 + k].range, Interval(1, kInf));
  }
}

TEST(MinibexParserTest, NestedLoopsUseOuterIndexInBounds) {
  ConstraintSystem csp = ParseMinibex(R"(
    Variables x[4] in [0, 10];
    Constraints
      for i=1:4;
        for j=i+1:4;
          x(i) - x(j) >= 1;
        end;
      end;
      x(1) = 9;
    end)");
  // Pairs (1,2) (1,3) (1,4) (2,3) (2,4) (3,4), then x(1) = 9.
  ASSERT_EQ(csp.constraints().size(), 7u);
  const std::vector<std::vector<int>> pairs = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (int c = 0; c < 6; ++c) EXPECT_EQ(VariablesOf(csp, c), pairs[c]) << c;
  EXPECT_EQ(VariablesOf(csp, 6), (std::vector<int>{0}));
}

TEST(MinibexParserTest, EmptyLoopIsSkipped) {
  ConstraintSystem csp = ParseMinibex(R"(
    Variables x[2] in [0, 1];
    Constraints
      for i=3:2; x(i) = 0; for j=1:2; x(j) = 1; end; end;
      x(1) = x(2);
    end)");
  ASSERT_EQ(csp.constraints().size(), 1u);
  EXPECT_EQ(VariablesOf(csp, 0), (std::vector<int>{0, 1}));
}

TEST(MinibexParserTest, RelationsGiveRanges) {
  ConstraintSystem csp = ParseMinibex(R"(
    Variables x in [0, 5]; y in [0, 5];
    Constraints
      x <= 1; x >= 2; x < 3; x > 4; x - y = 0; x <= y
    end;)");
  ASSERT_EQ(csp.constraints().size(), 6u);
  EXPECT_EQ(csp.constraints()[0].range, Interval(-kInf, 1));
  EXPECT_EQ(csp.constraints()[1].range, Interval(2, kInf));
  EXPECT_EQ(csp.constraints()[2].range, Interval(-kInf, 3));
  EXPECT_EQ(csp.constraints()[3].range, Interval(4, kInf));
  EXPECT_EQ(csp.constraints()[4].range, Interval(0.0));
  EXPECT_EQ(csp.constraints()[5].range, Interval(-kInf, 0));
  EXPECT_EQ(Eval(csp, 5, PointBox({1, 3})), Interval(-2.0));
}

TEST(MinibexParserTest, ForwardEvaluationMatchesDoubleArithmetic) {
  ConstraintSystem csp = ParseMinibex(R"(
    Variables x in [-1, 1]; y in [-1, 1];
    Constraints
      sin(x)*cos(y) + exp(x)/(1 + y^2) - sqrt(abs(x)) + min(x, y) - max(x, y)
        + tanh(x) + sinh(y) - cosh(x) + atan(y) + tan(x/3) + sqr(x - y) - 3*x*y
        + log(2 + x) - pi = 0;
    end)");
  const double x = 0.5, y = -0.25;
  const double expected = std::sin(x) * std::cos(y) + std::exp(x) / (1 + y * y) -
                          std::sqrt(std::fabs(x)) + std::min(x, y) - std::max(x, y) +
                          std::tanh(x) + std::sinh(y) - std::cosh(x) + std::atan(y) +
                          std::tan(x / 3) + (x - y) * (x - y) - 3 * x * y + std::log(2 + x) -
                          M_PI;
  const Interval got = Eval(csp, 0, PointBox({x, y}));
  EXPECT_TRUE(got.Contains(expected)) << got << " vs " << expected;
  EXPECT_LT(got.Width(), 1e-12);
}

TEST(MinibexParserTest, ConstantSubExpressionsAreFoldedSoundly) {
  // 0.1 * 3 is folded in interval arithmetic: it must contain the real 0.3,
  // which the double 0.1 * 3 (0.30000000000000004) would miss.
  ConstraintSystem csp = ParseMinibex(
      "Variables x in [0, 1]; Constraints x = 0.1 * 3; x = [0.1, 0.2] + 0.1; end");
  ASSERT_EQ(csp.constraints().size(), 2u);
  const Interval r = csp.constraints()[0].range;
  EXPECT_TRUE(Decimal("0.3").IsSubsetOf(r)) << r;
  EXPECT_LT(r.Width(), 1e-15);
  EXPECT_TRUE(Decimal("0.2").IsSubsetOf(csp.constraints()[1].range));
  EXPECT_TRUE(Decimal("0.3").IsSubsetOf(csp.constraints()[1].range));
}

TEST(MinibexParserTest, CommentsKeywordCaseAndLayout) {
  ConstraintSystem csp = ParseMinibex(
      "// header\n"
      "CONSTANTS /* block\n comment */ c = 1;\n"
      "variables\n"
      "  x in [0,\n 2];   // trailing\n"
      "Constraints\n"
      "  FOR i=1:2; x >= c*i; END;\n"
      "  x/* inline */<=2\n"
      "End");
  EXPECT_EQ(csp.num_variables(), 1);
  EXPECT_EQ(csp.domains()[0], Interval(0, 2));
  ASSERT_EQ(csp.constraints().size(), 3u);
  EXPECT_EQ(csp.constraints()[1].range, Interval(2, kInf));
}

TEST(MinibexParserTest, PrintedConstraintsParseBackToEnclosures) {
  const std::string variables = "x in [-2, 3]; y in [0.5, 4]; z[2] in [-1, 1];";
  const std::string source = "Variables " + variables + R"(
    Constraints
      x*x + y^2 = 2;
      0.1*x - y/3 <= [0.2, 0.3];
      -x^3 + exp(-y) >= 1e-3;
      sin(x + pi/7) - cos(z(1)) * z[1] = 0.7;
      min(x, y) + max(z(2), -0.5) - abs(x - z(1)) < 2;
      x^-2 + sqrt(y) + log(y) - tanh(x) + atan(z[0]) + sinh(y/4) - cosh(x/4) = 0;
      sqr(x - y) + tan(z(1)/2) > [-oo, -1];
      [1, 2] * x = y;
    end)";
  const ConstraintSystem original = ParseMinibex(source);
  ASSERT_EQ(original.constraints().size(), 8u);
  std::string printed = "Variables " + variables + "\nConstraints\n";
  for (int c = 0; c < static_cast<int>(original.constraints().size()); ++c)
    printed += "  " + original.ConstraintToString(c) + ";\n";
  printed += "end\n";
  ConstraintSystem reparsed;
  ASSERT_NO_THROW(reparsed = ParseMinibex(printed, "printed")) << printed;
  ASSERT_EQ(reparsed.num_variables(), original.num_variables());
  ASSERT_EQ(reparsed.constraints().size(), original.constraints().size()) << printed;

  RandomEngine rng(7);
  for (int c = 0; c < static_cast<int>(original.constraints().size()); ++c) {
    const Interval r0 = original.constraints()[c].range, r1 = reparsed.constraints()[c].range;
    EXPECT_TRUE(r0.IsSubsetOf(r1)) << c << ": " << r0 << " " << r1;
    EXPECT_LE(r1.Width(), r0.Width() + 1e-12 * (1 + r0.Mag()));
    for (int trial = 0; trial < 20; ++trial) {
      Box box;
      for (const Interval& d : original.domains()) {
        const double a = UniformReal(rng, d.lo(), d.hi());
        const double b = trial % 4 == 0 ? a : UniformReal(rng, d.lo(), d.hi());
        box.push_back(Interval(std::min(a, b), std::max(a, b)));
      }
      const Interval f0 = Eval(original, c, box), f1 = Eval(reparsed, c, box);
      // Printing widens constants by at most an ulp, so the reparsed
      // enclosure holds the original one and is barely wider.
      EXPECT_TRUE(f0.IsSubsetOf(f1)) << c << ": " << f0 << " " << f1 << "\n" << printed;
      if (f0.IsBounded() && f1.IsBounded()) {
        EXPECT_LE(f1.Width(), f0.Width() + 1e-9 * (1 + f0.Mag())) << c << ": " << f0 << f1;
      }
    }
  }
}

TEST(MinibexParserTest, AWholeSystemWrittenAsMinibexParsesBackToItself) {
  // Names as the car window gives them (x[17]) are not Minibex identifiers.
  ConstraintSystem original;
  Expr x = original.AddVariable("x[17]", Interval(-2.5, 0.1));
  Expr th = original.AddVariable("th[17]", Interval(-kInf, kInf));
  Expr y = original.AddVariable("y", Interval(0.3, kInf));
  original.AddConstraint(y - (x + original.Constant(Interval(2.7, 2.8)) * Cos(th)), Interval(0));
  original.AddConstraint(x * y, Interval(-kInf, 1.5));
  const std::string text = original.ToMinibex();
  ConstraintSystem reparsed;
  ASSERT_NO_THROW(reparsed = ParseMinibex(text, "written")) << text;
  ASSERT_EQ(reparsed.names(), (std::vector<std::string>{"x_17_", "th_17_", "y"})) << text;
  ASSERT_EQ(reparsed.domains().size(), original.domains().size());
  // The parser rounds an inexact decimal outward: a bound moves out by at most an ulp.
  for (std::size_t v = 0; v < original.domains().size(); ++v) {
    const Interval a = original.domains()[v], b = reparsed.domains()[v];
    EXPECT_TRUE(a.IsSubsetOf(b)) << v << ": " << a << " " << b;
    EXPECT_GE(b.lo(), std::nextafter(a.lo(), -kInf)) << v;
    EXPECT_LE(b.hi(), std::nextafter(a.hi(), kInf)) << v;
  }
  ASSERT_EQ(reparsed.constraints().size(), 2u);
  // The constraints print as they were written.
  const std::string again = reparsed.ToMinibex();
  EXPECT_EQ(again.substr(again.find("Constraints")), text.substr(text.find("Constraints")));
}

TEST(MinibexParserTest, WritingRefusesTwoNamesThatWouldCollide) {
  ConstraintSystem csp;
  csp.AddVariable("x[1]", Interval(0, 1));
  csp.AddVariable("x_1_", Interval(0, 1));
  EXPECT_THROW(csp.ToMinibex(), std::invalid_argument);
}

}  // namespace
}  // namespace icp

namespace icp {
namespace {

}  // namespace
}  // namespace icp

namespace icp {
namespace {

// atan2(y, x), y first as in C and IBEX: the argument of (x, y) in [-pi, pi]
// (thesis 003 §4.7.3), evaluated and written back.
TEST(MinibexParserTest, Atan2IsTheArgumentOfTheVector) {
  ConstraintSystem csp = ParseMinibex(
      "Variables x in [1,2]; y in [1,2]; t in [-4,4]; Constraints t = atan2(y, x); end");
  ASSERT_EQ(csp.constraints().size(), 1u);
  // t - atan2(y, x) over the domains: atan2 of the box is [atan(1/2), atan(2)].
  const Interval v = Eval(csp, 0, PointBox({2, 1, 0}));
  EXPECT_TRUE(v.Contains(-std::atan(0.5))) << v.lo() << " " << v.hi();
  EXPECT_LT(v.Width(), 1e-12);
  // The second quadrant and the cut: atan2(0, -1) holds pi.
  EXPECT_TRUE((-Eval(csp, 0, PointBox({-1, 0, 0}))).Contains(M_PI));
  EXPECT_NE(csp.ConstraintToString(0).find("atan2(y,x)"), std::string::npos)
      << csp.ConstraintToString(0);
  EXPECT_EQ(ParseMinibex(csp.ToMinibex()).ConstraintToString(0), csp.ConstraintToString(0));
}

}  // namespace
}  // namespace icp
