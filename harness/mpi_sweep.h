// `mpirun -n N icpbench run SPEC --mpi`: one sweep over N MPI ranks. Rank 0
// reads and validates the spec, sends its text to the other ranks (so only
// rank 0's machine needs the spec file), skips the runs already stored, and
// hands the others out one at a time to the worker ranks as they have room
// (dynamic load balancing: each rank runs up to --jobs runs at once in
// forked workers, harness/worker_pool.h, so a crash, hang or timeout is
// recorded as in a local sweep). Each finished run comes back over MPI (its
// summary, then its step file in chunks) and rank 0 stores it: it is the
// only process that writes OUT_DIR, which need not be shared.
//
// Ranks send each other a heartbeat every second. A worker rank rank 0
// hears nothing from for rank_timeout_s is lost: each of its runs in flight
// is handed to another rank, and a run lost with a second rank is recorded
// as failed with the ranks named. (Open MPI aborts the whole job when a rank
// dies unless mpirun is given --enable-recovery; then rank 0 dies too and
// the store is left as by a killed local sweep: rerunning resumes.) A
// worker rank that hears nothing from rank 0 for rank_timeout_s stops.
// SIGINT/SIGTERM (mpirun passes them on) stop the runs in flight as in a
// local sweep. After a lost rank or a signal no rank calls MPI_Finalize
// (Open MPI 4.1's can wait forever on a dead rank).
#ifndef ICPBENCH_HARNESS_MPI_SWEEP_H_
#define ICPBENCH_HARNESS_MPI_SWEEP_H_

#include <iosfwd>
#include <string>

#include "harness/runner.h"

namespace icp {

struct MpiSweepOptions {
  double rank_timeout_s = 60;  // in [kMinRankTimeoutS, kMaxRankTimeoutS]
  double heartbeat_s = 1;
};

// The range of --rank-timeout, checked where the option is read: at least
// two heartbeats (a shorter silence loses busy ranks by mistake), at most a
// day (a dead rank's runs wait that long for another rank).
constexpr double kMinRankTimeoutS = 2;
constexpr double kMaxRankTimeoutS = 86400;

struct MpiSweepResult {
  bool dispatcher = false;  // rank 0: summary is the sweep's
  SweepSummary summary;
  int worker_exit_code = 0;  // a worker rank's exit code
};

// Whether this icpbench was built with MPI.
bool MpiBuilt();

// Initializes MPI, runs this rank's part and finalizes MPI. Rank 0 reports
// progress on `progress`. Throws what RunSweep throws on rank 0, SpecError
// for a bad spec, std::invalid_argument without MPI or with one rank.
MpiSweepResult RunMpiSweep(const std::string& spec_file, const RunnerOptions& options,
                           const MpiSweepOptions& mpi, std::ostream& progress, bool terminal);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_MPI_SWEEP_H_
