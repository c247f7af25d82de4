// The results store: one SQLite file per output directory, append-only. A
// row per run (spec, status, reason, wall time, provenance, metrics) and a
// row per step, plus the step's reported variables (none for a run whose
// spec said record: runs; its runs.steps still counts them). Each run is written in
// one transaction when it finishes, so a sweep that dies loses only the runs
// in flight; reading a spec again skips the runs whose key is stored (and
// retries the failed and timed-out ones, see RunSweep).
//
// Schema (version 3, recorded in table meta with the conventions below; a
// version-1 or 2 store is migrated when opened for writing, and read as it
// is when opened read-only):
//   meta(key, value)                      schema_version, conventions
//   runs(id, key UNIQUE, spec_file, algorithm, algorithm_params JSON,
//        problem, problem_params JSON, seed, timeout_s, status, reason,
//        wall_time_s, steps, <RunMetrics fields>, corridors JSON,
//        <Provenance fields>)             one row per run, id = insertion order
//   steps(run_id, step, status, contained, area, centre_error, solve_time_s,
//         estimate)                      estimate: box|paving|accumulator|particles
//   step_values(run_id, step, pos, var, lo, hi, truth)
//                                         pos: the variable's place in the step;
//                                         keyed by (run_id, step, pos), var unique
//   step_properties(run_id, step, name, type, value)
//   run_properties(run_id, name, type, value)
//                                         what an estimator reports beyond the
//                                         columns; type int|real|text, value of
//                                         that SQL type; one value per name (the
//                                         last reported wins); loaded sorted by name
//   attempts(run_key, attempt, status, reason, wall_time_s, timeout_s, steps,
//            date, git_revision, machine)
//                                         the summary of every run row that was
//                                         replaced (a retry, --force, a merge
//                                         conflict), attempt = 1, 2, ... per key in
//                                         the order they were replaced; the run in
//                                         runs is the newest (or, after a merge, the
//                                         preferred) one; added by version 3
// Values: a NaN double is stored as NULL; +-inf as SQL REAL infinities (so
// empty boxes keep lo = +inf, hi = -inf); contained -1 (unknown) as NULL, so
// SQL aggregates skip unknown truths; seed as INTEGER, the uint64 read
// as int64 (seeds >= 2^63 show negative in SQL and load back exactly). In the
// corridors JSON a NaN is null and +-inf the strings "inf" and "-inf".
// Loading gives back exactly what was stored, except that SQLite keeps -0.0
// as 0.0.
//
// The file is in WAL mode with a 30 s busy timeout: reports can read while a
// sweep writes, and several processes may write. One ResultsStore may be used
// from several threads; its calls are serialised. A read-only store
// (OpenReadOnly) never writes the file, switches its journal or creates
// -wal/-shm files, so archived or another user's stores can be reported.
#ifndef ICPBENCH_HARNESS_RESULTS_STORE_H_
#define ICPBENCH_HARNESS_RESULTS_STORE_H_

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "harness/run_record.h"

struct sqlite3;

namespace icp {

class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Steps one at a time: fills *step and returns true, or returns false after
// the last.
using StepSource = std::function<bool(StepRecord*)>;
// The steps of run.steps (the record must outlive the source).
StepSource StepsOf(const RunRecord& run);

// A stored run's key and status (what a resume decides on).
struct StoredRun {
  std::string key;
  RunStatus status;
  std::string spec_file;  // SPEC#experiment that stored it
};

// One replaced run summary, from table attempts.
struct Attempt {
  std::string run_key;
  int attempt = 0;
  RunStatus status = RunStatus::kOk;
  std::string reason;
  double wall_time_s = 0;
  double timeout_s = 0;
  int steps = 0;
  std::string date;
  std::string git_revision;
  std::string machine;
};

// What MergeStores did: runs written and how key conflicts were settled.
class ResultsStore;
struct MergeSummary;
MergeSummary MergeStores(const std::string& out_dir, const std::vector<std::string>& in_dirs);

struct MergeSummary {
  int runs = 0;                   // runs in the merged store
  std::vector<int> from_input;    // runs kept from each input, in order
  int duplicates = 0;             // keys seen more than once
  // (kept status, dropped status) -> keys, for copies of differing status.
  std::map<std::pair<RunStatus, RunStatus>, int> kept_over;
  int equal_kept_first = 0;       // keys whose copies had the same status
  // "merge: 3 conflicting keys: kept ok over timeout for 2, ..." or "".
  std::string ConflictMessage() const;
};

class ResultsStore {
 public:
  // Opens (creating if needed) the store at path. Throws StoreError.
  explicit ResultsStore(const std::string& path);
  // Opens an existing store for reading only (SQLITE_OPEN_READONLY; no
  // journal switch, no schema creation or migration: versions 1 to 3 are
  // read as they are). A missing, zero-byte or non-store file is a
  // StoreError. Insert and MergeFrom throw StoreError on it.
  static std::unique_ptr<ResultsStore> OpenReadOnly(const std::string& path);
  ~ResultsStore();
  ResultsStore(const ResultsStore&) = delete;
  ResultsStore& operator=(const ResultsStore&) = delete;

  // Keys of the stored runs.
  std::vector<std::string> RunKeys() const;
  bool HasRun(const std::string& key) const;
  // Key and status of every stored run, in insertion order.
  std::vector<StoredRun> StoredRuns() const;
  // Appends a run with its steps in one transaction; a run with the same key
  // is replaced (a retry, --force), its summary kept in table attempts.
  void Insert(const RunRecord& run);
  // The same with the steps read one at a time from `steps` (run.steps is
  // not read), so a long run is stored in memory independent of its length.
  // An exception from `steps` rolls the run back and propagates.
  void Insert(const RunRecord& run, const StepSource& steps);
  // The replaced run summaries, by key then attempt.
  std::vector<Attempt> Attempts() const;
  // Every stored run, in insertion order; steps are loaded only if asked.
  std::vector<RunRecord> LoadRuns(bool with_steps) const;
  // Copies the runs of another store whose keys are not here, and replaces a
  // run here whose copy there is preferred (PreferredOver); returns how many
  // were copied or replaced.
  int MergeFrom(const std::string& other_path);

  const std::string& path() const { return path_; }
  int schema_version() const { return version_; }

 private:
  friend MergeSummary MergeStores(const std::string& out_dir,
                                  const std::vector<std::string>& in_dirs);
  struct ReadOnlyTag {};
  ResultsStore(const std::string& path, ReadOnlyTag);

  std::string path_;
  bool read_only_ = false;
  int version_ = 0;
  sqlite3* db_ = nullptr;
  mutable std::mutex mutex_;  // one connection: one statement sequence at a time
};

// The store file inside an output directory.
std::string StorePath(const std::string& out_dir);

// Whether a merge keeps a copy of status a over one of status b: ok, then
// skipped, then failed and timeout (equal, so the first copy is kept).
bool PreferredOver(RunStatus a, RunStatus b);

// Merges the stores of in_dirs (and the store already in out_dir, taken as
// the first input) into out_dir's store. Every input is opened and read
// before anything is written; the result is written to a temporary file in
// out_dir and renamed over out_dir/results.sqlite at the end, so a missing or
// bad input leaves out_dir as it was. Per key the preferred copy is kept
// (PreferredOver; among equals the first input's), the others go to table
// attempts, as do the inputs' own attempts. Holds out_dir's lock
// (directory_lock.h) throughout, as a `run` does: throws DirectoryLockedError
// while another process holds it, and removes what a killed merge left.
// Throws StoreError.
MergeSummary MergeStores(const std::string& out_dir, const std::vector<std::string>& in_dirs);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_RESULTS_STORE_H_
