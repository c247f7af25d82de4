// What a run of (algorithm, problem, parameters, seed) produces: one record
// per step and the run's metrics and provenance. The runner fills these, the
// results store keeps them, the reports and plots read them back.
#ifndef ICPBENCH_HARNESS_RUN_RECORD_H_
#define ICPBENCH_HARNESS_RUN_RECORD_H_

#include <cstdint>
#include <string>
#include <vector>

#include "core/estimate.h"
#include "core/params.h"

namespace icp {

// One reported variable of one step. truth is NaN when unknown; lo/hi are
// +inf/-inf when the box is empty.
struct VariableRecord {
  std::string name;
  double lo = 0;
  double hi = 0;
  double truth = 0;
};

struct StepRecord {
  int step = 0;
  std::string status;          // the estimator's: contracted|fixpoint|empty|stopped
  std::string estimate;        // its kind: box|paving|accumulator|particles
  std::vector<VariableRecord> vars;
  int contained = -1;          // truth inside the box: 1 yes, 0 no, -1 unknown
  double area = 0;             // x-y area, m^2; NaN without a planar position
  double centre_error = 0;     // distance box centre - truth, m; NaN if unknown
  double solve_time_s = 0;     // wall time of the estimator's step alone
  // What the estimator and its estimate report beyond these (work counters,
  // message, box count, effective sample size...).
  Properties properties;
};

// The interval error corridor of one variable over a run (paper 000 §5:
// [lo - truth, hi - truth] per step), summarised.
struct Corridor {
  std::string var;
  double mean_lower = 0;   // mean of lo - truth
  double mean_upper = 0;   // mean of hi - truth
  double min_lower = 0;    // most negative lo - truth
  double max_upper = 0;    // largest hi - truth
};

struct RunMetrics {
  int steps = 0;
  double mean_area = 0;           // over steps with a non-empty box, m^2
  double consistency_rate = 0;    // share of steps whose box holds the truth (paper 004 eq. 31)
  double centre_rmse = 0;         // root mean square of centre_error, m
  double time_mean_s = 0;
  double time_median_s = 0;
  double time_p90_s = 0;
  double time_mean_ci_lo_s = 0;   // bootstrap 95% interval of the mean time
  double time_mean_ci_hi_s = 0;
  std::vector<Corridor> corridors;
};

// The identity of a run: rerunning a spec skips runs whose key is stored.
struct RunSpec {
  std::string algorithm;
  ParamMap algorithm_params;
  std::string problem;
  ParamMap problem_params;
  std::uint64_t seed = 0;
  double timeout_s = 0;  // 0: none. Not part of the key.
  // Memory limit of the run's worker process (RLIMIT_DATA), MiB; 0: none. Not part
  // of the key. A run that exceeds it fails with "out of memory".
  double memory_limit_mb = 0;
  // Whether the run's steps are stored (spec key record: steps) or only the
  // run row with its metrics and properties (record: runs), for sweeps too
  // big to keep every step. Not part of the key.
  bool record_steps = true;
  // A canonical text of everything but the limits, e.g.
  // "hc4{carry=first,max_revise_calls=1000000,ratio=0.001}|car-track{...}|seed=3".
  // The harness keys runs on effective parameters (every declared one,
  // defaults resolved, canonical spelling: ResolveParams), so equal
  // computations share a key and a changed default is a new run. Params are in key order; a
  // backslash precedes any of \ { } = , | inside a name, key or value, so
  // two different specs never share a key.
  std::string Key() const;
};

enum class RunStatus { kOk, kFailed, kTimeout, kSkipped };
std::string_view ToString(RunStatus status);
RunStatus ParseRunStatus(std::string_view text);  // throws std::invalid_argument

// Where and how a run was made.
struct Provenance {
  std::string git_revision;
  std::string machine;     // host name and CPU model
  std::string compiler;    // e.g. "GNU 12.2.0"
  std::string flags;       // build type and flags
  std::string date;        // ISO 8601, UTC, when the run finished
};

struct RunRecord {
  RunSpec spec;
  std::string spec_file;   // the experiment spec it came from
  RunStatus status = RunStatus::kOk;
  std::string reason;      // why it failed, timed out or was skipped
  double wall_time_s = 0;
  std::vector<StepRecord> steps;
  RunMetrics metrics;
  Properties properties;   // the estimator's totals over the run
  Provenance provenance;
};

// The experiment of the spec that planned a run: what follows the last '#'
// of its spec_file ("specs/default.yaml#table1" -> "table1"; a spec's path
// may hold '#', an experiment's name may not); "" when none. A run that two
// experiments of one spec plan is stored once, under the first.
std::string ExperimentOf(const std::string& spec_file);
inline std::string ExperimentOf(const RunRecord& run) { return ExperimentOf(run.spec_file); }

}  // namespace icp

#endif  // ICPBENCH_HARNESS_RUN_RECORD_H_
