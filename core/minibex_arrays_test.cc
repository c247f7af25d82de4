// Minibex vectors and matrices (constants, variables, indexing), IBEX's
// hexadecimal doubles and a system without a Constraints section.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/minibex_parser.h"
#include "core/minibex_parser_testing.h"

namespace icp {
namespace {

using testing::BadInput;
using testing::Decimal;
using testing::Eval;
using testing::ExpectRejected;
using testing::PointBox;

TEST(MinibexArraysTest, VectorAndMatrixConstantsAreIndexedLikeVariables) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants
      c[3] = (1; 2; 0.1);
      M[2][2] = ((1, 2); (3, 4));
      r[1][2] = (5, 6);
      d[2] in [0, 1];
      I[2][2] in (([0, 1], 0); (0, [0, 1]));
    Variables x in [-10, 10];
    Constraints
      x + c(1) + c[1] = 0;
      x*M(2,1) + M[0][1] = 0;
      x - r(1,2) + d(2) = 0;
      x*c(3) + I[1][1] = 0;
    end)");
  EXPECT_EQ(Eval(csp, 0, PointBox({0.5})), Interval(3.5));
  EXPECT_EQ(Eval(csp, 1, PointBox({0.5})), Interval(3.5));
  EXPECT_EQ(Eval(csp, 2, PointBox({0.5})), Interval(-5.5, -4.5));
  // 0.1 is enclosed, as a scalar constant would be.
  EXPECT_EQ(Eval(csp, 3, PointBox({1})), Decimal("0.1") + Interval(0, 1));
}

// x[2][3] becomes x[0][0] .. x[1][2], row by row; x(i,j) counts from 1.
TEST(MinibexArraysTest, MatrixVariablesAreScalarsNamedRowByRow) {
  ConstraintSystem csp = ParseMinibex(R"(
    Variables A[2][3] in [0, 10]; y;
    Constraints
      A(1,1) + A(2,3) = 1;
      A[0][2] - A[1][0] = y;
      for i = 1:2; for j = 1:3; A(i,j) <= i*j; end; end;
    end)");
  EXPECT_EQ(csp.names(), (std::vector<std::string>{"A[0][0]", "A[0][1]", "A[0][2]", "A[1][0]",
                                                   "A[1][1]", "A[1][2]", "y"}));
  EXPECT_EQ(csp.domains()[5], Interval(0, 10));
  ASSERT_EQ(csp.constraints().size(), 2u + 6u);
  const Box at = PointBox({1, 2, 3, 4, 5, 6, 7});
  EXPECT_EQ(Eval(csp, 0, at), Interval(7));
  EXPECT_EQ(Eval(csp, 1, at), Interval(3 - 4 - 7));
  EXPECT_EQ(csp.constraints()[2 + 5].range, Interval(-kInf, 6));
  EXPECT_EQ(Eval(csp, 2 + 5, at), Interval(6));
}

// IBEX writes exact doubles as '#' and their 64 bits in hexadecimal.
TEST(MinibexArraysTest, HexadecimalLiteralIsThatDoubleExactly) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants h = #3FB999999999999A;
    Variables x in [#BFF0000000000000, #4000000000000000];
    Constraints x = h; x + #3FF8000000000000 >= 0; end)");
  EXPECT_EQ(csp.domains()[0], Interval(-1, 2));
  EXPECT_EQ(csp.constraints()[0].range, Interval(0.1));  // the double nearest 1/10, a point
  EXPECT_EQ(Eval(csp, 1, PointBox({0})), Interval(1.5));
}

// IBEX ends a system without constraints after its last declaration.
TEST(MinibexArraysTest, ASystemNeedsNoConstraintsSection) {
  for (const std::string text : {"Variables x in [0,1]; y;", "Variables x in [0,1]; y; Minimize x + y;",
                                 "Variables x in [0,1]; y; end"}) {
    SCOPED_TRACE(text);
    ConstraintSystem csp = ParseMinibex(text);
    EXPECT_EQ(csp.num_variables(), 2);
    EXPECT_TRUE(csp.constraints().empty());
  }
}

TEST(MinibexArraysTest, MisuseIsAnErrorWithItsPosition) {
  const std::vector<BadInput> cases = {
      {"Constants c[2] = (1; 2; 3); Variables x; end", 1, 18, "wrong shape"},
      {"Constants c[2] = (1; [2, 1]); Variables x; end", 1, 22, "empty interval"},
      {"Constants M[2][2] = ((1, 2); (3)); Variables x; end", 1, 30, "same shape"},
      {"Variables x; Constants c = 1; end", 1, 14, "expected 'Constraints' or 'end'"},
      {"Constants c[2] = (1; x); Variables x; end", 1, 22, "unknown identifier 'x'"},
      {"Variables A[2][2]; Constraints A(1) = 0; end", 1, 35, "takes two indices"},
      {"Variables A[2][2]; Constraints A[0] = 0; end", 1, 37, "takes two indices"},
      {"Variables A[2][2]; Constraints A(1,3) = 0; end", 1, 36, "index 3 out of range"},
      {"Variables A[2][2]; Constraints A = 0; end", 1, 32, "must be indexed, as in A(1,1)"},
      {"Variables x; Constraints x = (1; 2); end", 1, 32, "only a constant's value"},
      {"Variables x; Constraints x = #7FF0000000000000; end", 1, 30, "finite"},
      {"Variables x; Constraints x = #10000000000000000; end", 1, 30, "16 hexadecimal"},
      {"Variables x; Constraints x = #3FFz; end", 1, 30, "bad number '#3FFz'"},
      {"Variables x; Constraints x = # 1; end", 1, 30, "unexpected character '#'"},
  };
  ExpectRejected(cases);
}

}  // namespace
}  // namespace icp
