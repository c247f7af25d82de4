#include "core/minibex_parser.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/random.h"
#include "core/tape.h"

namespace icp {
namespace {

// Enclosure of constraint c's function at box.
Interval Eval(const ConstraintSystem& csp, int c, const Box& box) {
  std::vector<Interval> slots;
  return Tape(csp.graph(), csp.constraints()[c]).Forward(box, slots);
}

Box PointBox(const std::vector<double>& point) {
  Box box;
  for (double v : point) box.push_back(Interval(v));
  return box;
}

Interval Decimal(const std::string& text) {
  Interval x;
  EXPECT_TRUE(ParseDecimal(text, &x)) << text;
  return x;
}

std::vector<int> VariablesOf(const ConstraintSystem& csp, int c) {
  return Tape(csp.graph(), csp.constraints()[c]).variables();
}

// Parses text that must be rejected; returns the error.
MinibexError ErrorOf(const std::string& text) {
  try {
    ParseMinibex(text, "t.mbx");
  } catch (const MinibexError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return MinibexError("t.mbx", -1, -1, "accepted");
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

TEST(MinibexParserTest, PowersAndUnaryMinus) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants k = 2;
    Variables x in [1, 3];
    Constraints
      x^-1 = 0;
      x^(-2) = 0;
      -x^2 = 0;
      x^2^3 = 0;      // right-associative: x^8
      x^(k+1) = 0;
      x^0 = 0;
      2^-1 * x = 0;
      - - x = 0;
    end)");
  ASSERT_EQ(csp.constraints().size(), 8u);
  const Box two = PointBox({2});
  EXPECT_EQ(Eval(csp, 0, two), Interval(0.5));
  EXPECT_EQ(Eval(csp, 1, two), Interval(0.25));
  EXPECT_EQ(Eval(csp, 2, two), Interval(-4.0));
  EXPECT_EQ(Eval(csp, 3, two), Interval(256.0));
  EXPECT_EQ(Eval(csp, 4, two), Interval(8.0));
  EXPECT_EQ(Eval(csp, 5, two), Interval(1.0));
  EXPECT_EQ(Eval(csp, 6, two), Interval(1.0));
  EXPECT_EQ(Eval(csp, 7, two), Interval(2.0));
  // -x^2 on [1, 3] is [-9, -1], not (-x)^2 = [1, 9].
  EXPECT_EQ(Eval(csp, 2, csp.domains()), Interval(-9, -1));
}

TEST(MinibexParserTest, LnIsLog) {
  ConstraintSystem csp = ParseMinibex(
      "Variables x in [1, 2]; Constraints ln(x) = 0; log(x) = 0; end");
  ASSERT_EQ(csp.constraints().size(), 2u);
  // Hash-consing makes equal expressions one node.
  EXPECT_EQ(csp.constraints()[0].root, csp.constraints()[1].root);
  EXPECT_EQ(csp.graph().node(csp.constraints()[0].root).op, Op::kLog);
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

TEST(MinibexParserTest, ErrorMessageFormat) {
  const MinibexError e = ErrorOf("Variables x in [0,1];\nConstraints\n  x + q = 0;\nend");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 7);
  EXPECT_EQ(std::string(e.what()), "t.mbx:3:7: unknown identifier 'q'");
}

struct BadInput {
  std::string text;
  int line;    // 0: do not check the position
  int column;
  std::string message_part;
};

TEST(MinibexParserTest, RejectsBadInputWithPosition) {
  const std::vector<BadInput> cases = {
      {"", 1, 1, "expected 'Variables'"},
      {"Variables x in [0,1];", 1, 22, "missing 'end'"},
      {"Variables x in [0,1]; Constraints x = 1;", 1, 41, "unterminated Constraints"},
      {"Variables x in [0,1]; Constraints x = 1; end end", 1, 46, "after the final 'end'"},
      {"Variables x in [0,1] y in [0,1]; end", 1, 22, "expected ';'"},
      {"Variables x in [0,1];\nConstraints\n x = 1\n x = 2; end", 4, 2, "expected ';'"},
      {"Variables x in [0,1]; x in [2,3]; end", 1, 23, "duplicate name 'x'"},
      {"Constants c = 1; Variables c; end", 1, 28, "duplicate name 'c'"},
      {"Variables x in [2,1]; end", 1, 16, "empty interval"},
      {"Variables x in [+oo,+oo]; end", 1, 16, "empty interval"},
      {"Variables x in [0,1];\nConstraints x^0.5 = 1; end", 2, 15, "must be an integer"},
      {"Variables x in [0,1]; y;\nConstraints x^y = 1; end", 2, 15, "integer constant"},
      {"Variables x in [0,1]; Constraints foo(x) = 1; end", 1, 35, "unknown function 'foo'"},
      {"Variables x in [0,1]; Constraints acos(x) = 1; end", 1, 35, "not supported"},
      {"Variables x[3] in [0,1];\nConstraints\n  x(4) = 1; end", 3, 5, "out of range"},
      {"Variables x[3] in [0,1]; Constraints x(0) = 1; end", 1, 40, "out of range"},
      {"Variables x[3] in [0,1]; Constraints x[3] = 1; end", 1, 40, "out of range"},
      {"Variables x[3] in [0,1];\nConstraints\n for i=1:3;\n  x(i+1) = 1;\n end;\nend", 4, 5,
       "index 4 out of range"},
      {"Variables x[3] in [0,1]; Constraints x = 1; end", 1, 38, "must be indexed"},
      {"Variables x in [0,1]; Constraints x(1) = 1; end", 1, 36, "scalar variable"},
      {"Variables x in [0,1]; Constraints x = 1e; end", 1, 39, "bad number"},
      {"Variables x in [0,1]; Constraints x = 2x; end", 1, 39, "bad number"},
      {"Variables x in [0,1]; Constraints x = 1.2.3; end", 1, 39, "bad number"},
      {"Variables x in [0,1]; Constraints x = 1 # 2; end", 1, 41, "unexpected character '#'"},
      {"Variables x in [0,1]; Constraints x = 1; /* open", 1, 42, "unterminated /* comment"},
      {"Variables x in [0,1]; Constraints x + 1; end", 1, 40, "expected '=', '<=' or '>='"},
      {"Variables x in [0,1]; Constraints x = (1 + x; end", 1, 45, "expected ')'"},
      {"Variables x in [0,1]; Constraints x = sin x; end", 1, 43, "expected '('"},
      {"Variables x in [0,1]; Constraints x = min(x); end", 1, 44, "expected ','"},
      {"Variables x in [0,1]; Constraints x = sqrt(x, x); end", 1, 45, "one argument"},
      {"Variables x in [0,1]; Constraints = 1; end", 1, 35, "expected an expression"},
      {"Variables x in [0,1]; Constraints end", 1, 35, "expected a constraint"},
      {"Variables x in [0,1]; Constraints x = oo; end", 1, 39, "interval bound"},
      {"Variables end", 1, 11, "reserved word"},
      {"Variables 2; end", 1, 11, "expected a variable name"},
      {"Variables sin in [0,1]; end", 1, 11, "reserved word"},
      {"Variables x in [0,1]; Constraints\n for i=1:2; x = i;", 2, 19, "unterminated for loop"},
      {"Variables x in [0,1]; Constraints for i=2:1; x = 0;", 1, 52, "unterminated for loop"},
      {"Variables x in [0,1]; Constraints for i=1:2.5; x = 0; end; end", 1, 43,
       "must be an integer"},
      {"Variables x in [0,1]; Constraints for x=1:2; x = 0; end; end", 1, 39, "duplicate"},
      {"Variables x in [0,1]; Constraints for i=1:2; for i=1:2; x=0; end; end; end", 1, 50,
       "duplicate"},
      {"Variables x in [0,1]; Constraints x = i; end", 1, 39, "unknown identifier 'i'"},
      {"Constants c = x; Variables x; end", 1, 15, "unknown identifier 'x'"},
      {"Constants v[2] = [1,2]; Variables x; end", 1, 12, "vector constants"},
      {"Constants c = sqrt(-1); Variables x; end", 1, 15, "empty set"},
      {"Variables x; y in [x, 1]; end", 1, 20, "constant expression"},
      {"Variables x[0]; end", 1, 13, "positive size"},
      {"Variables x[2][2]; end", 1, 12, "matrix"},
      {"Variables x[1e12]; end", 1, 13, "too large"},
      {"Variables x in [0,1]; function f(x) return x; end", 1, 23, "not supported"},
      {"Constraints x = 1; end", 1, 1, "expected 'Variables'"},
      {"Variables x in [0,1]; Constraints x = 1; end\n;;", 2, 2, "after the final 'end'"},
      {"Variables\n\tx in [0,1]\xff; end", 2, 12, "unexpected byte 0xFF"},
      {"Variables x in [0,1]; Constraints x = [1, 2; end", 1, 44, "expected ']'"},
      {"Variables x in [0,1]; Constraints x = 2^40000000000; end", 1, 41, "too large"},
  };
  for (const BadInput& c : cases) {
    SCOPED_TRACE(c.text);
    const MinibexError e = ErrorOf(c.text);
    EXPECT_NE(std::string(e.what()).find(c.message_part), std::string::npos) << e.what();
    if (c.line > 0) {
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_EQ(e.column(), c.column) << e.what();
    }
  }
}

TEST(MinibexParserTest, DeepNestingIsAnErrorNotACrash) {
  auto nested = [](int depth) {
    return "Variables x in [0,1]; Constraints " + std::string(depth, '(') + "x" +
           std::string(depth, ')') + " = 0; end";
  };
  EXPECT_NO_THROW(ParseMinibex(nested(200)));
  // Just under the limit (500 levels): no stack overflow.
  EXPECT_NO_THROW(ParseMinibex(nested(495)));
  EXPECT_THROW(ParseMinibex(nested(505)), MinibexError);
  std::string calls = "Variables x; Constraints ";
  for (int i = 0; i < 495; ++i) calls += i % 2 ? "sin(" : "max(x, ";
  EXPECT_NO_THROW(ParseMinibex(calls + "x" + std::string(495, ')') + " = 0; end"));
  std::string loops = "Variables x; Constraints ";
  for (int i = 0; i < 495; ++i) loops += "for i" + std::to_string(i) + "=1:1; ";
  loops += "x = 0" + std::string(495, ' ');
  for (int i = 0; i < 495; ++i) loops += "end; ";
  EXPECT_EQ(ParseMinibex(loops + "end").constraints().size(), 1u);
  EXPECT_THROW(ParseMinibex(nested(100000)), MinibexError);
  const std::string minus = "Variables x; Constraints " + std::string(100000, '-') + "x = 0; end";
  EXPECT_THROW(ParseMinibex(minus), MinibexError);
  std::string powers = "Variables x; Constraints x";
  for (int i = 0; i < 100000; ++i) powers += "^1";
  EXPECT_THROW(ParseMinibex(powers + " = 0; end"), MinibexError);
  std::string deep_loops = "Variables x; Constraints ";
  for (int i = 0; i < 5000; ++i) deep_loops += "for i" + std::to_string(i) + "=1:1; ";
  EXPECT_THROW(ParseMinibex(deep_loops + "x = 0;"), MinibexError);
}

TEST(MinibexParserTest, HugeLoopIsAnErrorNotAHang) {
  // Each outer iteration re-reads the (skipped) inner loop until the token
  // budget runs out.
  EXPECT_THROW(
      ParseMinibex("Variables x; Constraints for i=1:1e15; for j=2:1; x = 0; end; end; end"),
      MinibexError);
}

TEST(MinibexParserTest, ParseMinibexFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::string missing = (dir / "icpbench_no_such_file.mbx").string();
  try {
    ParseMinibexFile(missing);
    ADD_FAILURE() << "missing file accepted";
  } catch (const MinibexError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_THROW(ParseMinibexFile(dir.string()), MinibexError);

  const std::string path =
      (dir / ("icpbench_parser_test_" + std::to_string(::getpid()) + ".mbx")).string();
  {
    std::ofstream out(path);
    out << "Variables\n  x in [0, 1];\nConstraints\n  x = y;\nend\n";
  }
  try {
    ParseMinibexFile(path);
    ADD_FAILURE() << "bad file accepted";
  } catch (const MinibexError& e) {
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.column(), 7);
    EXPECT_EQ(std::string(e.what()).rfind(path + ":4:7: ", 0), 0u) << e.what();
  }
  {
    std::ofstream out(path);
    out << "Variables\n  x in [0, 1];\nConstraints\n  x = 0.5;\nend\n";
  }
  ConstraintSystem csp = ParseMinibexFile(path);
  EXPECT_EQ(csp.num_variables(), 1);
  EXPECT_EQ(csp.constraints().size(), 1u);
  std::filesystem::remove(path);
}

// Random truncations and character edits of a valid file must either parse or
// throw MinibexError: never crash, hang or throw anything else.
TEST(MinibexParserTest, FuzzedInputsParseOrThrowMinibexError) {
  const std::string base = R"(// fuzz seed
Constants
  n = 3;
  c = 0.1;
  r in [1, 2.5];
Variables
  x[n] in [-1e3, +oo];
  y in [-oo, 1];
  z;
Constraints
  for i=1:n;
    x(i)^2 + c*y >= i*0.5;
    for j=i:n; x[j-1] - x(i) <= r; end;
  end;
  sin(y)*exp(-z) + ln(2 + abs(z)) - sqrt(sqr(y)) = min(y, max(z, -2));
  /* block */ y^-1 + z^(n-1) < pi;
end
)";
  ASSERT_NO_THROW(ParseMinibex(base));
  const std::string alphabet =
      "xyzncrij0123456789.e+-*/^()[]{},;:=<>! \n\t/#_aAoO";
  const std::vector<std::string> words = {"for", "end", "oo", "in", "Variables", "Constraints",
                                          "1e308", "1e-400", "99999999999", "sqrt(", "pi", "//",
                                          "/*", "x(", "x[", "0", "-", "^"};
  RandomEngine rng(12345);
  auto pick = [&rng](std::size_t n) { return UniformIndex(rng, n); };
  int parsed = 0, rejected = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string text = base;
    const int edits = 1 + static_cast<int>(pick(3));
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = pick(text.size() + 1);
      switch (pick(5)) {
        case 0:
          text.resize(at);
          break;
        case 1:
          if (at < text.size()) text[at] = alphabet[pick(alphabet.size())];
          break;
        case 2:
          if (at < text.size()) text[at] = static_cast<char>(pick(256));
          break;
        case 3:
          text.insert(at, words[pick(words.size())]);
          break;
        default:
          text.erase(at, pick(8));
          break;
      }
    }
    try {
      ConstraintSystem csp = ParseMinibex(text, "fuzz");
      CompiledSystem compiled(csp);  // the graph must be well formed
      EXPECT_EQ(compiled.num_variables(), csp.num_variables());
      ++parsed;
    } catch (const MinibexError& e) {
      ++rejected;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected " << e.what() << " on:\n" << text;
    }
  }
  // Both outcomes must occur, or the mutations are not exercising anything.
  EXPECT_GT(parsed, 50);
  EXPECT_GT(rejected, 500);
}

}  // namespace
}  // namespace icp
