// `icpbench solve FILE --algorithm NAME [--param k=v ...] [--format text|json]
// [--repeat N] [--timeout S]`: contracts the initial box of a Minibex file with a CSP
// contractor, or solves it as a relaxed CSP (q-relaxed, polynomial,
// accumulator: each constraint is one measurement, the file's domains the
// prior; see problems/minibex_file).
#ifndef ICPBENCH_HARNESS_SOLVE_COMMAND_H_
#define ICPBENCH_HARNESS_SOLVE_COMMAND_H_

#include <atomic>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/box.h"
#include "core/constraint_system.h"
#include "core/contractor.h"
#include "core/estimate.h"

namespace icp {

struct SolveOptions {
  std::string file;
  std::string algorithm = "hc4";
  std::vector<std::string> params;  // "key=value"
  std::string format = "text";      // text | json
  int repeat = 1;
  // Seconds each contraction or solve may take (> 0; inf: no limit). Past
  // it the algorithm stops with a sound box, status stopped.
  double timeout_s = kInf;
  // When set, the system already parsed from `file` (the Python module keeps
  // the systems it solves, so a notebook's loop does not parse each time);
  // CSP contractors then do not read the file.
  std::shared_ptr<const ConstraintSystem> parsed;
  // When set (with `parsed`), the CSP contractor an earlier Solve of the
  // same system, algorithm and parameters built (SolveResult::contractor),
  // contracted again as `--repeat` does instead of being built anew.
  std::shared_ptr<Contractor> contractor;
  // When set and raised, the solve stops as at its time limit and the
  // repeats end (the Python module's Ctrl-C).
  const std::atomic<bool>* cancel = nullptr;
  // When >= 0 (the command line) and the limit is finite: a contraction or
  // solve still running this many seconds past its limit ends the process
  // (exit 1, the message names the algorithm), as `run` kills such a run's
  // worker; one that never checks its stop condition would hang otherwise.
  double kill_grace_s = -1;
};

// An algorithm that failed inside Solve: it threw (anything but a usage,
// memory or environment error), returned no estimate or an invalid box, or
// ran past its limit. A bug of that algorithm (exit 1); the message names it.
class AlgorithmFault : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SolveResult {
  std::string algorithm;
  ConstraintSystem csp;
  Box box;
  ContractSummary summary;
  double time_s = 0;  // median over the repeats
  // Relaxed solvers only (`relaxed` set): the q used or found, the
  // estimate's kind and what it reports (Estimate::Extras), and for the
  // polynomial the hull for every q = 0..m.
  bool relaxed = false;
  int q = 0;
  std::string estimate_kind;
  Properties estimate_extras;
  std::vector<Box> hulls_by_q;
  // The CSP contractor used (null for the relaxed solvers), for reuse.
  std::shared_ptr<Contractor> contractor;
};

// Runs the contraction. Throws std::invalid_argument (bad algorithm,
// parameter or option), ParamError or MinibexError: all are usage errors;
// AlgorithmFault: the algorithm's own failure.
SolveResult Solve(const SolveOptions& options);

// The JSON contract: {"algorithm", "status": "empty"|"nonempty", "box":
// {name: [lo, hi]}, "time_s"}; infinite bounds are null, an empty box is {}.
// A contraction that stopped short (a time limit, max_revise_calls) adds
// "stopped": its message.
// Relaxed solvers add "q", "estimate": {"kind": "box"|"paving"|
// "accumulator", ...the estimate's extras ("boxes" for a paving, "max_count"
// for an accumulator)}, and, when computed, "by_q": [{"q", "status", "box"}]
// for q = 0..m. "box" is then the hull of the solution set.
std::string SolveResultToJson(const SolveResult& result);
std::string SolveResultToText(const SolveResult& result);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_SOLVE_COMMAND_H_
