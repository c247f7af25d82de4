#include "algorithms/hc4/hc4.h"

namespace icp {

void Describe(HC4Params& p, ParamSet& set) {
  set.Add("ratio", &p.ratio,
          "relative width decrease of a variable that re-queues its constraints",
          Range::HalfOpen(0, 1));
  set.Add("max_revise_calls", &p.max_revise_calls,
          "HC4Revise calls allowed per contraction before stopping", Range::AtLeast(1));
}

HC4Contractor::HC4Contractor(std::shared_ptr<const CompiledSystem> system, const HC4Params& params)
    : PropagationContractor(std::move(system), params.ratio, params.max_revise_calls),
      slots_(this->system().max_tape_size()) {}

bool HC4Contractor::Revise(int c, Box& box, WorkCounters&, bool* idempotent) {
  return HC4Revise(c, box, slots_, idempotent);
}

std::unique_ptr<Contractor> MakeHC4(const ParamMap& params, const ConstraintSystem& csp) {
  return std::make_unique<HC4Contractor>(std::make_shared<CompiledSystem>(csp),
                                         ParseParams<HC4Params>("hc4", params));
}

}  // namespace icp
