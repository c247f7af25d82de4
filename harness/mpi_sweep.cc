#include "harness/mpi_sweep.h"

#include <mpi.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <vector>

#include "core/params.h"
#include "harness/environment_error.h"
#include "harness/provenance.h"
#include "harness/sweep_recorder.h"
#include "harness/worker_output.h"
#include "harness/worker_pool.h"

namespace icp {

namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// CPU time of this thread: rank 0's own cost, not the time the other ranks
// on its cores take from it.
double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Every message is bytes; the tag says what they are. A message about a run
// starts with the run's index in the matrix and a newline.
enum Tag : int {
  kReady = 1,      // worker -> 0: {"jobs": K, "error": ""}
  kRun = 2,        // 0 -> worker: index \n key
  kSteps = 3,      // worker -> 0: index \n a chunk of the run's step file
  kDone = 4,       // worker -> 0: index \n {"summary", "steps", "machine"}
  kHeartbeat = 5,  // both ways, empty
  kStop = 6,       // 0 -> worker: no more runs; kNoFinalize after a loss or a signal
};

// The payload of kStop after a rank was lost or a stop signal came: Open
// MPI 4.1's MPI_Finalize can wait forever for a dead rank (its closing
// fence), and mpirun, stopping the job, would kill rank 0 in it before it
// says what it kept; so then no rank calls it (mpirun accepts that).
constexpr std::string_view kNoFinalize = "no-finalize";

constexpr std::size_t kChunkBytes = 1 << 20;

// MPI_Init and MPI_Finalize around a sweep; errors are returned, not fatal,
// so a dead peer does not abort this rank.
class MpiSession {
 public:
  MpiSession() {
    // Open MPI's handlers for SIGSEGV and the like would be inherited by the
    // forked workers and turn their crashes into backtraces: the runner
    // records the signal itself. (A user's own setting wins.)
    setenv("OMPI_MCA_opal_signal", "", 0);
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) MPI_Init(nullptr, nullptr);
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() {
    if (!skip_finalize_) MPI_Finalize();
  }
  void SkipFinalize() { skip_finalize_ = true; }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
  bool skip_finalize_ = false;
};

bool Send(int dest, Tag tag, const std::string& bytes) {
  return MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD) ==
         MPI_SUCCESS;
}

struct Message {
  int source = 0;
  int tag = 0;
  std::string bytes;
};

// The next message from `source` (MPI_ANY_SOURCE: anyone), if one is there.
bool TryReceive(int source, Message* m) {
  int flag = 0;
  MPI_Status status;
  if (MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status) != MPI_SUCCESS || !flag) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  m->source = status.MPI_SOURCE;
  m->tag = status.MPI_TAG;
  m->bytes.resize(static_cast<std::size_t>(count));
  MPI_Recv(m->bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return true;
}

std::string WithIndex(std::size_t index, const std::string& rest) { return std::to_string(index) + "\n" + rest; }

// Splits "index\nrest"; false when malformed.
bool SplitIndex(const std::string& bytes, std::size_t* index, std::string* rest) {
  const std::size_t nl = bytes.find('\n');
  if (nl == std::string::npos || nl == 0) return false;
  try {
    *index = std::stoul(bytes.substr(0, nl));
  } catch (const std::exception&) {
    return false;
  }
  *rest = bytes.substr(nl + 1);
  return true;
}

// Rank 0's text of the spec goes to every rank; "" with an error.
void BroadcastSpec(int rank, std::string* text, std::string* error) {
  std::string packed = rank == 0 ? (error->empty() ? "T" + *text : "E" + *error) : "";
  long long size = static_cast<long long>(packed.size());
  MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  packed.resize(static_cast<std::size_t>(size));
  MPI_Bcast(packed.data(), static_cast<int>(size), MPI_BYTE, 0, MPI_COMM_WORLD);
  if (packed.empty()) packed = "E(no spec received)";
  (packed[0] == 'T' ? *text : *error) = packed.substr(1);
}

std::string RankName(int rank) { return "rank " + std::to_string(rank); }

// The waits between polls while nothing happens: 50 us at first, so that a
// message is taken up at once in a busy sweep, doubling to `longest`, so
// that a rank waiting on long runs takes next to no CPU from them (three
// ranks polling every 2 ms took 4 % of a 2-core machine). Worker ranks wait
// up to 10 ms (a finished run wakes them through its pipe); rank 0 up to
// 1 ms, because a worker's result (a large message waits for the receiver)
// and its next run wait on rank 0.
class IdleBackoff {
 public:
  explicit IdleBackoff(std::chrono::microseconds longest) : longest_(longest) {}
  void Reset() { wait_ = kFirst; }
  std::chrono::microseconds Next() {
    const auto wait = wait_;
    wait_ = std::min(2 * wait_, longest_);
    return wait;
  }
  void Sleep() { std::this_thread::sleep_for(Next()); }
  // The next wait in whole milliseconds, at least one (for poll()).
  int NextMs() { return static_cast<int>(std::max<std::int64_t>(1, Next().count() / 1000)); }

 private:
  static constexpr std::chrono::microseconds kFirst{50};
  std::chrono::microseconds longest_;
  std::chrono::microseconds wait_ = kFirst;
};

// --- A worker rank ---------------------------------------------------------

class WorkerRank {
 public:
  WorkerRank(int rank, const Spec* spec, const RunnerOptions& options, const MpiSweepOptions& mpi)
      : rank_(rank),
        spec_(spec),
        mpi_(mpi),
        jobs_(std::max(1, options.jobs)),
        step_dir_(std::filesystem::temp_directory_path() /
                  ("icpbench-rank" + std::to_string(rank) + "-" + std::to_string(getpid()))),
        pool_(step_dir_.string(), options.jobs, options.kill_grace_s),
        machine_(CurrentProvenance().machine) {}
  ~WorkerRank() {
    pool_.Stop();
    std::error_code ec;
    std::filesystem::remove_all(step_dir_, ec);
  }

  // Tells rank 0 how many runs it takes at once (none, with the reason,
  // when `error` says this rank cannot run the spec), then runs what it is
  // sent. Returns 0 when rank 0 said stop, 3 when rank 0 went silent, 128 +
  // the signal that stopped it. *peer_lost: rank 0 lost a rank, or this
  // rank lost rank 0 (MPI_Finalize must not be called).
  int Run(std::string error, bool* peer_lost) {
    std::error_code ec;
    std::filesystem::create_directories(step_dir_, ec);
    if (error.empty() && ec)
      error = RankName(rank_) + " cannot create its step directory " + step_dir_.string() + ": " + ec.message();
    Send(0, kReady,
         nlohmann::json{{"jobs", error.empty() ? jobs_ : 0}, {"error", error}, {"machine", machine_}}.dump());
    if (const int cpus = UsableCpus(); error.empty() && jobs_ > cpus)
      std::fprintf(stderr,
                   "icpbench: %s runs --jobs %d on %d CPU%s: mpirun bound it (mpirun --bind-to none lets "
                   "its runs use the whole node)\n",
                   RankName(rank_).c_str(), jobs_, cpus, cpus == 1 ? "" : "s");
    const StopSignals signals;
    Clock::time_point heard = Clock::now(), sent = heard;
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
        heard = Clock::now();
        if (m.tag == kStop) {
          *peer_lost = m.bytes == kNoFinalize;
          return 0;
        }
        if (m.tag == kRun) StartRun(m.bytes);
      }
      const auto now = Clock::now();
      if (Seconds(now - sent) >= mpi_.heartbeat_s) {
        Send(0, kHeartbeat, "");
        sent = now;
      }
      if (Seconds(now - heard) > mpi_.rank_timeout_s) {
        std::fprintf(stderr, "icpbench: %s: nothing from rank 0 for %g s: stopping\n", RankName(rank_).c_str(),
                     mpi_.rank_timeout_s);
        *peer_lost = true;
        return 3;
      }
      if (!idle) backoff.Reset();
    }
  }

 private:
  void StartRun(const std::string& bytes) {
    std::size_t index = 0;
    std::string key;
    if (!SplitIndex(bytes, &index, &key)) return;
    FinishedRun f;
    f.record.status = RunStatus::kFailed;
    if (spec_ == nullptr || index >= spec_->runs.size() || spec_->runs[index].spec.Key() != key) {
      f.record.reason = RankName(rank_) + " expands the spec differently from rank 0 (another icpbench "
                        "version or other plugins?)";
    } else if (pool_.Start(spec_->runs[index])) {
      in_flight_[key] = index;
      return;
    } else {  // recorded as failed: the next sweep retries it
      f.record.reason = RankName(rank_) + ": " + pool_.start_error() + ": " + std::strerror(pool_.start_errno());
    }
    SendDone(index, f.record, false);
  }

  void SendResult(FinishedRun& f) {
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
        if (n > 0) Send(0, kSteps, WithIndex(index, chunk.substr(0, n)));
      }
    }
    SendDone(index, f.record, steps);
  }

  void SendDone(std::size_t index, const RunRecord& r, bool steps) {
    Send(0, kDone, WithIndex(index, nlohmann::json{{"summary", SerializeSummary(r)},
                                                   {"steps", steps},
                                                   {"machine", machine_}}.dump()));
  }

  // The matrix index of a finished run.
  std::size_t IndexOf(const FinishedRun& f) {
    const auto it = in_flight_.find(f.run.spec.Key());
    const std::size_t index = it->second;  // every started run is there
    in_flight_.erase(it);
    return index;
  }

  int rank_;
  const Spec* spec_;
  MpiSweepOptions mpi_;
  int jobs_;
  std::filesystem::path step_dir_;
  WorkerPool pool_;
  std::string machine_;
  std::unordered_map<std::string, std::size_t> in_flight_;  // key -> matrix index
};

// --- Rank 0 ---------------------------------------------------------------

class Dispatcher {
 public:
  // *rank_lost is set when a rank is lost.
  Dispatcher(const Spec& spec, int ranks, const MpiSweepOptions& mpi, SweepRecorder* recorder,
             std::ostream& messages, bool* rank_lost)
      : spec_(spec),
        mpi_(mpi),
        recorder_(recorder),
        messages_(messages),
        rank_lost_(rank_lost),
        ranks_(static_cast<std::size_t>(ranks)) {
    for (std::size_t i = 0; i < spec.runs.size(); ++i) index_of_[spec.runs[i].spec.Key()] = i;
    for (const PlannedRun& run : recorder->queue()) queue_.push_back({index_of_.at(run.spec.Key()), {}});
    recorder->queue().clear();
    const auto now = Clock::now();
    for (Rank& r : ranks_) r.heard = r.sent = now;
    ranks_[0].lost = true;  // this one: it runs nothing
  }

  ~Dispatcher() {
    for (Rank& rank : ranks_)
      for (auto& [index, run] : rank.in_flight) Discard(run);
  }

  // Returns when every run is stored, a stop signal came, or no rank is left.
  void Run() {
    const StopSignals signals;
    IdleBackoff backoff(std::chrono::milliseconds(1));
    while (StopSignals::Caught() == 0) {
      const double start = ThreadCpuSeconds();
      const bool sent = Dispatch();
      if (queue_.empty() && InFlight() == 0) {
        busy_s_ += ThreadCpuSeconds() - start;
        return;
      }
      if (LiveRanks() == 0) {
        throw EnvironmentError("every worker rank is lost or could not run the spec: " +
                               std::to_string(queue_.size() + InFlight()) +
                               " runs not run (rerunning resumes)");
      }
      bool received = false, drained = false;
      Message m;
      for (int i = 0; i < 64; ++i) {
        if (!TryReceive(MPI_ANY_SOURCE, &m)) {
          drained = true;
          break;
        }
        received = true;
        Handle(m);
      }
      if (sent || received) busy_s_ += ThreadCpuSeconds() - start;
      SendHeartbeats();
      // Only with every waiting message taken: after a long store here, a
      // live rank's heartbeats may still be queued.
      const auto now = Clock::now();
      for (std::size_t r = 1; r < ranks_.size() && drained; ++r) {
        if (!ranks_[r].lost && Seconds(now - ranks_[r].heard) > mpi_.rank_timeout_s)
          Lose(r, "nothing from it for " + FormatDouble(mpi_.rank_timeout_s) + " s");
      }
      if (sent || received) {
        backoff.Reset();
      } else {
        backoff.Sleep();
      }
    }
    interrupted_by_ = StopSignals::Caught();
  }

  int interrupted_by() const { return interrupted_by_; }
  // CPU seconds spent sending runs and handling messages (storing
  // included), and storing alone.
  double busy_s() const { return busy_s_; }
  double storing_s() const { return storing_s_; }
  int InFlight() const {
    int n = 0;
    for (const Rank& r : ranks_) n += static_cast<int>(r.in_flight.size());
    return n;
  }

 private:
  struct Pending {
    std::size_t index;
    std::vector<int> lost_with;  // the ranks it was in flight on when they were lost
  };
  struct InFlightRun {
    Pending pending;
    std::string step_file;  // where its steps arrive ("" until the first chunk)
    std::FILE* steps = nullptr;
  };
  struct Rank {
    bool ready = false;
    bool lost = false;
    int jobs = 0;
    Clock::time_point heard, sent;
    std::map<std::size_t, InFlightRun> in_flight;
  };

  int LiveRanks() const {
    int n = 0;
    for (const Rank& r : ranks_) n += !r.lost && (!r.ready || r.jobs > 0);
    return n;
  }

  // To each live rank whose heartbeat is due (also while a long run is
  // stored, so its rank does not take rank 0 for lost).
  void SendHeartbeats() {
    const auto now = Clock::now();
    for (std::size_t r = 1; r < ranks_.size(); ++r) {
      Rank& rank = ranks_[r];
      if (rank.lost || Seconds(now - rank.sent) < mpi_.heartbeat_s) continue;
      Send(static_cast<int>(r), kHeartbeat, "");  // a rank it cannot reach falls silent
      rank.sent = now;
    }
  }

  // Sends runs to the ranks with room; returns whether it sent any.
  bool Dispatch() {
    bool sent = false;
    for (std::size_t r = 1; r < ranks_.size(); ++r) {
      Rank& rank = ranks_[r];
      while (rank.ready && !rank.lost && static_cast<int>(rank.in_flight.size()) < rank.jobs && !queue_.empty()) {
        Pending p = queue_.front();
        queue_.pop_front();
        const PlannedRun& run = spec_.runs[p.index];
        if (!run.skip_reason.empty()) {
          Store(SweepRecorder::Skipped(run), p.index, "", "rank 0");
          continue;
        }
        if (!Send(static_cast<int>(r), kRun, WithIndex(p.index, run.spec.Key()))) {
          queue_.push_front(p);
          Lose(r, "a message to it failed");
          break;
        }
        rank.sent = Clock::now();
        rank.in_flight[p.index] = InFlightRun{p, "", nullptr};
        sent = true;
      }
    }
    if (sent) recorder_->progress().InFlight(recorder_->summary(), InFlightText());
    return sent;
  }

  void Store(const RunRecord& r, std::size_t index, const std::string& step_file, const std::string& where) {
    const double start = ThreadCpuSeconds();
    recorder_->Record(r, spec_.runs[index].experiment, step_file, where, InFlightText(),
                      [this] { SendHeartbeats(); });
    storing_s_ += ThreadCpuSeconds() - start;
  }

  void Handle(const Message& m) {
    const auto r = static_cast<std::size_t>(m.source);
    if (r == 0 || r >= ranks_.size()) return;
    Rank& rank = ranks_[r];
    if (rank.lost) {  // too late: its runs went elsewhere
      Send(m.source, kStop, "");
      return;
    }
    rank.heard = Clock::now();
    if (m.tag == kReady) {
      const nlohmann::json j = nlohmann::json::parse(m.bytes, nullptr, false);
      rank.ready = true;
      rank.jobs = j.is_object() ? j.value("jobs", 0) : 0;
      const std::string error = j.is_object() ? j.value("error", std::string("bad ready message")) : "bad ready message";
      if (!error.empty()) {
        messages_ << "icpbench: " << RankName(m.source) << " runs nothing: " << error << "\n";
      } else {
        messages_ << "icpbench: " << RankName(m.source) << " on "
                  << (j.is_object() ? j.value("machine", std::string("?")) : "?") << ": " << rank.jobs
                  << " runs at a time\n";
      }
      return;
    }
    std::size_t index = 0;
    std::string rest;
    if ((m.tag != kSteps && m.tag != kDone) || !SplitIndex(m.bytes, &index, &rest)) return;
    auto it = rank.in_flight.find(index);
    if (it == rank.in_flight.end()) return;
    if (m.tag == kSteps) {
      InFlightRun& run = it->second;
      if (run.steps == nullptr && run.step_file.empty()) {
        run.step_file = StepFilePath(recorder_->out_dir(), "rank" + std::to_string(r) + "-" + std::to_string(index));
        run.steps = std::fopen(run.step_file.c_str(), "we");
        if (run.steps == nullptr) ThrowErrno("cannot write the step file " + run.step_file, errno);
      }
      if (std::fwrite(rest.data(), 1, rest.size(), run.steps) != rest.size())
        ThrowErrno("cannot write the step file " + run.step_file, errno);
      return;
    }
    InFlightRun run = std::move(it->second);
    rank.in_flight.erase(it);  // before the progress counts what is in flight
    Dispatch();                // the rank's next run first: storing takes longer
    Finish(r, run, rest);
  }

  void Finish(std::size_t r, InFlightRun& run, const std::string& done) {
    const PlannedRun& planned = spec_.runs[run.pending.index];
    RunRecord record;
    record.spec = planned.spec;
    bool steps = false;
    try {
      const nlohmann::json j = nlohmann::json::parse(done);
      record = DeserializeSummary(j.at("summary").get<std::string>(), planned.spec);
      record.provenance.machine = j.at("machine").get<std::string>();
      steps = j.at("steps").get<bool>();
    } catch (const std::exception& e) {
      record.status = RunStatus::kFailed;
      record.reason = UnreadableWorkerOutput(std::string(e.what()) + ", from " + RankName(static_cast<int>(r)));
    }
    if (run.steps != nullptr && std::fclose(run.steps) != 0) {
      run.steps = nullptr;
      ThrowErrno("cannot write the step file " + run.step_file, errno);
    }
    run.steps = nullptr;
    if (steps && run.step_file.empty()) {  // a run of no steps sends no chunk
      run.step_file = StepFilePath(recorder_->out_dir(), "rank" + std::to_string(r) + "-" + std::to_string(run.pending.index));
      std::ofstream touch(run.step_file);
    }
    const std::string step_file = steps ? run.step_file : "";
    struct Unlink {
      std::string path;
      ~Unlink() {
        if (!path.empty()) std::remove(path.c_str());
      }
    } unlink_after{run.step_file};
    Store(record, run.pending.index, step_file, RankName(static_cast<int>(r)));
  }

  // The rank is gone: its runs in flight go back to the queue, or fail if
  // they were lost with another rank before.
  void Lose(std::size_t r, const std::string& why) {
    Rank& rank = ranks_[r];
    rank.lost = true;
    *rank_lost_ = true;
    messages_ << "icpbench: " << RankName(static_cast<int>(r)) << " lost (" << why << "): ";
    if (rank.in_flight.empty()) messages_ << "no run was in flight there\n";
    int requeued = 0;
    std::vector<Pending> failed;
    for (auto it = rank.in_flight.rbegin(); it != rank.in_flight.rend(); ++it) {
      InFlightRun& run = it->second;
      Discard(run);
      run.pending.lost_with.push_back(static_cast<int>(r));
      if (run.pending.lost_with.size() >= 2) {
        failed.push_back(run.pending);
      } else {
        queue_.push_front(run.pending);
        ++requeued;
      }
    }
    const int lost = static_cast<int>(rank.in_flight.size());
    rank.in_flight.clear();
    if (lost > 0)
      messages_ << requeued << " of its " << lost << " runs in flight go to other ranks, " << failed.size()
                << " (lost with a rank before) are recorded as failed\n";
    for (const Pending& p : failed) {
      RunRecord record;
      record.spec = spec_.runs[p.index].spec;
      record.status = RunStatus::kFailed;
      record.reason = "lost with worker ranks";
      for (int lost_rank : p.lost_with) record.reason += " " + std::to_string(lost_rank);
      record.reason += " (" + why + ")";
      Store(record, p.index, "", RankName(static_cast<int>(r)));
    }
  }

  static void Discard(InFlightRun& run) {
    if (run.steps != nullptr) std::fclose(run.steps);
    run.steps = nullptr;
    if (!run.step_file.empty()) std::remove(run.step_file.c_str());
  }

  // "1:2 2:1 3:lost": the runs in flight on each worker rank.
  std::string InFlightText() const {
    std::string text;
    for (std::size_t r = 1; r < ranks_.size(); ++r) {
      if (!text.empty()) text += " ";
      text += std::to_string(r) + ":" + (ranks_[r].lost ? "lost" : std::to_string(ranks_[r].in_flight.size()));
    }
    return text;
  }

  const Spec& spec_;
  MpiSweepOptions mpi_;
  SweepRecorder* recorder_;
  std::ostream& messages_;
  bool* rank_lost_;
  std::vector<Rank> ranks_;
  std::unordered_map<std::string, std::size_t> index_of_;
  std::deque<Pending> queue_;
  int interrupted_by_ = 0;
  double busy_s_ = 0;
  double storing_s_ = 0;
};

}  // namespace

bool MpiBuilt() { return true; }

MpiSweepResult RunMpiSweep(const std::string& spec_file, const RunnerOptions& options,
                           const MpiSweepOptions& mpi, std::ostream& progress, bool terminal) {
  MpiSession session;
  if (session.size() < 2)
    throw std::invalid_argument("--mpi needs at least 2 ranks (mpirun -n N, N >= 2): rank 0 dispatches, the "
                                "others run");
  // Rank 0 reads the spec; whatever it finds, the others learn it (else they
  // would wait in the broadcast).
  std::string text, error;
  std::optional<Spec> spec;
  std::exception_ptr failure;
  if (session.rank() == 0) {
    try {
      text = ReadSpecText(spec_file);
      spec = ParseSpec(text, spec_file);
    } catch (const std::exception& e) {
      error = e.what();
      failure = std::current_exception();
    }
  }
  BroadcastSpec(session.rank(), &text, &error);
  MpiSweepResult result;
  if (session.rank() != 0) {
    if (!error.empty()) return {false, {}, 2};  // rank 0 says why
    std::string spec_error;
    try {
      spec = ParseSpec(text, spec_file);
    } catch (const std::exception& e) {
      spec_error = RankName(session.rank()) + " cannot read rank 0's spec: " + e.what();
    }
    WorkerRank worker(session.rank(), spec ? &*spec : nullptr, options, mpi);
    bool peer_lost = false;
    try {
      result.worker_exit_code = worker.Run(spec_error, &peer_lost);
    } catch (...) {  // rank 0 will lose this rank: MPI_Finalize would wait on it
      session.SkipFinalize();
      throw;
    }
    if (peer_lost) session.SkipFinalize();
    return result;
  }
  // However rank 0 leaves (done, an error, a signal), the workers stop.
  bool no_finalize = false;  // a rank was lost, or a stop signal came
  struct StopWorkers {
    MpiSession& session;
    const bool& no_finalize;
    ~StopWorkers() {
      for (int r = 1; r < session.size(); ++r) Send(r, kStop, no_finalize ? std::string(kNoFinalize) : "");
      if (no_finalize) session.SkipFinalize();
    }
  } stop_workers{session, no_finalize};
  if (failure) std::rethrow_exception(failure);
  SweepRecorder recorder(*spec, options, progress, terminal);
  progress << "icpbench: " << spec->runs.size() << " runs in " << spec_file;
  if (options.shard_count > 1) progress << ", shard " << options.shard_index << "/" << options.shard_count;
  progress << ", " << recorder.queue().size() << " to run on " << session.size() - 1
           << " worker ranks, results in " << StorePath(options.out_dir) << "\n";
  result.dispatcher = true;
  Dispatcher dispatcher(*spec, session.size(), mpi, &recorder, progress, &no_finalize);
  dispatcher.Run();
  if (dispatcher.interrupted_by() != 0) no_finalize = true;
  result.summary = recorder.summary();
  result.summary.interrupted_by = dispatcher.interrupted_by();
  result.summary.stopped = dispatcher.InFlight();
  recorder.progress().Finish();
  if (const int runs = result.summary.Finished(); runs > 0) {
    char line[160];
    std::snprintf(line, sizeof line, "icpbench: rank 0 per run: %.3f ms CPU dispatching, %.3f ms CPU storing\n",
                  1e3 * (dispatcher.busy_s() - dispatcher.storing_s()) / runs, 1e3 * dispatcher.storing_s() / runs);
    progress << line;
  }
  return result;
}

}  // namespace icp
