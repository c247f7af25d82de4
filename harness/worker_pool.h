// Runs in forked worker processes, at most `jobs` at a time: one process a
// run, so that a run that crashes, hangs past its timeout (killed
// kill_grace_s after it) or returns garbage comes back as a failed or
// timed-out record with its reason. A worker dies with the process that
// started it, whatever kills that, and keeps the terminal's Ctrl-C for it.
// The local sweep (harness/runner.h) and the MPI worker ranks
// (harness/mpi_sweep.h) both run their runs here.
#ifndef ICPBENCH_HARNESS_WORKER_POOL_H_
#define ICPBENCH_HARNESS_WORKER_POOL_H_

#include <sys/types.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include "harness/run_record.h"
#include "harness/spec.h"

namespace icp {

// A run whose worker is done.
struct FinishedRun {
  PlannedRun run;
  RunRecord record;       // its summary, without steps
  std::string step_file;  // where its steps are; empty: none (record: runs, or the worker failed)
};

// The CPUs this process may run on (its affinity mask, which mpirun and
// taskset narrow; workers inherit it): the default number of jobs.
int UsableCpus();

class WorkerPool {
 public:
  // Workers write their step files in step_dir and close close_in_workers
  // (descriptors that must not outlive the starting process, e.g. a lock).
  WorkerPool(std::string step_dir, int jobs, double kill_grace_s, std::vector<int> close_in_workers = {});
  ~WorkerPool();  // Stop()
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int Running() const { return static_cast<int>(workers_.size()); }
  bool HasRoom() const { return Running() < jobs_; }

  // Forks a worker for the run. When pipe() or fork() fails returns false,
  // with the errno and what failed in start_errno()/start_error().
  bool Start(const PlannedRun& run);
  int start_errno() const { return start_errno_; }
  const std::string& start_error() const { return start_error_; }

  // Waits up to timeout_ms for the workers, kills those past their time,
  // and hands each run that finished to on_finished (its step file is
  // removed after the call). Returns at once when no worker runs.
  void Poll(int timeout_ms, const std::function<void(FinishedRun&)>& on_finished);

  // Hands each worker that has already exited to on_finished, with what its
  // pipe still holds, without waiting for the others: before a Stop, so that
  // a run that finished while the parent was busy (storing another, or
  // stopped by Ctrl-Z) is kept, not killed as if it were in flight.
  void CollectExited(const std::function<void(FinishedRun&)>& on_finished);

  // Kills and reaps every worker: their runs are lost.
  void Stop();

 private:
  struct Worker {
    pid_t pid = -1;
    int fd = -1;
    std::string output;
    std::chrono::steady_clock::time_point started;
    double kill_after_s = 0;  // 0: never
    double hard_limit_s = 0;  // the worker's own wall-clock limit (alarm); 0: none
    double cpu_limit_s = 0;   // its CPU-time limit, all threads (RLIMIT_CPU); 0: none
    bool killed = false;
    PlannedRun run;
    std::string step_file;
  };
  FinishedRun Finish(Worker& w, int wait_status);
  // One read of w's pipe into its output; true at its end (or an error).
  static bool ReadSome(Worker& w);
  // Finishes workers_[i], reaped with wait_status and its pipe read to the
  // end: removes it, calls on_finished, then removes its step file.
  void Hand(std::size_t i, int wait_status, const std::function<void(FinishedRun&)>& on_finished);

  std::string step_dir_;
  int jobs_;
  double kill_grace_s_;
  std::vector<int> close_in_workers_;
  std::vector<Worker> workers_;
  int started_ = 0;
  int start_errno_ = 0;
  std::string start_error_;
};

}  // namespace icp

#endif  // ICPBENCH_HARNESS_WORKER_POOL_H_
