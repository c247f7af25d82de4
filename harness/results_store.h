// The results store: one SQLite file per output directory, append-only. A
// row per run (spec, status, reason, wall time, provenance, metrics) and a
// row per step, plus the step's reported variables. Each run is written in
// one transaction when it finishes, so a sweep that dies loses only the runs
// in flight; reading a spec again skips the runs whose key is stored.
//
// Schema (version 2, recorded in table meta with the conventions below; a
// version-1 store is migrated when opened):
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
// from several threads; its calls are serialised.
#ifndef ICPBENCH_HARNESS_RESULTS_STORE_H_
#define ICPBENCH_HARNESS_RESULTS_STORE_H_

#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/run_record.h"

struct sqlite3;

namespace icp {

class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ResultsStore {
 public:
  // Opens (creating if needed) the store at path. Throws StoreError.
  explicit ResultsStore(const std::string& path);
  ~ResultsStore();
  ResultsStore(const ResultsStore&) = delete;
  ResultsStore& operator=(const ResultsStore&) = delete;

  // Keys of the stored runs.
  std::vector<std::string> RunKeys() const;
  bool HasRun(const std::string& key) const;
  // Appends a run with its steps in one transaction; a run with the same key
  // is replaced (used by --force).
  void Insert(const RunRecord& run);
  // Every stored run, in insertion order; steps are loaded only if asked.
  std::vector<RunRecord> LoadRuns(bool with_steps) const;
  // Copies the runs of another store whose keys are not here; returns how
  // many were copied.
  int MergeFrom(const std::string& other_path);

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
  mutable std::mutex mutex_;  // one connection: one statement sequence at a time
};

// The store file inside an output directory.
std::string StorePath(const std::string& out_dir);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_RESULTS_STORE_H_
