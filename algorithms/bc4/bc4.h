// BC4 (Benhamou, Goualard, Granvilliers, Puget 1999; paper 000 §3.4): HC4Revise
// on each constraint narrows the variables that occur once in it (for them
// hull and box consistency coincide); the variables that occur more than once
// are then narrowed by BC3's univariate Newton + bisection search, which is
// immune to the dependency problem. Propagated with the AC3-like queue.
//
// Sound. On constraints where every variable occurs once (the car-track CSP,
// eq. 14) BC4 does exactly what HC4 does.
#ifndef ICPBENCH_ALGORITHMS_BC4_BC4_H_
#define ICPBENCH_ALGORITHMS_BC4_BC4_H_

#include <memory>
#include <vector>

#include "algorithms/bc3/bc3.h"

namespace icp {

// BC4 takes BC3's parameters: the propagation ratio, and epsilon and
// max_bisections for the variables that occur more than once.
using BC4Params = BC3Params;

class BC4Contractor : public PropagationContractor {
 public:
  BC4Contractor(std::shared_ptr<const CompiledSystem> system, const BC4Params& params);
  std::string_view Name() const override { return "bc4"; }

 protected:
  bool Revise(int c, Box& box, WorkCounters& work, bool* idempotent) override;

 private:
  BoxNarrower narrower_;
  std::vector<Interval> slots_;
  std::vector<std::vector<int>> multiple_;  // per constraint: variables occurring twice or more
};

std::unique_ptr<Contractor> MakeBC4(const ParamMap& params, const ConstraintSystem& csp);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_BC4_BC4_H_
