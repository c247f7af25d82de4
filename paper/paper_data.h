// Numbers the paper's comparisons read off stored runs, beyond the groups'
// metrics (report/report.h).
#ifndef ICPBENCH_PAPER_PAPER_DATA_H_
#define ICPBENCH_PAPER_PAPER_DATA_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "report/report.h"

namespace icp {

// The machine of a group's first ok run (provenance); "an unknown machine".
std::string MachineOf(const GroupSummary& group);

// Mean width hi - lo of variable var over a run's steps whose box is not
// empty; NaN when none.
double MeanWidth(const RunRecord& run, const std::string& var);

// Mean width of the GPS box of var ("x", "y") over a run's steps that record
// one (car-track's step annotations gps_<var>_lo/hi); NaN when none.
double MeanGpsWidth(const RunRecord& run, const std::string& var);

// Over the steps of a group's ok runs.
struct StepStats {
  int steps = 0;
  int known = 0;                   // steps whose containment is known
  int contained = 0;               // of those, holding the truth
  double median_centre_error = 0;  // NaN when none is known
  double mean_run_time_s = 0;      // solve time summed over a run's steps, mean over runs
  double consistency() const;      // contained / known; NaN when none known
};
StepStats StatsOf(const GroupSummary& group);

}  // namespace icp

#endif  // ICPBENCH_PAPER_PAPER_DATA_H_
