// The AC3-like propagation loop shared by HC4, BC3 and BC4 (paper 000 §3):
// a FIFO queue of constraints; each popped constraint is revised, and every
// variable that shrank by more than `ratio` of its width re-queues the
// constraints it occurs in (itself included, unless its revise reported that
// a second one could change nothing). Subclasses say what revising a
// constraint means.
#ifndef ICPBENCH_CORE_PROPAGATION_H_
#define ICPBENCH_CORE_PROPAGATION_H_

#include <cstdint>
#include <memory>
#include <vector>

#include "core/contractor.h"
#include "core/tape.h"

namespace icp {

class PropagationContractor : public Contractor {
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
  // Narrows box with constraint c; returns false if c has no solution in box.
  // A revise is not assumed idempotent: even with single occurrences, a
  // backward projection that takes the hull of a union (a division by an
  // interval holding 0, an overflowed enclosure) can narrow more on a second
  // call, so a constraint whose variables shrank is queued again, unless the
  // revise sets *idempotent (false on entry) because it knows that calling
  // it again right away would narrow nothing (Tape::Revise says when).
  virtual bool Revise(int c, Box& box, WorkCounters& work, bool* idempotent) = 0;

 private:
  void Push(int c);

  std::shared_ptr<const CompiledSystem> system_;
  double ratio_;
  std::int64_t max_revise_calls_;
  std::vector<int> queue_;
  std::vector<char> queued_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  std::vector<Interval> before_;
};

}  // namespace icp

#endif  // ICPBENCH_CORE_PROPAGATION_H_
