#include "algorithms/bc4/bc4.h"

namespace icp {

BC4Contractor::BC4Contractor(std::shared_ptr<const CompiledSystem> system, const BC4Params& params)
    : PropagationContractor(std::move(system), params.ratio, params.max_revise_calls),
      narrower_(params.epsilon, params.max_bisections),
      slots_(this->system().max_tape_size()),
      multiple_(this->system().num_constraints()) {
  for (int c = 0; c < this->system().num_constraints(); ++c) {
    const Tape& t = this->system().tape(c);
    for (int v : t.variables())
      if (t.Occurrences(v) > 1) multiple_[c].push_back(v);
  }
}

bool BC4Contractor::Revise(int c, Box& box, WorkCounters& work, bool* idempotent) {
  const Tape& tape = system().tape(c);
  // HC4Revise is sound for every variable and optimal for single occurrences
  // (where it is idempotent too; with multiple occurrences BC3 narrowing
  // follows and nothing is claimed).
  if (!HC4Revise(c, box, slots_, multiple_[c].empty() ? idempotent : nullptr)) return false;
  if (multiple_[c].empty()) return true;
  if (tape.Forward(box, slots_).IsEmpty()) return false;
  for (int v : multiple_[c])
    if (!narrower_.Narrow(tape, v, box, slots_, work)) return false;
  return true;
}

std::unique_ptr<Contractor> MakeBC4(const ParamMap& params, const ConstraintSystem& csp) {
  return std::make_unique<BC4Contractor>(std::make_shared<CompiledSystem>(csp),
                                         ParseParams<BC4Params>("bc4", params));
}

}  // namespace icp
