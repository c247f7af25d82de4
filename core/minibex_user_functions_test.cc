// Minibex user functions and temporaries: a call builds the DAG its body
// written out by hand would, and misuse is an error with its position.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/minibex_parser.h"
#include "core/minibex_parser_testing.h"

namespace icp {
namespace {

using testing::BadInput;
using testing::Eval;
using testing::ExpectRejected;
using testing::PointBox;

// What a constraint's DAG is made of: its text, its distinct nodes, and its
// distinct interval constants (each a real of its own).
struct DagSummary {
  std::string text;
  int nodes = 0;
  int interval_constants = 0;
  bool operator==(const DagSummary&) const = default;
};

DagSummary Summarize(const ConstraintSystem& csp, int c) {
  const ExprGraph& g = csp.graph();
  const int root = csp.constraints()[c].root;
  DagSummary s{g.ToString(root, csp.names())};
  std::unordered_set<int> seen;
  std::vector<int> stack = {root};
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    if (!seen.insert(id).second) continue;
    const ExprNode& node = g.node(id);
    if (node.op == Op::kConst && !node.value.IsPoint()) ++s.interval_constants;
    if (node.a >= 0) stack.push_back(node.a);
    if (node.b >= 0) stack.push_back(node.b);
  }
  s.nodes = static_cast<int>(seen.size());
  return s;
}

void ExpectSameSystems(const std::string& with_functions, const std::string& by_hand) {
  const ConstraintSystem a = ParseMinibex(with_functions), b = ParseMinibex(by_hand);
  ASSERT_EQ(a.names(), b.names());
  ASSERT_EQ(a.constraints().size(), b.constraints().size());
  for (int c = 0; c < static_cast<int>(a.constraints().size()); ++c) {
    SCOPED_TRACE(c);
    EXPECT_EQ(a.constraints()[c].range, b.constraints()[c].range);
    const DagSummary sa = Summarize(a, c), sb = Summarize(b, c);
    EXPECT_EQ(sa.text, sb.text);
    EXPECT_EQ(sa.nodes, sb.nodes);
    EXPECT_EQ(sa.interval_constants, sb.interval_constants);
    EXPECT_EQ(Eval(a, c, a.domains()), Eval(b, c, b.domains()));
  }
}

TEST(MinibexUserFunctionsTest, ACallEvaluatesTheBodyAtTheArguments) {
  ConstraintSystem csp = ParseMinibex(R"(
    function dist(xa, ya, xb, yb)
      dx = xa - xb;
      dy = ya - yb;
      return sqrt(dx^2 + dy^2);
    end
    Variables x in [-10, 10]; y in [-10, 10];
    Constraints
      dist(x, y, 1, 2) <= 3;
      dist(x + 1, 2*y, x, 0) = 5;
    end)");
  ASSERT_EQ(csp.num_variables(), 2);
  ASSERT_EQ(csp.constraints().size(), 2u);
  EXPECT_EQ(Eval(csp, 0, PointBox({4, 6})), Interval(5));
  const Interval at_7_2 = Eval(csp, 1, PointBox({7, 2}));  // sqrt(1 + 16), enclosed
  EXPECT_LE(at_7_2.lo(), std::sqrt(17.0));
  EXPECT_GE(at_7_2.hi(), std::sqrt(17.0));
  EXPECT_LT(at_7_2.hi() - at_7_2.lo(), 1e-15);
  EXPECT_EQ(csp.constraints()[1].range, Interval(5));
}

// Functions after the variables too, calling earlier functions, with vector
// and matrix parameters given a name or an array.
TEST(MinibexUserFunctionsTest, VectorAndMatrixArgumentsAndNestedCalls) {
  ConstraintSystem csp = ParseMinibex(R"(
    Constants c[3] = (1; 2; 3);
    Variables p[3] in [-5, 5]; A[2][2] in [0, 10]; t in [0, 1];
    function sq(a) return a^2; end
    function norm2(v[3])
      s = sq(v(1)) + sq(v[1]);
      return s + sq(v(3));
    end
    function trace(M[2][2]) return M(1,1) + M[1][1]; end
    Constraints
      norm2(p) = 1;
      norm2((t; 2*t; p(1))) <= 2;
      norm2(c) + trace(A) >= 0;
      trace(((1, t); (p[2], 4))) = 5;
    end)");
  ASSERT_EQ(csp.num_variables(), 3 + 4 + 1);
  const Box at = PointBox({1, 2, 3, 4, 5, 6, 7, 0.5});  // p, A row by row, t
  EXPECT_EQ(Eval(csp, 0, at), Interval(14));
  EXPECT_EQ(Eval(csp, 1, at), Interval(0.25 + 1 + 1));
  EXPECT_EQ(Eval(csp, 2, at), Interval(14 + 4 + 7));
  EXPECT_EQ(Eval(csp, 3, at), Interval(5));
}

TEST(MinibexUserFunctionsTest, InliningBuildsTheDagWrittenByHand) {
  ExpectSameSystems(R"(
    Constants r in [0.9, 1.1];
    function f(a, b) u = a*b; return u + sin(u) - r*a; end
    function g(v[2]) return f(v(1), v(2))^2 + v(1)*[1, 2]; end
    Variables x in [-1, 1]; y in [0, 2];
    Constraints
      f(x, y) <= 1;
      g((x; y + 0.1)) = [0, 1];
      f(x + [1, 2], y) >= -3;
    end)",
                    R"(
    Constants r in [0.9, 1.1];
    Variables x in [-1, 1]; y in [0, 2];
    Constraints
      x*y + sin(x*y) - r*x <= 1;
      ((x*(y + 0.1)) + sin(x*(y + 0.1)) - r*x)^2 + x*[1, 2] = [0, 1];
      (x + [1, 2])*y + sin((x + [1, 2])*y) - r*(x + [1, 2]) >= -3;
    end)");
}

// IBEX's ctr_assign: a name bound to an expression for the constraints
// after it; in a loop body, for that iteration.
TEST(MinibexUserFunctionsTest, TemporariesInConstraintsAreSubstituted) {
  ExpectSameSystems(R"(
    Variables x[3] in [-1, 1];
    Constraints
      s = x(1) + x(2);
      s^2 + s <= 1;
      for i = 1:2;
        d = x(i+1) - x(i) + [0, 0.1];
        d*d <= 0.5;
      end;
      w = s*[1, 2];
      w - w = 0;
    end)",
                    R"(
    Variables x[3] in [-1, 1];
    Constraints
      (x(1) + x(2))^2 + (x(1) + x(2)) <= 1;
      (x(2) - x(1) + [0, 0.1])*(x(2) - x(1) + [0, 0.1]) <= 0.5;
      (x(3) - x(2) + [0, 0.1])*(x(3) - x(2) + [0, 0.1]) <= 0.5;
      (x(1) + x(2))*[1, 2] - (x(1) + x(2))*[1, 2] = 0;
    end)");
}

TEST(MinibexUserFunctionsTest, MisuseIsAnErrorWithItsPosition) {
  const std::string f = "function f(a, b) return a + b; end\n";
  const std::vector<BadInput> cases = {
      {f + "Variables x; Constraints f(x) = 1; end", 2, 29, "takes 2 arguments, got 1"},
      {f + "Variables x; Constraints f(x, x, x) = 1; end", 2, 34, "takes 2 arguments, got more"},
      {"Variables x; Constraints g(x) = 1; end", 1, 26, "unknown function 'g'"},
      {"function f(a) return f(a) + 1; end Variables x; end", 1, 22, "recursion"},
      {f + "function f(a) return a; end Variables x; end", 2, 10, "duplicate name 'f'"},
      {f + "Variables f; end", 2, 11, "duplicate name 'f'"},
      {"function f(a, a) return a; end Variables x; end", 1, 15, "duplicate name 'a'"},
      {"function f(a) return a + q; end Variables x; end", 1, 26, "unknown identifier 'q'"},
      {"Variables x; function f(a) return a + x; end Constraints f(x) = 0; end", 1, 39,
       "not visible in a function body"},
      {"function f(a) b = a; Variables x; end", 1, 22, "expected 'return'"},
      {"function f(v[2]) return v(3); end Variables x; end", 1, 27, "out of range"},
      {"function f(v[2]) return v(1); end Variables x; Constraints f(x) = 0; end", 1, 62,
       "must be 'v[2]'"},
      {"function f(v[2]) return v(1); end Variables x[3]; Constraints f(x) = 0; end", 1, 65,
       "shape of 'v[2]', not 'x[3]'"},
      {"function f(v[2]) return (v(1); v(2)); end Variables x; end", 1, 25, "returns a vector"},
      {"Variables x; Constraints t = x; end", 1, 33, "expected a constraint after the temporary"},
      // A loop body's temporary ends with its iteration.
      {"Variables x; Constraints for i=1:1; t = x; t = 0; end; t <= 1; end", 1, 56,
       "unknown identifier 't'"},
      {"Variables x; Minimize x; function f(a) return a; end", 1, 26, "must come before"},
  };
  ExpectRejected(cases);
}

}  // namespace
}  // namespace icp
