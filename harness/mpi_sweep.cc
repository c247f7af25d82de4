// The MPI sweep's entry point: starts MPI, has rank 0 read the spec and
// broadcast it, then runs this rank's part (rank 0 dispatches, the others
// run; harness/mpi_sweep_*.cc) and decides whether MPI_Finalize is safe.
#include "harness/mpi_sweep.h"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>

#include "harness/mpi_sweep_internal.h"
#include "harness/spec.h"
#include "harness/sweep_recorder.h"

namespace icp {

namespace {

using detail::BroadcastSpec;
using detail::Dispatcher;
using detail::kNoFinalize;
using detail::kStop;
using detail::RankName;
using detail::Send;
using detail::WorkerRank;

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

}  // namespace

bool MpiBuilt() { return true; }

MpiSweepResult RunMpiSweep(const std::string& spec_file, const RunnerOptions& options,
                           const MpiSweepOptions& mpi, std::ostream& progress, bool terminal) {
  MpiSession session;
  if (session.size() < 2)
    throw std::invalid_argument(
        "--mpi needs at least 2 ranks (mpirun -n N, N >= 2): rank 0 dispatches, the "
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
    // Rank 0 says why and exits 2; this rank ends quietly, so that mpiexec,
    // which ends the job at the first rank that fails, does not kill rank 0
    // before its message is out.
    if (!error.empty()) return {false, {}, 0};
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
      for (int r = 1; r < session.size(); ++r)
        Send(r, kStop, no_finalize ? std::string(kNoFinalize) : "");
      if (no_finalize) session.SkipFinalize();
    }
  } stop_workers{session, no_finalize};
  if (failure) std::rethrow_exception(failure);
  SweepRecorder recorder(*spec, options, progress, terminal);
  progress << "icpbench: " << spec->runs.size() << " runs in " << spec_file;
  if (options.shard_count > 1)
    progress << ", shard " << options.shard_index << "/" << options.shard_count;
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
    std::snprintf(line, sizeof line,
                  "icpbench: rank 0 per run: %.3f ms CPU dispatching, %.3f ms CPU storing\n",
                  1e3 * (dispatcher.busy_s() - dispatcher.storing_s()) / runs,
                  1e3 * dispatcher.storing_s() / runs);
    progress << line;
  }
  return result;
}

}  // namespace icp
