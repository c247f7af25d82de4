// The sweep runner: executes the run matrix of a spec in parallel worker
// processes (one forked process per run, at most `jobs` at a time), so that a
// run that crashes, hangs past its timeout or returns garbage is recorded as
// failed with its reason while the sweep goes on. Each finished run is
// written to the results store at once; runs already stored are skipped,
// except failed and timed-out ones, which are retried (unless no_retry).
// A worker writes each step to a file of its own in the output directory as
// the run goes (.steps-*.ndjson) and its run's summary to a pipe at the end;
// the parent streams that file into the store, so neither process holds a
// run's steps and the parent's memory does not grow with a run's length.
// A run whose spec says record: runs writes no step file: the store gets its
// run row (metrics accumulated in the worker, properties) and no step rows.
#ifndef ICPBENCH_HARNESS_RUNNER_H_
#define ICPBENCH_HARNESS_RUNNER_H_

#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>

#include "harness/directory_lock.h"

#include "algorithms/estimator.h"
#include "harness/run_record.h"
#include "harness/shard.h"
#include "harness/spec.h"
#include "problems/problem.h"

namespace icp {

struct RunnerOptions {
  std::string out_dir;
  int jobs = 1;
  int shard_index = 0;  // this machine's share (ShardRuns, harness/shard.h)
  int shard_count = 1;
  bool force = false;   // rerun runs that are already stored
  bool no_retry = false;  // keep stored failed/timeout runs instead of retrying them
  // Extra seconds after a run's timeout before its process is killed (the
  // run first gets the chance to stop by itself).
  double kill_grace_s = 2;
};

struct SweepSummary {
  int planned = 0;      // runs in this shard
  int already_stored = 0;
  int ok = 0;
  int failed = 0;
  int timed_out = 0;
  int skipped = 0;      // incompatible algorithm/problem pairs
  // Set when SIGINT or SIGTERM stopped the sweep: the signal, and the runs
  // then in flight (killed, not recorded). Finished runs stay stored.
  int interrupted_by = 0;
  int stopped = 0;
  int Finished() const { return ok + failed + timed_out + skipped; }
};

// Runs the sweep; progress goes to `progress` (a bar on a terminal, plain
// lines otherwise). Holds an exclusive lock on OUT_DIR/.lock meanwhile
// (throws DirectoryLockedError if another process holds it). Workers die
// with the calling process, whatever kills it. SIGINT/SIGTERM stop the
// workers and return with interrupted_by set. Throws StoreError if the store
// cannot be opened, EnvironmentError when the environment fails (no pipe or
// fork: the runs in flight are finished and stored first).
SweepSummary RunSweep(const Spec& spec, const RunnerOptions& options, std::ostream& progress,
                      bool progress_is_terminal);

// One step as a run takes it: the view the algorithm needs checked
// (std::invalid_argument), the estimator stepped, its estimate checked
// (InvalidResult) and measured (MeasureStep) with the estimator's status and
// solve time (its own, else the wall time of its Step). The runner, the
// Python module's stepping by hand and the results browser's re-run share it.
struct TakenStep {
  StepResult result;
  StepRecord record;
};
TakenStep TakeStep(Estimator& estimator, View needs, const Step& step, const StopCondition& stop);

// One run in the calling process: the problem's steps fed to the algorithm,
// each contracted box checked and recorded. Never throws: an exception or an
// invalid box becomes a failed record with its reason.
RunRecord ExecuteRun(const RunSpec& spec);

// Receives each step's record as a run makes it.
using StepSink = std::function<void(const StepRecord&)>;
// The same, each step handed to sink instead of kept (record.steps stays
// empty; the metrics are accumulated as the steps go), so memory does not
// grow with the run. A sink that throws fails the run at that step.
RunRecord ExecuteRun(const RunSpec& spec, const StepSink& sink);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_RUNNER_H_
