#include "core/propagation.h"

namespace icp {

Propagation::Propagation(int num_variables, std::vector<std::vector<int>> scopes, double ratio,
                         std::int64_t max_revise_calls)
    : scopes_(std::move(scopes)),
      revisers_of_(num_variables),
      ratio_(ratio),
      max_revise_calls_(max_revise_calls),
      queue_(scopes_.size()),
      queued_(scopes_.size(), 0) {
  for (int r = 0; r < num_revisers(); ++r)
    for (int v : scopes_[r]) revisers_of_[v].push_back(r);
}

void Propagation::Push(int r) {
  if (queued_[r]) return;
  queued_[r] = 1;
  std::size_t tail = head_ + count_;
  if (tail >= queue_.size()) tail -= queue_.size();
  queue_[tail] = r;
  ++count_;
}

int Propagation::Pop() {
  const int r = queue_[head_];
  if (++head_ == queue_.size()) head_ = 0;
  --count_;
  queued_[r] = 0;
  return r;
}

ContractSummary Propagation::Run(Box& box, const ContractContext& context, Revisers& revisers) {
  head_ = count_ = 0;
  if (context.all_changed()) {
    for (int r = 0; r < num_revisers(); ++r) Push(r);
  } else {
    for (int v : context.changed())
      for (int r : revisers_of_[v]) Push(r);
  }
  ContractSummary summary;
  // Revisers only narrow, so the box differs from the one given as soon as
  // one revise changed a bound.
  bool changed = false;
  auto finish = [&](ContractStatus status, const char* message) {
    while (count_ > 0) Pop();  // leave the queue clean for the next call
    if (status == ContractStatus::kEmpty) box.SetEmpty();
    summary.status = status;
    summary.message = message;
    return summary;
  };
  while (count_ > 0) {
    if (summary.work.revise_calls >= max_revise_calls_)
      return finish(ContractStatus::kStopped, "max_revise_calls reached");
    if ((summary.work.revise_calls & 255) == 255 && context.stop().ShouldStop())
      return finish(ContractStatus::kStopped, "stopped (time limit)");
    const int r = Pop();
    const std::vector<int>& scope = scopes_[r];
    before_.resize(scope.size());
    for (std::size_t i = 0; i < scope.size(); ++i) before_[i] = box[scope[i]];
    ++summary.work.revise_calls;
    bool idempotent = false;
    if (!revisers.Revise(r, box, summary.work, &idempotent))
      return finish(ContractStatus::kEmpty, "");
    for (std::size_t i = 0; i < scope.size(); ++i) {
      const Interval& after = box[scope[i]];
      if (after.lo() == before_[i].lo() && after.hi() == before_[i].hi()) continue;
      changed = true;
      if (!ShrankByMoreThan(before_[i], after, ratio_)) continue;
      for (int other : revisers_of_[scope[i]])
        if (other != r || !idempotent) Push(other);
    }
  }
  if (changed) {
    summary.status = ContractStatus::kContracted;
  } else {
    summary.status = box.IsEmpty() ? ContractStatus::kEmpty : ContractStatus::kFixpoint;
  }
  return summary;
}

namespace {
std::vector<std::vector<int>> ConstraintScopes(const CompiledSystem& system) {
  std::vector<std::vector<int>> scopes;
  for (int c = 0; c < system.num_constraints(); ++c) scopes.push_back(system.tape(c).variables());
  return scopes;
}
}  // namespace

PropagationContractor::PropagationContractor(std::shared_ptr<const CompiledSystem> system,
                                             double ratio, std::int64_t max_revise_calls)
    : system_(std::move(system)),
      propagation_(system_->num_variables(), ConstraintScopes(*system_), ratio,
                   max_revise_calls) {}

ContractSummary PropagationContractor::Contract(Box& box, ContractContext& context) {
  incremental_ = !context.all_changed();
  return propagation_.Run(box, context, *this);
}

}  // namespace icp
