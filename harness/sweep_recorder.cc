#include "harness/sweep_recorder.h"

#include <filesystem>
#include <atomic>
#include <map>
#include <mutex>
#include <ostream>
#include <set>

#include "harness/environment_error.h"
#include "harness/output_directory.h"
#include "harness/provenance.h"
#include "harness/shard.h"
#include "harness/worker_output.h"

namespace icp {

namespace {

volatile std::sig_atomic_t g_stop_signal = 0;
std::atomic<bool> g_stop_flag{false};  // lock-free: safe to set in a handler
extern "C" void OnStopSignal(int sig) {
  g_stop_signal = sig;
  g_stop_flag.store(true, std::memory_order_relaxed);
}

std::string CreatedDirectory(const std::string& dir) {
  CreateOutputDirectory(dir, kChooseAnotherOut);
  return dir;
}

}  // namespace

namespace {
// The handlers before the first of the living StopSignals, and how many live.
std::mutex g_signals_mutex;
int g_signals_users = 0;
struct sigaction g_old_int {}, g_old_term {}, g_old_hup {}, g_old_pipe {};
}  // namespace

StopSignals::StopSignals() {
  std::lock_guard<std::mutex> lock(g_signals_mutex);
  if (g_signals_users++ > 0) return;
  g_stop_signal = 0;
  g_stop_flag = false;
  struct sigaction sa {};
  sa.sa_handler = OnStopSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
  sigaction(SIGHUP, &sa, &g_old_hup);  // the terminal closed: stop as for Ctrl-C
  // A closed stderr (a pipe to `head`, a dropped ssh) must not kill the
  // sweep mid-store: writes to it fail instead, and the runs go on.
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, &g_old_pipe);
}

StopSignals::~StopSignals() {
  std::lock_guard<std::mutex> lock(g_signals_mutex);
  if (--g_signals_users > 0) return;
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
  sigaction(SIGHUP, &g_old_hup, nullptr);
  sigaction(SIGPIPE, &g_old_pipe, nullptr);
}

int StopSignals::Caught() { return g_stop_signal; }

void StopSignals::Request(int signal) {
  g_stop_signal = signal;
  g_stop_flag = true;
}

const std::atomic<bool>& StopSignals::Flag() { return g_stop_flag; }

SweepRecorder::SweepRecorder(const Spec& spec, const RunnerOptions& options, std::ostream& progress,
                             bool terminal)
    : out_dir_(CreatedDirectory(options.out_dir)),
      spec_file_(spec.file),
      lock_(out_dir_, progress),
      // Step files of a killed sweep go once the lock says none is running.
      store_((RemoveStaleStepFiles(out_dir_), StorePath(out_dir_))) {
  // Kept: ok and skipped runs; failed and timed-out ones are retried (a
  // transient kill must not be permanent) unless no_retry.
  std::map<std::string, std::string> stored;  // key -> the experiment it is filed under
  for (const StoredRun& r : store_.StoredRuns()) {
    const bool finished = r.status == RunStatus::kOk || r.status == RunStatus::kSkipped;
    if (finished || options.no_retry) stored[r.key] = ExperimentOf(r.spec_file);
  }
  // Tables and figures pick runs by experiment: a stored run filed under
  // another one (a renamed experiment, an earlier spec) is kept but missed.
  int filed_elsewhere = 0;
  std::string example;
  for (std::size_t i : ShardRuns(spec, options.shard_index, options.shard_count)) {
    ++summary_.planned;
    const auto it = stored.find(spec.runs[i].spec.Key());
    if (!options.force && it != stored.end()) {
      ++summary_.already_stored;
      if (it->second != spec.runs[i].experiment && filed_elsewhere++ == 0)
        example = "'" + it->second + "', planned here in '" + spec.runs[i].experiment + "'";
      continue;
    }
    queue_.push_back(spec.runs[i]);
  }
  for (const std::string& note : spec.notes) progress << "icpbench: note: " << note << "\n";
  if (filed_elsewhere > 0)
    progress << "icpbench: " << filed_elsewhere << " of the runs already stored "
             << (filed_elsewhere == 1 ? "is" : "are") << " filed under another experiment (e.g. "
             << example << "): tables and figures that pick this spec's experiments leave "
             << (filed_elsewhere == 1 ? "it" : "them") << " out; --force reruns "
             << (filed_elsewhere == 1 ? "it" : "them") << " under this spec\n";
  progress_.emplace(progress, terminal, static_cast<int>(queue_.size()));
  // Computed once (it runs git) while descriptors are still free: a sweep
  // that exhausts them must not store an empty provenance.
  CurrentProvenance();
}

void SweepRecorder::Record(RunRecord r, const std::string& experiment, const std::string& step_file,
                           const std::string& where, const std::string& in_flight,
                           const std::function<void()>& while_storing) {
  r.spec_file = spec_file_ + (experiment.empty() ? "" : "#" + experiment);
  const std::string machine = r.provenance.machine;  // where it ran, when not here
  r.provenance = CurrentProvenance();
  if (!machine.empty()) r.provenance.machine = machine;
  if (step_file.empty()) {
    store_.Insert(r);
  } else {
    try {
      StepSource steps = ReadStepFile(step_file, r.metrics.steps);
      if (while_storing) {
        steps = [steps, &while_storing, read = 0](StepRecord* step) mutable {
          if (++read % 4096 == 0) while_storing();
          return steps(step);
        };
      }
      store_.Insert(r, steps);
    } catch (const WorkerOutputError& e) {  // rolled back: stored as failed, without steps
      r.status = RunStatus::kFailed;
      r.reason = UnreadableWorkerOutput(e.what());
      r.metrics = RunMetrics{};
      store_.Insert(r);
    }
  }
  switch (r.status) {
    case RunStatus::kOk: ++summary_.ok; break;
    case RunStatus::kFailed: ++summary_.failed; break;
    case RunStatus::kTimeout: ++summary_.timed_out; break;
    case RunStatus::kSkipped: ++summary_.skipped; break;
  }
  progress_->Done(r, summary_, where, in_flight);
}

void SweepRecorder::RecordSkipped(const PlannedRun& run) { Record(Skipped(run), run.experiment); }

RunRecord SweepRecorder::Skipped(const PlannedRun& run) {
  RunRecord r;
  r.spec = run.spec;
  r.status = RunStatus::kSkipped;
  r.reason = run.skip_reason;
  return r;
}

}  // namespace icp
