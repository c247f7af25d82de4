// A fault-injection plugin for testing the harness, not an algorithm: after
// `after_calls` good steps (HC4 over the window, carry=first) it crashes,
// hangs, throws, allocates without bound (64 MiB blocks, each touched once, until std::bad_alloc or
// 64 GiB) or returns a box that is not inside the step's domains, as `mode` says; `spin` hangs busy
// on twice as many threads as the machine has cores, ignoring the stop condition (a hung parallel
// run: its CPU time grows faster than the clock); `slow` is no fault but HC4 with every step
// slow_ms longer (a long run, to kill mid-sweep). The harness must record such runs as failed (or
// timed out) with their reason and carry on.
#ifndef ICPBENCH_ALGORITHMS_FAULT_FAULT_H_
#define ICPBENCH_ALGORITHMS_FAULT_FAULT_H_

#include <cstdint>
#include <memory>
#include <string>

#include "algorithms/estimator.h"
#include "core/params.h"

namespace icp {

struct FaultParams {
  // none | segfault | abort | hang | spin | throw | allocate | garbage | slow
  std::string mode = "segfault";
  // Steps that behave (as HC4) before the fault.
  int after_calls = 0;
  // mode slow: the sleep added to every step, ms.
  double slow_ms = 100;
};
void Describe(FaultParams& p, ParamSet& set);

std::unique_ptr<Estimator> MakeFault(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_FAULT_FAULT_H_
