#include "core/tape.h"

#include <gtest/gtest.h>

namespace icp {
namespace {

TEST(TapeTest, ForwardEvaluatesTheNaturalExtension) {
  // Paper 000 §2.3: on [-3, 4], x^2 + 4x + 4 gives [-8, 36] and its factored
  // form (x + 2)^2 gives [0, 36] (the dependency problem).
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-3, 4});
  csp.AddConstraint(Sqr(x) + 4.0 * x + 4.0, Interval());
  csp.AddConstraint(Sqr(x + 2.0), Interval());
  std::vector<Interval> slots;
  Box box = csp.domains();
  EXPECT_EQ(Tape(csp.graph(), csp.constraints()[0]).Forward(box, slots), Interval(-8, 36));
  EXPECT_EQ(Tape(csp.graph(), csp.constraints()[1]).Forward(box, slots), Interval(0, 36));
}

TEST(TapeTest, SharedSubExpressionsAreOneSlotAndCountAsOccurrences) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  Expr y = csp.AddVariable("y", {0, 1});
  Expr s = x + y;
  csp.AddConstraint(s * s + x, Interval(0.0));
  Tape tape(csp.graph(), csp.constraints()[0]);
  // x, y, x+y, (x+y)*(x+y), +x: five slots, x+y computed once.
  EXPECT_EQ(tape.size(), 5);
  EXPECT_EQ(tape.variables(), (std::vector<int>{0, 1}));
  EXPECT_EQ(tape.Occurrences(0), 3);
  EXPECT_EQ(tape.Occurrences(1), 2);
}

TEST(TapeTest, BackwardProjectsThroughSharedNodes) {
  // (x + y)^2 = 4 with x, y in [0, 3]: x + y = 2, so both end up in [0, 2].
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 3});
  Expr y = csp.AddVariable("y", {0, 3});
  csp.AddConstraint(Sqr(x + y), Interval(4.0));
  Tape tape(csp.graph(), csp.constraints()[0]);
  Box box = csp.domains();
  std::vector<Interval> slots;
  ASSERT_TRUE(tape.Revise(box, slots));
  EXPECT_EQ(box[0], Interval(0, 2));
  EXPECT_EQ(box[1], Interval(0, 2));
}

TEST(TapeTest, ReviseReportsInconsistency) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-1, 1});
  csp.AddConstraint(Exp(x), Interval(10, 20));
  Tape tape(csp.graph(), csp.constraints()[0]);
  Box box = csp.domains();
  std::vector<Interval> slots;
  EXPECT_FALSE(tape.Revise(box, slots));
}

TEST(TapeTest, UndefinedEverywhereIsEmpty) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-3, -1});
  csp.AddConstraint(Sqrt(x), Interval());
  Tape tape(csp.graph(), csp.constraints()[0]);
  std::vector<Interval> slots;
  EXPECT_TRUE(tape.Forward(csp.domains(), slots).IsEmpty());
}

TEST(TapeTest, CompiledSystemIndexesConstraintsByVariable) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  Expr y = csp.AddVariable("y", {0, 1});
  Expr z = csp.AddVariable("z", {0, 1});
  csp.AddConstraint(x + y, Interval(1.0));
  csp.AddConstraint(y * z, Interval(0.5));
  CompiledSystem sys(csp);
  EXPECT_EQ(sys.constraints_of(0), (std::vector<int>{0}));
  EXPECT_EQ(sys.constraints_of(1), (std::vector<int>{0, 1}));
  EXPECT_EQ(sys.constraints_of(2), (std::vector<int>{1}));
}

}  // namespace
}  // namespace icp
