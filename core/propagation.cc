#include "core/propagation.h"

namespace icp {

PropagationContractor::PropagationContractor(std::shared_ptr<const CompiledSystem> system,
                                             double ratio, std::int64_t max_revise_calls)
    : system_(std::move(system)),
      ratio_(ratio),
      max_revise_calls_(max_revise_calls),
      queue_(system_->num_constraints()),
      queued_(system_->num_constraints(), 0) {}

void PropagationContractor::Push(int c) {
  if (queued_[c]) return;
  queued_[c] = 1;
  queue_[(head_ + count_) % queue_.size()] = c;
  ++count_;
}

ContractSummary PropagationContractor::Contract(Box& box, ContractContext& context) {
  head_ = count_ = 0;
  if (context.all_changed()) {
    for (int c = 0; c < system_->num_constraints(); ++c) Push(c);
  } else {
    for (int v : context.changed())
      for (int c : system_->constraints_of(v)) Push(c);
  }
  const StopCondition& stop = context.stop();
  ContractSummary summary;
  const Box start = box;
  auto finish = [&](ContractStatus status, const char* message) {
    while (count_ > 0) {  // leave the queue clean for the next call
      queued_[queue_[head_]] = 0;
      head_ = (head_ + 1) % queue_.size();
      --count_;
    }
    if (status == ContractStatus::kEmpty) box.SetEmpty();
    summary.status = status;
    summary.message = message;
    return summary;
  };
  while (count_ > 0) {
    if (summary.work.revise_calls >= max_revise_calls_)
      return finish(ContractStatus::kStopped, "max_revise_calls reached");
    if ((summary.work.revise_calls & 255) == 255 && stop.ShouldStop())
      return finish(ContractStatus::kStopped, "stopped (time limit)");
    const int c = queue_[head_];
    head_ = (head_ + 1) % queue_.size();
    --count_;
    queued_[c] = 0;
    const Tape& tape = system_->tape(c);
    const auto& vars = tape.variables();
    before_.resize(vars.size());
    for (std::size_t i = 0; i < vars.size(); ++i) before_[i] = box[vars[i]];
    ++summary.work.revise_calls;
    bool idempotent = false;
    if (!Revise(c, box, summary.work, &idempotent)) return finish(ContractStatus::kEmpty, "");
    for (std::size_t i = 0; i < vars.size(); ++i) {
      const Interval& after = box[vars[i]];
      if (after.lo() == before_[i].lo() && after.hi() == before_[i].hi()) continue;
      if (!ShrankByMoreThan(before_[i], after, ratio_)) continue;
      for (int other : system_->constraints_of(vars[i]))
        if (other != c || !idempotent) Push(other);
    }
  }
  summary.status = StatusOf(start, box);
  return summary;
}

}  // namespace icp
