// Experiment specs (YAML): which algorithms, with which parameter grids, run
// on which problems, with which seeds. specs/default.yaml is the default
// suite; docs/specs.md shows the format. A list value is a grid axis:
//
//   timeout_s: 300            # per run (default 600)
//   memory_limit_mb: 4096     # per worker process (default 4096; 0: none)
//   record: steps             # steps (default): every step row; runs: the run rows only
//   seeds: [1, 2]             # or repetitions: 3 (seeds 1..3); default [1]
//   experiments:
//     - name: table1
//       algorithms:
//         - hc4                                   # defaults
//         - {name: bc4, params: {ratio: [0.001, 0.01]}}
//       problems:
//         - {name: car-track, params: {w: 20}}
//       seeds: [1]            # optional, overrides the top level
//
// A spec with no `experiments` is one experiment with top-level
// `algorithms` and `problems`. Every name, key and value is checked against
// the registries before anything runs; errors name the file, line and key.
//
// The matrix order (Spec::runs), which shards are cut from (harness/shard.h),
// depends only on the spec's text: experiments in order; within one, for
// each problem entry in order, each algorithm entry in order, then the
// problem's grid points, the algorithm's grid points and the seeds. A grid
// varies its last-given key fastest, each key's values in the order given.
// A run that an earlier entry or experiment already planned (the same key)
// is dropped. Nothing is hashed or read from the machine, so every machine
// expands a spec to the same list.
#ifndef ICPBENCH_HARNESS_SPEC_H_
#define ICPBENCH_HARNESS_SPEC_H_

#include <stdexcept>
#include <string>
#include <vector>

#include "harness/run_record.h"

namespace icp {

class SpecError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The most runs a spec may expand to (its whole matrix, every experiment
// together); a larger one is a SpecError before it is expanded.
inline constexpr std::size_t kMaxRuns = 1'000'000;

// The memory limit (RLIMIT_DATA) of each worker unless a spec says otherwise
// (memory_limit_mb), so a run that runs away fails alone instead of making
// the kernel pick a process to kill; and the least a spec may set (the
// worker's libraries and thread stacks).
inline constexpr double kDefaultMemoryLimitMb = 4096;
inline constexpr double kMinMemoryLimitMb = 64;

struct PlannedRun {
  RunSpec spec;
  std::string experiment;
  // Non-empty when the algorithm cannot run on the problem (views differ):
  // the run is recorded as skipped with this reason.
  std::string skip_reason;
};

struct Spec {
  std::string file;
  std::vector<PlannedRun> runs;  // the whole matrix, duplicates removed, in spec order
  // The problems' notes on their parameters (ProblemInfo::note), once each;
  // run prints them before the runs.
  std::vector<std::string> notes;
};

// Reads and validates a spec file. Throws SpecError("FILE:LINE:COL: key
// 'algorithms[1].params.ratio': ...") on any problem.
Spec LoadSpec(const std::string& path);
// The text of a spec file (SpecError if it cannot be read).
std::string ReadSpecText(const std::string& path);
// The same from text (source names it in errors).
Spec ParseSpec(const std::string& text, const std::string& source);

// The entries of params whose value differs from defaults (or that defaults
// lacks).
ParamMap NonDefaultParams(const ParamMap& defaults, const ParamMap& params);
// The current defaults of a registered plugin's parameters; {} for a name no
// longer registered.
ParamMap AlgorithmDefaults(const std::string& name);
ParamMap ProblemDefaults(const std::string& name);
// The run with only the parameters that differ from the current defaults of
// its registered plugins: what people read (tables, progress lines), while
// keys and the store keep the effective parameters.
RunSpec WithoutDefaults(RunSpec spec);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_SPEC_H_
