// What the MPI sweep's sources share (not part of its API): the messages the
// ranks exchange, the idle backoff, and the two roles, a worker rank and
// rank 0's dispatcher. Built only with MPI.
#ifndef ICPBENCH_HARNESS_MPI_SWEEP_INTERNAL_H_
#define ICPBENCH_HARNESS_MPI_SWEEP_INTERNAL_H_

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <vector>

#include "harness/mpi_sweep.h"
#include "harness/spec.h"
#include "harness/sweep_recorder.h"
#include "harness/worker_pool.h"

namespace icp::detail {

using Clock = std::chrono::steady_clock;

inline double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// CPU time of this thread: rank 0's own cost, not the time the other ranks
// on its cores take from it.
double ThreadCpuSeconds();

// --- Messages (mpi_sweep_protocol.cc) ---------------------------------------

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
inline constexpr std::string_view kNoFinalize = "no-finalize";

inline constexpr std::size_t kChunkBytes = 1 << 20;

bool Send(int dest, Tag tag, const std::string& bytes);
// Send without blocking: polls until the message has left (true), or until
// keep_waiting() says to give up (false; a receiver that died never takes a
// large message, and a blocking send to it never returns).
bool SendWhile(int dest, Tag tag, std::string bytes, const std::function<bool()>& keep_waiting);
// Takes one heartbeat waiting from source, leaving other messages queued.
bool TakeHeartbeat(int source);

struct Message {
  int source = 0;
  int tag = 0;
  std::string bytes;
};

// The next message from `source` (MPI_ANY_SOURCE: anyone), if one is there.
bool TryReceive(int source, Message* m);

std::string WithIndex(std::size_t index, const std::string& rest);

// Splits "index\nrest"; false when malformed.
bool SplitIndex(const std::string& bytes, std::size_t* index, std::string* rest);

// Rank 0's text of the spec goes to every rank; "" with an error.
void BroadcastSpec(int rank, std::string* text, std::string* error);

std::string RankName(int rank);

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

// --- A worker rank (mpi_sweep_worker.cc) ------------------------------------

class WorkerRank {
 public:
  WorkerRank(int rank, const Spec* spec, const RunnerOptions& options, const MpiSweepOptions& mpi);
  ~WorkerRank();

  // Tells rank 0 how many runs it takes at once (none, with the reason,
  // when `error` says this rank cannot run the spec), then runs what it is
  // sent. Returns 0 when rank 0 said stop, 3 when rank 0 went silent, 128 +
  // the signal that stopped it. *peer_lost: rank 0 lost a rank, or this
  // rank lost rank 0 (MPI_Finalize must not be called).
  int Run(std::string error, bool* peer_lost);

 private:
  void StartRun(const std::string& bytes);
  // Sends to rank 0 while it lives: false once nothing came from it for
  // --rank-timeout (its heartbeats are taken while waiting); then rank 0 is
  // lost and nothing more is sent.
  bool SendToRankZero(Tag tag, std::string bytes);
  // Whether rank 0 has been silent for --rank-timeout.
  bool RankZeroSilent() const;
  void SendResult(FinishedRun& f);
  void SendDone(std::size_t index, const RunRecord& r, bool steps);
  // The matrix index of a finished run.
  std::size_t IndexOf(const FinishedRun& f);

  int rank_;
  const Spec* spec_;
  MpiSweepOptions mpi_;
  int jobs_;
  std::filesystem::path step_dir_;
  WorkerPool pool_;
  std::string machine_;
  std::unordered_map<std::string, std::size_t> in_flight_;  // key -> matrix index
  Clock::time_point heard_;     // the last message from rank 0
  bool rank_zero_lost_ = false;  // a send to it was given up
};

// --- Rank 0 (mpi_sweep_dispatcher.cc; heartbeats and lost ranks in
// mpi_sweep_lost_ranks.cc) ---------------------------------------------------

class Dispatcher {
 public:
  // *rank_lost is set when a rank is lost.
  Dispatcher(const Spec& spec, int ranks, const MpiSweepOptions& mpi, SweepRecorder* recorder,
             std::ostream& messages, bool* rank_lost);
  ~Dispatcher();

  // Returns when every run is stored, a stop signal came, or no rank is left.
  void Run();

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
  void SendHeartbeats();
  // Sends runs to the ranks with room; returns whether it sent any.
  bool Dispatch();
  void Store(const RunRecord& r, std::size_t index, const std::string& step_file,
             const std::string& where);
  void Handle(const Message& m);
  void Finish(std::size_t r, InFlightRun& run, const std::string& done);
  // The rank is gone: its runs in flight go back to the queue, or fail if
  // they were lost with another rank before.
  void Lose(std::size_t r, const std::string& why);
  static void Discard(InFlightRun& run);
  // Where the steps of the run at `index` from rank r are written.
  std::string StepFileFor(std::size_t r, std::size_t index) const;
  // "1:2 2:1 3:lost": the runs in flight on each worker rank.
  std::string InFlightText() const;

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

}  // namespace icp::detail

#endif  // ICPBENCH_HARNESS_MPI_SWEEP_INTERNAL_H_
