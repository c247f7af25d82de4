#include "core/constraint_contractor.h"

namespace icp {

namespace {
// Repeating HC4Revise past this shrink ratio buys little; 50 passes bound
// the slow geometric convergence of a constraint with repeated variables.
constexpr double kRatio = 1e-3;
constexpr int kMaxPasses = 50;
}  // namespace

ConstraintContractor::ConstraintContractor(std::shared_ptr<const CompiledSystem> system,
                                           int constraint)
    : system_(std::move(system)), constraint_(constraint),
      slots_(static_cast<std::size_t>(system_->tape(constraint).size())) {}

ContractSummary ConstraintContractor::Contract(Box& box, ContractContext&) {
  ContractSummary summary;
  if (box.IsEmpty()) {
    summary.status = ContractStatus::kEmpty;
    return summary;
  }
  // Only the tape's variables can change: they alone are saved and compared
  // (this runs once per grid cell in the accumulator).
  const Tape& tape = system_->tape(constraint_);
  const std::vector<int>& vars = tape.variables();
  start_.resize(vars.size());
  bool changed = false;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    for (std::size_t i = 0; i < vars.size(); ++i) start_[i] = box[vars[i]];
    bool idempotent = false;
    ++summary.work.revise_calls;
    if (!tape.Revise(box, slots_, &idempotent)) {
      box.SetEmpty();
      summary.status = ContractStatus::kEmpty;
      return summary;
    }
    bool shrank = false;
    for (std::size_t i = 0; i < vars.size(); ++i) {
      changed = changed || !(start_[i] == box[vars[i]]);
      shrank = shrank || ShrankByMoreThan(start_[i], box[vars[i]], kRatio);
    }
    if (idempotent || !shrank) break;
  }
  summary.status = changed ? ContractStatus::kContracted : ContractStatus::kFixpoint;
  return summary;
}

std::vector<std::shared_ptr<Contractor>> ConstraintContractors(const ConstraintSystem& csp) {
  auto system = std::make_shared<const CompiledSystem>(csp);
  std::vector<std::shared_ptr<Contractor>> out;
  for (int c = 0; c < system->num_constraints(); ++c)
    out.push_back(std::make_shared<ConstraintContractor>(system, c));
  return out;
}

}  // namespace icp
