// A worker rank of the MPI sweep: tells rank 0 how many runs it takes, runs
// what it is sent in forked workers and sends each result back.
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "harness/mpi_sweep_internal.h"
#include "harness/provenance.h"
#include "harness/worker_output.h"

namespace icp::detail {

namespace {

constexpr std::string_view kStepDirPrefix = "icpbench-rank";

// The step directory of a worker rank in the temporary directory: its rank
// and process id in the name, so ranks sharing a node do not meet.
std::filesystem::path StepDir(int rank) {
  return std::filesystem::temp_directory_path() /
         (std::string(kStepDirPrefix) + std::to_string(rank) + "-" + std::to_string(getpid()));
}

// Removes the step directories that killed ranks left (a rank removes its
// own when it ends, but not when SIGKILL or a crash ends it): those named as
// StepDir names them whose process no longer exists. A directory whose
// process lives, or that cannot be removed (another user's), stays.
void RemoveStaleStepDirs() {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::temp_directory_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(kStepDirPrefix)) continue;
    const std::size_t dash = name.rfind('-');
    int pid = 0;
    const char* first = name.data() + dash + 1;
    const char* last = name.data() + name.size();
    if (dash == std::string::npos || std::from_chars(first, last, pid).ptr != last || pid <= 0) continue;
    if (kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::filesystem::remove_all(entry.path(), ec);
  }
}

}  // namespace

WorkerRank::WorkerRank(int rank, const Spec* spec, const RunnerOptions& options,
                       const MpiSweepOptions& mpi)
    : rank_(rank),
      spec_(spec),
      mpi_(mpi),
      jobs_(std::max(1, options.jobs)),
      step_dir_(StepDir(rank)),
      pool_(step_dir_.string(), options.jobs, options.kill_grace_s),
      machine_(CurrentProvenance().machine) {}

WorkerRank::~WorkerRank() {
  pool_.Stop();
  std::error_code ec;
  std::filesystem::remove_all(step_dir_, ec);
}

int WorkerRank::Run(std::string error, bool* peer_lost) {
  RemoveStaleStepDirs();
  std::error_code ec;
  std::filesystem::create_directories(step_dir_, ec);
  if (error.empty() && ec)
    error = RankName(rank_) + " cannot create its step directory " + step_dir_.string() + ": " +
            ec.message();
  heard_ = Clock::now();
  SendToRankZero(kReady, nlohmann::json{{"jobs", error.empty() ? jobs_ : 0}, {"error", error}, {"machine", machine_}}
                             .dump());
  if (const int cpus = UsableCpus(); error.empty() && jobs_ > cpus)
    std::fprintf(stderr,
                 "icpbench: %s runs --jobs %d on %d CPU%s: mpirun bound it (mpirun --bind-to none "
                 "lets its runs use the whole node)\n",
                 RankName(rank_).c_str(), jobs_, cpus, cpus == 1 ? "" : "s");
  const StopSignals signals;
  Clock::time_point sent = Clock::now(), last_check = sent;
  IdleBackoff backoff(std::chrono::milliseconds(10));
  while (true) {
    if (StopSignals::Caught() != 0) return 128 + StopSignals::Caught();
    bool idle = true;
    // Waits on the workers (a finished one ends the wait), or sleeps.
    if (pool_.Running() > 0) {
      pool_.Poll(backoff.NextMs(), [&](FinishedRun& f) {
        SendResult(f);
        sent = Clock::now();
        idle = false;
      });
    } else {
      backoff.Sleep();
    }
    Message m;
    while (TryReceive(0, &m)) {
      idle = false;
      heard_ = Clock::now();
      if (m.tag == kStop) {
        *peer_lost = m.bytes == kNoFinalize;
        return 0;
      }
      if (m.tag == kRun) StartRun(m.bytes);
    }
    const auto now = Clock::now();
    if (Seconds(now - sent) >= mpi_.heartbeat_s) {
      SendToRankZero(kHeartbeat, "");
      sent = now;
    }
    // Longer than the timeout since the last check: this rank did not run
    // (the job was suspended, as `scontrol suspend` does), so rank 0's
    // silence meanwhile says nothing: it has a fresh timeout to speak.
    if (Seconds(now - last_check) > mpi_.rank_timeout_s && !rank_zero_lost_) heard_ = now;
    last_check = now;
    if (rank_zero_lost_ || RankZeroSilent()) {
      std::fprintf(stderr, "icpbench: %s: nothing from rank 0 for %g s: stopping\n",
                   RankName(rank_).c_str(), mpi_.rank_timeout_s);
      *peer_lost = true;
      return 3;
    }
    if (!idle) backoff.Reset();
  }
}

void WorkerRank::StartRun(const std::string& bytes) {
  std::size_t index = 0;
  std::string key;
  if (!SplitIndex(bytes, &index, &key)) return;
  FinishedRun f;
  f.record.status = RunStatus::kFailed;
  if (spec_ == nullptr || index >= spec_->runs.size() || spec_->runs[index].spec.Key() != key) {
    f.record.reason = RankName(rank_) +
                      " expands the spec differently from rank 0 (another icpbench "
                      "version or other plugins?)";
  } else if (pool_.Start(spec_->runs[index])) {
    in_flight_[key] = index;
    return;
  } else {  // recorded as failed: the next sweep retries it
    f.record.reason = RankName(rank_) + ": " + pool_.start_error() + ": " +
                      std::strerror(pool_.start_errno());
  }
  SendDone(index, f.record, false);
}

bool WorkerRank::RankZeroSilent() const { return Seconds(Clock::now() - heard_) > mpi_.rank_timeout_s; }

bool WorkerRank::SendToRankZero(Tag tag, std::string bytes) {
  if (rank_zero_lost_) return false;
  rank_zero_lost_ = !SendWhile(0, tag, std::move(bytes), [this] {
    while (TakeHeartbeat(0)) heard_ = Clock::now();
    return !RankZeroSilent();
  });
  return !rank_zero_lost_;
}

void WorkerRank::SendResult(FinishedRun& f) {
  const std::size_t index = IndexOf(f);
  bool steps = !f.step_file.empty();
  if (steps) {
    std::ifstream in(f.step_file, std::ios::binary);
    if (!in) {
      f.record.status = RunStatus::kFailed;
      f.record.reason = UnreadableWorkerOutput("cannot open the step file " + f.step_file);
      f.record.metrics = RunMetrics{};
      steps = false;
    }
    std::string chunk(kChunkBytes, '\0');
    while (steps && in) {
      in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
      const auto n = static_cast<std::size_t>(in.gcount());
      if (n > 0 && !SendToRankZero(kSteps, WithIndex(index, chunk.substr(0, n)))) return;  // rank 0 is gone
    }
  }
  SendDone(index, f.record, steps);
}

void WorkerRank::SendDone(std::size_t index, const RunRecord& r, bool steps) {
  SendToRankZero(kDone, WithIndex(index, nlohmann::json{{"summary", SerializeSummary(r)},
                                                        {"steps", steps},
                                                        {"machine", machine_}}.dump()));
}

std::size_t WorkerRank::IndexOf(const FinishedRun& f) {
  const auto it = in_flight_.find(f.run.spec.Key());
  const std::size_t index = it->second;  // every started run is there
  in_flight_.erase(it);
  return index;
}

}  // namespace icp::detail
