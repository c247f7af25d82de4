// The recording side of a sweep, in the one process that writes the output
// directory (the local runner, or rank 0 of an MPI sweep): it holds the
// directory's lock, plans which runs of the spec are left to do, and stores
// each finished run at once, counting it and reporting progress.
#ifndef ICPBENCH_HARNESS_SWEEP_RECORDER_H_
#define ICPBENCH_HARNESS_SWEEP_RECORDER_H_

#include <atomic>
#include <csignal>
#include <deque>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

#include "harness/directory_lock.h"
#include "harness/progress.h"
#include "harness/results_store.h"
#include "harness/runner.h"
#include "harness/spec.h"

namespace icp {

// SIGINT/SIGTERM/SIGHUP are caught while one lives (Caught() says which
// came, 0 while none), and SIGPIPE ignored; the previous handlers come back
// after the last one (sweeps overlapping in threads of one process, as
// icpbench.run can, share the handlers: a signal stops them all).
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  static int Caught();
  // Stops the sweeps in progress as if signal had come (the Python module's
  // exit stops those of its daemon threads); a sweep that starts later
  // begins with none caught.
  static void Request(int signal);
  // Raised with Caught(): a cancel flag for StopCondition::WithCancelFlag.
  static const std::atomic<bool>& Flag();
};

class SweepRecorder {
 public:
  // Creates the output directory, takes its lock, removes stale step files,
  // opens the store, and plans this shard's runs: those stored are skipped
  // (failed and timed-out ones are retried unless no_retry; all rerun with
  // force). Throws DirectoryLockedError, StoreError, EnvironmentError.
  SweepRecorder(const Spec& spec, const RunnerOptions& options, std::ostream& progress, bool terminal);

  // The runs left to do, in matrix order; the sweep takes them from the front.
  std::deque<PlannedRun>& queue() { return queue_; }
  SweepSummary& summary() { return summary_; }
  Progress& progress() { return *progress_; }
  int lock_fd() const { return lock_.fd(); }
  const std::string& out_dir() const { return out_dir_; }

  // Stores a finished run, its steps read from step_file when one is given
  // (a step file that cannot be read stores the run as failed); `where` and
  // `in_flight` go to the progress (Progress::Done). while_storing is called
  // every few thousand steps of a long run.
  void Record(RunRecord r, const std::string& experiment, const std::string& step_file = "",
              const std::string& where = "", const std::string& in_flight = "",
              const std::function<void()>& while_storing = {});
  // Records a run the spec marks as skipped (incompatible views).
  void RecordSkipped(const PlannedRun& run);
  // The record of such a run.
  static RunRecord Skipped(const PlannedRun& run);

 private:
  std::string out_dir_;
  std::string spec_file_;
  DirectoryLock lock_;
  ResultsStore store_;
  std::deque<PlannedRun> queue_;
  SweepSummary summary_;
  std::optional<Progress> progress_;
};

}  // namespace icp

#endif  // ICPBENCH_HARNESS_SWEEP_RECORDER_H_
