// The AC3-like propagation loop (paper 000 §3), the one loop that HC3, HC4,
// BC3 and BC4 share: a FIFO queue of revisers, each scoped to the variables
// it reads and narrows; each popped reviser is revised, and every variable of
// its scope that shrank by more than `ratio` of its width re-queues the
// revisers whose scope holds it (itself included, unless its revise reported
// that a second one could change nothing). HC4, BC3 and BC4 revise the
// constraints of a compiled system (PropagationContractor); HC3 revises the
// primitive constraints of its decomposition over the box extended by its
// auxiliary variables.
#ifndef ICPBENCH_CORE_PROPAGATION_H_
#define ICPBENCH_CORE_PROPAGATION_H_

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/contractor.h"
#include "core/tape.h"

namespace icp {

// What a Propagation revises: reviser r reads and narrows only the
// components of the box in its scope, and never widens one.
class Revisers {
 public:
  // Narrows box with reviser r; returns false if r has no solution in box.
  // A revise is not assumed idempotent: even with single occurrences, a
  // backward projection that takes the hull of a union (a division by an
  // interval holding 0, an overflowed enclosure) can narrow more on a second
  // call, so a reviser whose variables shrank is queued again, unless the
  // revise sets *idempotent (false on entry) because it knows that calling
  // it again right away would narrow nothing (Tape::Revise says when).
  virtual bool Revise(int r, Box& box, WorkCounters& work, bool* idempotent) = 0;

 protected:
  ~Revisers() = default;
};

class Propagation {
 public:
  // No revisers: Run changes nothing.
  Propagation() = default;
  // scopes[r] lists the distinct variables of reviser r, as indices into
  // boxes of num_variables components. Stops after max_revise_calls revises.
  Propagation(int num_variables, std::vector<std::vector<int>> scopes, double ratio,
              std::int64_t max_revise_calls);

  // Revises box with revisers, starting from those whose scope holds one of
  // the context's changed variables, until the queue runs empty (or the
  // context's stop condition or max_revise_calls ends it: kStopped). Empties
  // box when a revise finds no solution.
  ContractSummary Run(Box& box, const ContractContext& context, Revisers& revisers);

  int num_revisers() const { return static_cast<int>(scopes_.size()); }

 private:
  void Push(int r);
  int Pop();

  std::vector<std::vector<int>> scopes_;
  std::vector<std::vector<int>> revisers_of_;  // variable -> revisers whose scope holds it
  double ratio_ = 0;
  std::int64_t max_revise_calls_ = 0;
  std::vector<int> queue_;  // a ring of num_revisers() slots
  std::vector<char> queued_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  std::vector<Interval> before_;
};

// A propagation over the constraints of a compiled system, each scoped to the
// variables of its tape; subclasses say what revising constraint c means.
class PropagationContractor : public Contractor, protected Revisers {
 public:
  PropagationContractor(std::shared_ptr<const CompiledSystem> system, double ratio,
                        std::int64_t max_revise_calls);

  // Propagates from the constraints of the context's changed variables: after
  // a change of a few variables in a box that was otherwise at a fixpoint (3B
  // shaving), this reaches the same fixpoint as propagating from every
  // constraint with far less work.
  ContractSummary Contract(Box& box, ContractContext& context) final;

  const CompiledSystem& system() const { return *system_; }
  const std::shared_ptr<const CompiledSystem>& shared_system() const { return system_; }

 protected:
  // HC4Revise of constraint c (Tape::Revise; slots are scratch). During a
  // contraction told which few variables changed (3B's trials) the same
  // constraints are revised over and over with most of their variables
  // unchanged, and it revises incrementally (Tape::ReviseIncremental, the
  // same results); a fresh contraction revises each constraint a few times
  // only, and sweeps in full.
  // (Inline: a call less in HC4's revise, the one thing its loop does.)
  bool HC4Revise(int c, Box& box, std::vector<Interval>& slots, bool* idempotent) {
    const Tape& tape = system_->tape(c);
    if (!incremental_) return tape.Revise(box, slots, idempotent);
    if (memories_.empty()) memories_.resize(system_->num_constraints());
    return tape.ReviseIncremental(box, memories_[c], slots, idempotent);
  }

 private:
  std::shared_ptr<const CompiledSystem> system_;
  Propagation propagation_;
  bool incremental_ = false;
  std::vector<ForwardMemory> memories_;  // per constraint, for HC4Revise
};

}  // namespace icp

#endif  // ICPBENCH_CORE_PROPAGATION_H_
