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

}  // namespace icp
