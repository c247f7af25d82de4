// A fault-injection plugin for testing the harness, not an algorithm: after
// `after_calls` good contractions (HC4) it crashes, hangs, throws or returns
// a box that is not a contraction, as `mode` says. The harness must record
// such runs as failed (or timed out) with their reason and carry on.
#ifndef ICPBENCH_ALGORITHMS_FAULT_FAULT_H_
#define ICPBENCH_ALGORITHMS_FAULT_FAULT_H_

#include <memory>
#include <string>

#include "core/constraint_system.h"
#include "core/contractor.h"
#include "core/params.h"

namespace icp {

struct FaultParams {
  // none | segfault | abort | hang | throw | garbage
  std::string mode = "segfault";
  // Contractions that behave (as HC4) before the fault.
  int after_calls = 0;
};
void Describe(FaultParams& p, ParamSet& set);

std::unique_ptr<Contractor> MakeFault(const ParamMap& params, const ConstraintSystem& csp);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_FAULT_FAULT_H_
