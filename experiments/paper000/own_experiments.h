// Paper 000's setting pushed past the paper, from specs/default.yaml's
// experiments of our own: `start` (the heading unknown in [-pi, pi] when the
// drive begins) and `outage` (GPS lost for outage_length steps from
// outage_start). Measured here so that the paper discusses every experiment
// the suite runs.
#ifndef ICPBENCH_EXPERIMENTS_PAPER000_OWN_EXPERIMENTS_H_
#define ICPBENCH_EXPERIMENTS_PAPER000_OWN_EXPERIMENTS_H_

#include <vector>

#include "harness/run_record.h"
#include "report/report.h"

namespace icp {

// start: per configuration, the heading width of the newest state at the
// first step, the 20th and the last, and the share of steps holding the
// truth. outage: per configuration, the mean x-y area over the outage_length
// steps before the outage, during it and after it, and the share of the
// outage's steps holding the truth. Medians over the runs (seeds) with their
// 95 % intervals; a table with no runs is omitted and says which spec makes
// them.
std::vector<TextTable> Paper000OwnExperimentTables(const std::vector<RunRecord>& runs);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_PAPER000_OWN_EXPERIMENTS_H_
