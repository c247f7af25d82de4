// One constraint of a system as a contractor: HC4Revise of its tape repeated
// until no variable shrinks by more than 1e-3 of its width (or it reports
// that one more could change nothing). This is how a measurement becomes the
// contractor of a measurement-set view (core/view.h): a problem writes each
// measurement as a constraint over the state, and the relaxed solvers
// combine the contractors. Sound: HC4Revise never removes a solution.
// Not thread-safe (scratch buffers): one contractor per thread.
#ifndef ICPBENCH_CORE_CONSTRAINT_CONTRACTOR_H_
#define ICPBENCH_CORE_CONSTRAINT_CONTRACTOR_H_

#include <memory>
#include <vector>

#include "core/constraint_system.h"
#include "core/contractor.h"
#include "core/tape.h"

namespace icp {

class ConstraintContractor : public Contractor {
 public:
  ConstraintContractor(std::shared_ptr<const CompiledSystem> system, int constraint);
  std::string_view Name() const override { return "constraint"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

 private:
  std::shared_ptr<const CompiledSystem> system_;
  int constraint_;
  std::vector<Interval> slots_;
  std::vector<Interval> start_;  // the tape's variables before a pass
};

// One contractor per constraint of csp, in order, over csp's variables.
std::vector<std::shared_ptr<Contractor>> ConstraintContractors(const ConstraintSystem& csp);

}  // namespace icp

#endif  // ICPBENCH_CORE_CONSTRAINT_CONTRACTOR_H_
