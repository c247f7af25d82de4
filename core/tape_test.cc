#include "core/tape.h"

#include <gtest/gtest.h>

#include <iterator>
#include <algorithm>
#include <random>

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

TEST(TapeTest, BackwardCutsOperandsToTheDomainOfSqrtAndLog) {
  // The root lies in its range, yet x loses its negative part.
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-1, 4});
  Expr y = csp.AddVariable("y", {1, 2});
  csp.AddConstraint(Sqrt(x) + y, Interval(0, 10));
  csp.AddConstraint(Log(x) + y, Interval());
  for (int c = 0; c < 2; ++c) {
    Tape tape(csp.graph(), csp.constraints()[c]);
    Box box = csp.domains();
    std::vector<Interval> slots;
    ASSERT_TRUE(tape.Revise(box, slots));
    EXPECT_EQ(box[0], Interval(0, 4)) << c;
    EXPECT_EQ(box[1], Interval(1, 2)) << c;
  }
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

TEST(TapeTest, ConstantSubExpressionsAreFoldedWithTheSameEnclosure) {
  // dth / 2 is folded at construction; Forward gives what evaluating it on
  // every call gave.
  ConstraintSystem csp;
  Expr th = csp.AddVariable("th", {0.1, 0.3});
  Expr dth = csp.Constant(Interval(0.01, 0.02));
  csp.AddConstraint(Cos(th + dth / 2.0), Interval());
  Tape tape(csp.graph(), csp.constraints()[0]);
  EXPECT_EQ(tape.size(), 6);  // th, dth, 2, dth / 2, th + dth / 2, cos
  std::vector<Interval> slots;
  EXPECT_EQ(tape.Forward(csp.domains(), slots),
            Cos(Interval(0.1, 0.3) + Interval(0.01, 0.02) / Interval(2.0)));
}

// Revise on domains says it is not idempotent, and indeed a second call
// narrows variable var further.
void ExpectNotIdempotent(const Tape& tape, const Box& domains, int var) {
  Box box = domains;
  std::vector<Interval> slots;
  bool idempotent = true;
  ASSERT_TRUE(tape.Revise(box, slots, &idempotent));
  EXPECT_FALSE(idempotent);
  Box again = box;
  ASSERT_TRUE(tape.Revise(again, slots));
  EXPECT_LT(again[var].Width(), box[var].Width());
}

// Revise reports idempotence only where a second call changes nothing, and
// the two ways it can fail (see Tape::idempotent_when_bounded) do fail.
TEST(TapeTest, ReviseClaimsIdempotenceOnlyWhenItHolds) {
  {
    // The car-track odometry constraint: single occurrences, continuous.
    ConstraintSystem csp;
    Expr xp = csp.AddVariable("xp", {-10, 10});
    Expr thp = csp.AddVariable("thp", {0.1, 0.3});
    Expr xk = csp.AddVariable("xk", {-8, 12});
    csp.AddConstraint(xk, Relation::kEq,
                      xp + csp.Constant(Interval(2.7, 2.8)) * Cos(thp + csp.Constant(0.01)));
    Tape tape(csp.graph(), csp.constraints()[0]);
    EXPECT_TRUE(tape.idempotent_when_bounded());
    Box box = csp.domains();
    std::vector<Interval> slots;
    bool idempotent = false;
    ASSERT_TRUE(tape.Revise(box, slots, &idempotent));
    EXPECT_TRUE(idempotent);
    EXPECT_NE(box, csp.domains());
    Box again = box;
    ASSERT_TRUE(tape.Revise(again, slots));
    EXPECT_EQ(again, box);
  }
  {
    // Overflow: sinh(-800) is -inf, and only the second call, on x without
    // the overflowing part, narrows y.
    ConstraintSystem csp;
    Expr x = csp.AddVariable("x", {-800, 1.3});
    Expr y = csp.AddVariable("y", {-0.5, 2.5});
    csp.AddConstraint(Sqr(y) * Sinh(x), Interval(0.5, 3));
    Tape tape(csp.graph(), csp.constraints()[0]);
    EXPECT_TRUE(tape.idempotent_when_bounded());
    ExpectNotIdempotent(tape, csp.domains(), 1);
  }
  {
    // Division by an interval holding 0: the quotient is the whole line
    // until z is narrowed, then it narrows y.
    ConstraintSystem csp;
    Expr x = csp.AddVariable("x", {-2, -1});
    Expr y = csp.AddVariable("y", {-1.5, 2.5});
    Expr z = csp.AddVariable("z", {-0.1, 2});
    csp.AddConstraint(y - x / z, Interval(-2, 1));
    Tape tape(csp.graph(), csp.constraints()[0]);
    EXPECT_FALSE(tape.idempotent_when_bounded());
    ExpectNotIdempotent(tape, csp.domains(), 1);
  }
  {
    // A variable occurring twice.
    ConstraintSystem csp;
    Expr x = csp.AddVariable("x", {-2, 4});
    csp.AddConstraint(x * x + x, Interval(0.0));
    EXPECT_FALSE(Tape(csp.graph(), csp.constraints()[0]).idempotent_when_bounded());
  }
}

// The incremental sweeps of a univariate search, after one Forward on the
// box, give what the full sweeps give on the box with the variable set,
// including empty results (sqrt and division undefined on part of the
// domain) and derivatives; paired sweeps give what two single ones give, and
// none of them writes to the Forward's slots.
TEST(TapeTest, UnivariateSweepsMatchTheFullSweeps) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 3});
  Expr y = csp.AddVariable("y", {0.5, 1});
  Expr z = csp.AddVariable("z", {-1, 4});
  csp.AddConstraint(Sqrt(x) * Cos(y + z) + x / (z - 1.0) + Sqr(y), Interval(0.0));
  Tape tape(csp.graph(), csp.constraints()[0]);
  std::vector<Interval> full, dfull, slots;
  const Interval values[] = {{-2, 3}, {-2, -1}, {0, 0}, {1, 1}, {0.25, 2.5}, {2, 3}, {-1, 4}};
  auto same = [](const Interval& a, const Interval& b) {
    return a.IsEmpty() ? b.IsEmpty() : !b.IsEmpty() && a.lo() == b.lo() && a.hi() == b.hi();
  };
  for (int var : tape.variables()) {
    ASSERT_FALSE(tape.Forward(csp.domains(), slots).IsEmpty());
    const std::vector<Interval> forward = slots;
    const Tape::UnivariateCode univariate = tape.Univariate(var);
    const std::span<const UnivariateInstr> code = univariate.code;
    ASSERT_EQ(code.size(), univariate.slots.size());
    ASSERT_FALSE(code.empty());
    EXPECT_EQ(univariate.slots.back(), tape.size() - 1);
    std::vector<Interval> lane(code.size()), other(code.size()), dlane(code.size());
    for (const Interval& v : values) {
      Box box = csp.domains();
      box[var] = v;
      Interval d_full;
      const Interval f_full = tape.ForwardWithDerivative(box, var, full, dfull, &d_full);
      const Interval f = Tape::ForwardUnivariate(code, v, slots, lane.data());
      ASSERT_TRUE(same(f, f_full)) << "var " << var << " at " << v;
      for (const Interval& w : values) {
        // Lanes that hold nothing from earlier sweeps: a skipped step shows.
        std::fill(other.begin(), other.end(), Interval(-7, 7));
        std::fill(dlane.begin(), dlane.end(), Interval(-7, 7));
        const auto [fv, fw] =
            Tape::ForwardUnivariatePair(code, v, w, slots, other.data(), dlane.data());
        EXPECT_TRUE(same(fv, f_full)) << "var " << var << " at " << v << " paired with " << w;
        EXPECT_TRUE(same(fw, Tape::ForwardUnivariate(code, w, slots, dlane.data())))
            << "var " << var << " at " << w << " paired with " << v;
      }
      if (f.IsEmpty()) continue;
      Tape::ForwardUnivariate(code, v, slots, lane.data());
      const Interval d = Tape::DerivativeUnivariate(code, slots, lane.data(), dlane.data());
      EXPECT_TRUE(d == d_full) << "var " << var << " at " << v;
    }
    for (std::size_t s = 0; s < slots.size(); ++s)
      EXPECT_TRUE(SameBits(slots[s], forward[s])) << "slot " << s << " written";
  }
}

// The system of the incremental-sweep tests: tapes of 2 to 5 variables
// (swept in part up to Tape::kMaskVariables, in full beyond), with sqrt and
// division undefined on part of the domains.
ConstraintSystem IncrementalSweepSystem() {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 3});
  Expr y = csp.AddVariable("y", {0.5, 1});
  Expr z = csp.AddVariable("z", {-1, 4});
  Expr t = csp.AddVariable("t", {-1, 1});
  csp.AddConstraint(Sqrt(x) * Cos(y + z) + x / (z - 1.0) + Sqr(y), Interval(-1, 1));
  Expr u = csp.AddVariable("u", {-3, 3});
  csp.AddConstraint(t - (y + 2.0 * Cos(z + 0.5)), Interval(0.0));  // car-track shape
  csp.AddConstraint(x * u + Sin(t) - y / z + Sqr(u - t), Interval(0, 2));  // 5 variables
  return csp;
}

// The values the variables take along those tests' sequences: ones that
// empty the forward sweep, -0 for +0, unbounded ones.
const Interval kSweepValues[] = {{-2, 3},  {-2, -1}, {0, 0},  {-0.0, 0},  {1, 1},
                                     {0.25, 2.5}, {2, 3}, {-1, 4}, {0.5, 1},   {-1, 1},
                                     {-kInf, 1},  {2, kInf}, Interval::Entire()};

// ReviseIncremental, with one memory kept along a sequence of boxes in which
// a few variables change at a time (to values that empty the forward sweep,
// to -0 for +0, to unbounded ones, back to earlier values), does what Revise
// does: the same result, the same box and the same idempotence claim, bit
// for bit; on tapes of few variables (swept in part) and of many (in full).
TEST(TapeTest, IncrementalRevisionsMatchFullOnes) {
  const ConstraintSystem csp = IncrementalSweepSystem();
  const auto& values = kSweepValues;
  std::mt19937 rng(7);
  for (const Constraint& constraint : csp.constraints()) {
    Tape tape(csp.graph(), constraint);
    ForwardMemory memory;
    std::vector<Interval> slots, full_slots;
    Box box = csp.domains();
    for (int step = 0; step < 400; ++step) {
      for (int var : tape.variables())
        if (rng() % 3 == 0) box[var] = values[rng() % std::size(values)];
      Box full = box, incremental = box;
      bool full_idempotent = false, incremental_idempotent = false;
      const bool full_ok = tape.Revise(full, full_slots, &full_idempotent);
      const bool ok = tape.ReviseIncremental(incremental, memory, slots, &incremental_idempotent);
      ASSERT_EQ(ok, full_ok) << "step " << step;
      if (!ok) continue;  // the box is then partly contracted and dropped
      for (int var : tape.variables()) {
        ASSERT_TRUE(SameBits(incremental[var], full[var]))
            << "step " << step << ", var " << var << ": " << incremental[var] << " vs " << full[var];
      }
      ASSERT_EQ(incremental_idempotent, full_idempotent) << "step " << step;
      if (rng() % 4 == 0) box = full;  // go on from the contracted box too
    }
  }
}

// Reforward, along a sequence of boxes in which a few variables change at a
// time (as above), brings the slots of a Forward on the previous box to
// those of a Forward on the new one, bit for bit; after an empty result the
// next box starts from a full Forward, as BC3's revise does.
TEST(TapeTest, ReforwardMatchesAFullForward) {
  const ConstraintSystem csp = IncrementalSweepSystem();
  const auto& values = kSweepValues;
  std::mt19937 rng(11);
  int partial = 0;
  for (const Constraint& constraint : csp.constraints()) {
    Tape tape(csp.graph(), constraint);
    const std::vector<int>& vars = tape.variables();
    std::vector<Interval> slots, full;
    Box box = csp.domains();
    bool have_slots = !tape.Forward(box, slots).IsEmpty();
    for (int step = 0; step < 400; ++step) {
      int changed = 0;
      for (std::size_t i = 0; i < vars.size(); ++i) {
        if (rng() % 3 != 0) continue;
        box[vars[i]] = values[rng() % std::size(values)];
        if (i < Tape::kMaskVariables) changed |= 1 << i;
      }
      const Interval expected = tape.Forward(box, full);
      if (!have_slots) {
        have_slots = !tape.Forward(box, slots).IsEmpty();
        continue;
      }
      const Interval root = tape.Reforward(box, changed, slots);
      ASSERT_EQ(root.IsEmpty(), expected.IsEmpty()) << "step " << step;
      have_slots = !root.IsEmpty();
      if (!have_slots) continue;
      partial += vars.size() <= Tape::kMaskVariables && changed != (1 << vars.size()) - 1;
      for (int s = 0; s < tape.size(); ++s)
        ASSERT_TRUE(SameBits(slots[s], full[s])) << "step " << step << ", slot " << s;
    }
  }
  EXPECT_GT(partial, 100);  // most re-evaluations left some slots as they were
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

// A sub-ICSP (paper 004 eq. 22-25) keeps every variable and only the
// chosen constraints, in the order chosen, over a graph of their nodes only.
TEST(TapeTest, WithConstraintsKeepsTheVariablesAndTheChosenConstraints) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  Expr y = csp.AddVariable("y", {-1, 2});
  Expr z = csp.AddVariable("z", {0, 3});
  csp.AddConstraint(x + y, Interval(1.0));
  csp.AddConstraint(Sin(y) * Exp(z) - Sqr(x), Interval(0.5));
  csp.AddConstraint(Pow(z, 3) / (x - 2.0), Relation::kLeq, y);
  const ConstraintSystem part = csp.WithConstraints({2, 0});
  EXPECT_EQ(part.names(), csp.names());
  EXPECT_EQ(part.domains(), csp.domains());
  ASSERT_EQ(part.constraints().size(), 2u);
  EXPECT_EQ(part.ConstraintToString(0), csp.ConstraintToString(2));
  EXPECT_EQ(part.ConstraintToString(1), csp.ConstraintToString(0));
  EXPECT_LT(part.graph().size(), csp.graph().size());  // sin, exp, sqr left out
  CompiledSystem sys(part);
  EXPECT_EQ(sys.constraints_of(0), (std::vector<int>{0, 1}));
  EXPECT_THROW(csp.WithConstraints({3}), std::out_of_range);
}

}  // namespace
}  // namespace icp
