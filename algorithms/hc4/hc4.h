// HC4 (Benhamou et al. 1999; paper 000 §3.2): HC4Revise on each constraint's
// tape (a forward interval evaluation and a backward projection, no
// decomposition into primitive constraints), propagated with an AC3-like
// queue over the constraints that share a variable whose domain shrank, until
// no domain shrinks by more than `ratio` of its width.
//
// Sound: every step is a projection that keeps all solutions. With multiple
// occurrences of a variable in a constraint (x*x + y^2 = 2) HC4Revise suffers
// from the dependency problem; BC3/BC4 do not.
#ifndef ICPBENCH_ALGORITHMS_HC4_HC4_H_
#define ICPBENCH_ALGORITHMS_HC4_HC4_H_

#include <memory>
#include <vector>

#include "core/constraint_system.h"
#include "core/params.h"
#include "core/propagation.h"

namespace icp {

struct HC4Params {
  // A variable whose width shrinks by more than this fraction wakes up the
  // constraints it occurs in. Smaller is tighter and slower; 1e-3 to 0.1 are
  // the usual choices.
  double ratio = 1e-3;
  // Upper bound on HC4Revise calls per contraction, a guard against slow
  // convergence (a box shrinking geometrically forever).
  int max_revise_calls = 1000000;
};
void Describe(HC4Params& p, ParamSet& set);

class HC4Contractor : public PropagationContractor {
 public:
  HC4Contractor(std::shared_ptr<const CompiledSystem> system, const HC4Params& params);
  std::string_view Name() const override { return "hc4"; }

 protected:
  bool Revise(int c, Box& box, WorkCounters& work, bool* idempotent) override;

 private:
  std::vector<Interval> slots_;
};

std::unique_ptr<Contractor> MakeHC4(const ParamMap& params, const ConstraintSystem& csp);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_HC4_HC4_H_
