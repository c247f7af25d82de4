// Where and how results are produced: git revision, machine, compiler and
// flags, date. Recorded with every run (DESIGN.md: a self-describing log).
#ifndef ICPBENCH_HARNESS_PROVENANCE_H_
#define ICPBENCH_HARNESS_PROVENANCE_H_

#include <string>

#include "harness/run_record.h"

namespace icp {

// The provenance of this binary on this machine, date = now.
Provenance CurrentProvenance();
// Now in ISO 8601, UTC ("2026-11-29T10:25:00Z").
std::string UtcNow();

}  // namespace icp

#endif  // ICPBENCH_HARNESS_PROVENANCE_H_
