// Tape: one constraint f(x) in range compiled into a flat instruction list
// (the reachable part of the expression DAG in topological order). Forward
// evaluates interval enclosures of every sub-expression; Backward projects the
// root's range back onto the operands (HC4Revise, paper 000 §3.2). Algorithms
// share tapes and never re-parse.
#ifndef ICPBENCH_CORE_TAPE_H_
#define ICPBENCH_CORE_TAPE_H_

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include "core/box.h"
#include "core/constraint_system.h"

namespace icp {

struct TapeInstr {
  Op op;
  int a = -1;  // operand slot
  int b = -1;  // second operand slot
  int n = 0;   // variable index (kVar) or exponent (kPow)
};

// One step of a univariate sweep (Tape::Univariate): an operation whose
// operands are either slots of the Forward on the box (index >= 0) or earlier
// values of the sweep's lane (~k, the k-th); or the variable itself (kVar).
struct UnivariateInstr {
  Op op;
  int a = 0;
  int b = 0;  // a again for unary operations
  int n = 0;  // kPow's exponent
};

// A constraint's forward values kept from one revision to the next (see
// Tape::ReviseIncremental), with the variable domains they were computed on.
class ForwardMemory {
 private:
  friend class Tape;
  std::vector<Interval> slots_;   // empty: nothing kept
  std::vector<Interval> inputs_;  // parallel to Tape::variables()
  int unbounded_ = 0;             // constant and operation slots with an unbounded value
};

class Tape {
 public:
  Tape(const ExprGraph& graph, const Constraint& constraint);

  // Evaluates every slot on box; returns the root's enclosure (empty if some
  // sub-expression is undefined everywhere on the box).
  Interval Forward(const Box& box, std::vector<Interval>& slots) const;
  // Brings slots, a Forward on a box that differs from box at most in the
  // variables of the set changed (bit i: variables()[i]), up to a Forward on
  // box: re-evaluates only the slots that depend on those variables (every
  // slot for tapes of more than kMaskVariables variables). The same result
  // as Forward(box, slots), bit for bit.
  Interval Reforward(const Box& box, int changed, std::vector<Interval>& slots) const;
  // The largest number of variables for which Reforward and ReviseIncremental
  // re-evaluate only the dependent slots.
  static constexpr int kMaskVariables = 4;
  // Intersects the root slot with range and projects back to the variables,
  // writing their contracted domains into box. slots must hold a Forward pass
  // on box. Returns false when the constraint has no solution in box (box is
  // then left partly contracted: callers mark it empty). kPaired: sums and
  // differences as EvalOp<true>'s (ReviseIncremental's, the same bits).
  template <bool kPaired = false>
  bool Backward(Box& box, std::vector<Interval>& slots) const;
  // Forward evaluation with the derivative with respect to variable var
  // (interval forward-mode differentiation over the tape): returns the root's
  // enclosure and stores the enclosure of its derivative on box in
  // *derivative. slots and dslots are scratch buffers.
  Interval ForwardWithDerivative(const Box& box, int var, std::vector<Interval>& slots,
                                 std::vector<Interval>& dslots, Interval* derivative) const;
  // Incremental evaluation for a univariate search over variable var (BC3's
  // bound search), where only var's value changes between evaluations: after
  // a Forward on the box, the univariate sweeps evaluate only the slots that
  // depend on var, into a lane of their own (lane[k]: the k-th of them), and
  // read the other slots from the Forward, which they leave untouched. The
  // results are those of Forward and ForwardWithDerivative on the box with
  // var set to x, bit for bit.
  // The slots that depend on var (its own and every operation above them),
  // ascending, and their instructions in the same order with operands
  // renamed for the sweeps (see UnivariateInstr); empty if var does not
  // occur. The last slot is the root.
  struct UnivariateCode {
    std::span<const int> slots;
    std::span<const UnivariateInstr> code;
  };
  UnivariateCode Univariate(int var) const {
    // Inline, and a linear search over a constraint's few variables: BC3
    // asks once per narrowing, and copying an out-of-line call's result
    // into the narrower stalled on a store-forwarding reload.
    const auto it = std::find(variables_.begin(), variables_.end(), var);
    if (it == variables_.end()) return {};
    const std::size_t i = it - variables_.begin();
    const int begin = dependent_begin_[i], count = dependent_begin_[i + 1] - begin;
    return {std::span<const int>(dependent_slots_.data() + begin, count),
            std::span<const UnivariateInstr>(univariate_code_.data() + begin, count)};
  }
  // The root's enclosure with var = x; slots hold a Forward on the box, and
  // lane receives code.size() values (not all of them if the result is empty).
  static Interval ForwardUnivariate(std::span<const UnivariateInstr> code, const Interval& x,
                                    const std::vector<Interval>& slots, Interval* lane);
  // Two of those sweeps in one pass, for the two edge tests of a bound
  // search: the roots' enclosures with var = x (lane_x) and var = y (lane_y).
  static std::pair<Interval, Interval> ForwardUnivariatePair(
      std::span<const UnivariateInstr> code, const Interval& x, const Interval& y,
      const std::vector<Interval>& slots, Interval* lane_x, Interval* lane_y);
  // The derivative's enclosure with respect to var at the lane of a
  // ForwardUnivariate that returned a non-empty enclosure; dlane receives
  // code.size() values.
  static Interval DerivativeUnivariate(std::span<const UnivariateInstr> code,
                                       const std::vector<Interval>& slots, const Interval* lane,
                                       Interval* dlane);
  // HC4Revise = Forward + Backward. Returns false when box has no solution.
  // If idempotent is given, it is set to whether a second Revise right after
  // this one could narrow nothing more (see idempotent_when_bounded()): the
  // tape qualifies and the forward enclosure of every operation was bounded.
  bool Revise(Box& box, std::vector<Interval>& slots, bool* idempotent = nullptr) const;
  // Revise for propagations that revise a constraint many times with few of
  // its variables changed in between (3B's trials): the forward sweep
  // re-evaluates only the slots that depend on a variable whose domain
  // differs, bit for bit, from the one memory's last sweep read, and keeps
  // the others' values in memory (tapes of more than kMaskVariables
  // variables are swept in full). Same results as Revise, bit for bit.
  bool ReviseIncremental(Box& box, ForwardMemory& memory, std::vector<Interval>& slots,
                         bool* idempotent) const;
  // True when every variable occurs once and every operation is continuous
  // with an interval image (no division, tan, log or negative power). HC4Revise
  // on such a tape is then idempotent while all forward enclosures of the
  // operations are bounded: it computes the hull of each projection of the
  // constraint's solution set, and evaluating that hull again gives back the
  // same enclosures. Unbounded enclosures break this (0 * inf is 0 on bounds,
  // overflowed results lose the link to their operands), and so do the
  // excluded operations, whose images over an interval can have a gap that
  // the hull fills (core/tape_test.cc has examples of each).
  bool idempotent_when_bounded() const { return idempotent_when_bounded_; }

  // Distinct variables of the constraint, ascending.
  const std::vector<int>& variables() const { return variables_; }
  // How often variable var occurs in the expression tree (shared
  // sub-expressions counted once per use).
  int Occurrences(int var) const;
  const Interval& range() const { return range_; }
  int size() const { return static_cast<int>(code_.size()); }
  const std::vector<TapeInstr>& code() const { return code_; }
  const Interval& constant(int slot) const { return constants_[slot]; }

 private:
  // Forward; with kTrackBounded, also clears *bounded if the enclosure of
  // some operation or constant is unbounded.
  template <bool kTrackBounded>
  Interval ForwardSweep(const Box& box, std::vector<Interval>& slots, bool* bounded) const;
  // The forward sweep of ReviseIncremental: memory's slots brought up to date
  // with box, copied into slots; empty (and memory cleared) as Forward.
  Interval ForwardIncremental(const Box& box, ForwardMemory& memory,
                              std::vector<Interval>& slots) const;
  // Slot s's value and derivative with respect to variable var from its
  // operands' (forward-mode differentiation, one slot).
  void EvalWithDerivative(int s, const Box& box, int var, std::vector<Interval>& slots,
                          std::vector<Interval>& dslots) const;

  std::vector<TapeInstr> code_;
  std::vector<Interval> constants_;  // per slot; used by kConst slots
  std::vector<int> variables_;
  std::vector<int> occurrences_;     // parallel to variables_
  // For tapes of at most kMaskVariables variables, per set of changed
  // variables (bit i: variables_[i]): the variable and operation slots that
  // depend on one of them, ascending, at recompute_slots_[recompute_begin_[m]
  // .. recompute_begin_[m + 1]).
  std::vector<int> recompute_slots_;
  std::vector<int> recompute_begin_;
  // Per variable (parallel to variables_): its dependent slots, ascending,
  // at dependent_slots_[dependent_begin_[i] .. dependent_begin_[i + 1]).
  std::vector<int> dependent_slots_;
  std::vector<int> dependent_begin_;
  std::vector<UnivariateInstr> univariate_code_;  // parallel to dependent_slots_
  Interval range_;
  bool idempotent_when_bounded_ = false;
  bool has_partial_ops_ = false;  // sqrt or log: Backward sweeps every slot
};

// Every constraint of a system, compiled, with the variable -> constraints
// incidence used by propagation queues.
class CompiledSystem {
 public:
  explicit CompiledSystem(const ConstraintSystem& system);
  int num_variables() const { return num_variables_; }
  int num_constraints() const { return static_cast<int>(tapes_.size()); }
  const Tape& tape(int c) const { return tapes_[c]; }
  const std::vector<int>& constraints_of(int var) const { return constraints_of_[var]; }
  // Largest tape, to size scratch buffers.
  int max_tape_size() const { return max_tape_size_; }

 private:
  int num_variables_;
  std::vector<Tape> tapes_;
  std::vector<std::vector<int>> constraints_of_;
  int max_tape_size_ = 0;
};

}  // namespace icp

#endif  // ICPBENCH_CORE_TAPE_H_
