#include "paper/paper_data.h"

#include <cmath>
#include <limits>

#include "harness/metrics.h"
#include "plots/figures.h"

namespace icp {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

std::string MachineOf(const GroupSummary& group) {
  for (const RunRecord* r : group.ok_runs)
    if (!r->provenance.machine.empty()) return r->provenance.machine;
  return "an unknown machine";
}

double MeanWidth(const RunRecord& run, const std::string& var) {
  std::vector<double> widths;
  for (const StepRecord& s : run.steps) {
    for (const VariableRecord& v : s.vars) {
      if (v.name == var && v.lo <= v.hi && std::isfinite(v.hi - v.lo))
        widths.push_back(v.hi - v.lo);
    }
  }
  return widths.empty() ? kNaN : Mean(widths);
}

double MeanGpsWidth(const RunRecord& run, const std::string& var) {
  std::vector<double> widths;
  // Rows {step, lo - truth, hi - truth}: the truth cancels in the width.
  for (const std::vector<double>& row : GpsCorridorRows(run, var)) {
    if (row.size() >= 3 && std::isfinite(row[2] - row[1])) widths.push_back(row[2] - row[1]);
  }
  return widths.empty() ? kNaN : Mean(widths);
}

double StepStats::consistency() const {
  return known > 0 ? static_cast<double>(contained) / known : kNaN;
}

StepStats StatsOf(const GroupSummary& group) {
  StepStats stats;
  std::vector<double> errors, run_times;
  for (const RunRecord* r : group.ok_runs) {
    double run_time = 0;
    for (const StepRecord& s : r->steps) {
      ++stats.steps;
      if (s.contained >= 0) ++stats.known, stats.contained += s.contained;
      if (std::isfinite(s.centre_error)) errors.push_back(s.centre_error);
      run_time += s.solve_time_s;
    }
    run_times.push_back(run_time);
  }
  stats.median_centre_error = errors.empty() ? kNaN : Quantile(errors, 0.5);
  stats.mean_run_time_s = run_times.empty() ? kNaN : Mean(run_times);
  return stats;
}

}  // namespace icp
