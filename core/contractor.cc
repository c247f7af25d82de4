#include "core/contractor.h"

namespace icp {

std::string_view ToString(ContractStatus status) {
  switch (status) {
    case ContractStatus::kContracted: return "contracted";
    case ContractStatus::kFixpoint: return "fixpoint";
    case ContractStatus::kEmpty: return "empty";
    case ContractStatus::kStopped: return "stopped";
  }
  return "?";
}

WorkCounters& WorkCounters::operator+=(const WorkCounters& o) {
  revise_calls += o.revise_calls;
  newton_steps += o.newton_steps;
  bisections += o.bisections;
  inner_calls += o.inner_calls;
  return *this;
}

StopCondition StopCondition::After(std::chrono::duration<double> budget) {
  StopCondition s;
  const Clock::time_point now = Clock::now();
  // Saturate: a budget past the clock's range (inf, 1e300, NaN) means no
  // deadline; the plain sum overflows int64 and lands in the past.
  const double room = std::chrono::duration<double>(Clock::time_point::max() - now).count();
  if (!(budget.count() < room / 2)) return s;
  if (budget.count() <= 0) {
    s.deadline_ = now;
    return s;
  }
  s.deadline_ = now + std::chrono::duration_cast<Clock::duration>(budget);
  return s;
}

bool StopCondition::ShouldStop() const {
  if (cancel_ && cancel_->load(std::memory_order_relaxed)) return true;
  return deadline_ != Clock::time_point::max() && Clock::now() >= deadline_;
}

ContractStatus StatusOf(const Box& before, const Box& after) {
  if (after.IsEmpty()) return ContractStatus::kEmpty;
  return before == after ? ContractStatus::kFixpoint : ContractStatus::kContracted;
}

namespace {
// Adds a part's summary to the total; true when the part ended the
// contraction (empty box or stop), with the total's status set.
bool Absorb(const ContractSummary& part, Box& box, ContractSummary& total) {
  total.work += part.work;
  if (part.status == ContractStatus::kEmpty) box.SetEmpty();
  if (part.status != ContractStatus::kEmpty && part.status != ContractStatus::kStopped) return false;
  total.status = part.status;
  total.message = part.message;
  return true;
}
}  // namespace

ContractSummary SequenceContractor::Contract(Box& box, ContractContext& context) {
  const Box before = box;
  ContractSummary summary;
  ContractContext fresh(context.stop());
  for (std::size_t i = 0; i < parts_.size(); ++i)
    if (Absorb(parts_[i]->Contract(box, i == 0 ? context : fresh), box, summary)) return summary;
  summary.status = StatusOf(before, box);
  return summary;
}

ContractSummary FixpointContractor::Contract(Box& box, ContractContext& context) {
  const Box start = box;
  ContractSummary summary;
  ContractContext fresh(context.stop());
  for (int it = 0; it < max_iterations_; ++it) {
    const Box before = box;
    if (Absorb(inner_->Contract(box, it == 0 ? context : fresh), box, summary)) return summary;
    bool shrank = false;
    for (std::size_t i = 0; i < box.size() && !shrank; ++i)
      shrank = ShrankByMoreThan(before[i], box[i], ratio_);
    if (!shrank) break;
  }
  summary.status = StatusOf(start, box);
  return summary;
}

}  // namespace icp
