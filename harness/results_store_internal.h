// What the results store's sources share (not part of its API): SQLite
// statements and transactions, the encodings of values, and the steps that
// schema, writing, reading and merging call on one another.
#ifndef ICPBENCH_HARNESS_RESULTS_STORE_INTERNAL_H_
#define ICPBENCH_HARNESS_RESULTS_STORE_INTERNAL_H_

#include <sqlite3.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "harness/results_store.h"

namespace icp::detail {

inline constexpr double kStoreNaN = std::numeric_limits<double>::quiet_NaN();

// The columns of table runs after id, in the order WriteRun binds and
// ReadRuns reads them.
inline constexpr const char* kRunColumns =
    "key, spec_file, algorithm, algorithm_params, problem, problem_params, seed, timeout_s, "
    "status, reason, wall_time_s, steps, mean_area, consistency_rate, centre_rmse, time_mean_s, "
    "time_median_s, time_p90_s, time_mean_ci_lo_s, time_mean_ci_hi_s, corridors, git_revision, "
    "machine, compiler, flags, date";

// Throws the error of `what` on the store at path, with SQLite's message when
// db is given: EnvironmentError for a full disk, descriptors, permissions,
// I/O or memory, else StoreError.
[[noreturn]] void Fail(const std::string& path, const std::string& what, sqlite3* db);

// A prepared statement, finalised on scope exit.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& path, std::string_view sql) : db_(db), path_(path) {
    if (sqlite3_prepare_v2(db, sql.data(), static_cast<int>(sql.size()), &stmt_, nullptr) !=
        SQLITE_OK) {
      Fail(path, "preparing '" + std::string(sql) + "'", db);
    }
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  void Text(int i, std::string_view v) {
    Check(sqlite3_bind_text(stmt_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT));
  }
  void Int(int i, std::int64_t v) { Check(sqlite3_bind_int64(stmt_, i, v)); }
  // NaN -> NULL; infinities are kept as REAL values.
  void Double(int i, double v) {
    Check(std::isnan(v) ? sqlite3_bind_null(stmt_, i) : sqlite3_bind_double(stmt_, i, v));
  }
  void Null(int i) { Check(sqlite3_bind_null(stmt_, i)); }

  // True while there is a row; throws on errors.
  bool Step() {
    int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    Fail(path_, "running '" + std::string(sqlite3_sql(stmt_)) + "'", db_);
  }
  void Run() {
    while (Step()) {
    }
  }
  void Reset() {
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
  }

  bool IsNull(int i) const { return sqlite3_column_type(stmt_, i) == SQLITE_NULL; }
  std::string ColumnText(int i) const {
    const unsigned char* p = sqlite3_column_text(stmt_, i);
    if (p == nullptr) return "";
    return std::string(reinterpret_cast<const char*>(p),
                       static_cast<std::size_t>(sqlite3_column_bytes(stmt_, i)));
  }
  std::int64_t ColumnInt(int i) const { return sqlite3_column_int64(stmt_, i); }
  double ColumnDouble(int i) const {
    return IsNull(i) ? kStoreNaN : sqlite3_column_double(stmt_, i);
  }

 private:
  void Check(int rc) {
    if (rc != SQLITE_OK) Fail(path_, "binding a value", db_);
  }
  sqlite3* db_;
  const std::string& path_;
  sqlite3_stmt* stmt_ = nullptr;
};

// Runs sql (one or more statements); a StoreError with SQLite's message.
void Exec(sqlite3* db, const std::string& path, const char* sql);

// Runs body inside BEGIN IMMEDIATE (a writer; or `begin`) ... COMMIT, rolling
// back if it throws.
template <class Body>
void InTransaction(sqlite3* db, const std::string& path, Body&& body,
                   const char* begin = "BEGIN IMMEDIATE") {
  Exec(db, path, begin);
  try {
    body();
    Exec(db, path, "COMMIT");
  } catch (...) {
    sqlite3_exec(db, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

// Runs body inside one read transaction (one snapshot for all its queries).
template <class Body>
void InReadTransaction(sqlite3* db, const std::string& path, Body&& body) {
  InTransaction(db, path, std::forward<Body>(body), "BEGIN");
}

// The status stored for run `key`; a StoreError if it is not one.
RunStatus ParseStoredStatus(const std::string& text, const std::string& path,
                            const std::string& key);

// Parameters as a JSON object of text values, and back.
std::string ParamsToJson(const ParamMap& params, const std::string& path);
ParamMap ParamsFromJson(const std::string& text, const std::string& path);
// Corridors as a JSON array (NaN as null, +-inf as "inf"/"-inf"), and back.
std::string CorridorsToJson(const std::vector<Corridor>& corridors);
std::vector<Corridor> CorridorsFromJson(const std::string& text, const std::string& path);
// Binds a property's name, type and value to columns i, i + 1, i + 2.
void BindProperty(Statement& q, int i, const Property& p);
// A property from columns name, type, value at i, i + 1, i + 2.
Property ReadProperty(const Statement& q, int i);

// Opens an existing store file for reading only (results_store.cc):
// immutable when no -wal file exists (no writer), else a plain read-only open
// that shares a running sweep's WAL index. Throws StoreError.
sqlite3* OpenExistingReadOnly(const std::string& path);

// Schema and migrations (results_store_schema.cc).
//
// Checks that db is an icpbench store and returns its schema version. With
// may_create (a writer), makes an empty file (or one without tables) into a
// store and migrates an older version to this one; without (a reader),
// accepts versions 1 to kSchemaVersion as they are.
int CheckOrCreateSchema(sqlite3* db, const std::string& path, bool may_create);

// Writing (results_store_write.cc).
//
// Appends a.* as the key's next attempt (a.attempt is ignored). Runs inside
// the caller's transaction.
void AddAttempt(sqlite3* db, const std::string& path, const Attempt& a);
// Writes one run with its steps, replacing a run with the same key (whose
// summary goes to attempts first, so no measurement vanishes silently). Runs
// inside the caller's transaction.
// The steps come from next_step (run.steps is not read): a run of any
// length is written without holding its steps.
void WriteRun(sqlite3* db, const std::string& path, const RunRecord& run,
              const StepSource& next_step);

// Reading (results_store_read.cc).
//
// The summary of the stored run with this key, and its id; nullopt if none.
std::optional<std::pair<std::int64_t, Attempt>> StoredSummary(sqlite3* db,
                                                              const std::string& path,
                                                              const std::string& key);

}  // namespace icp::detail

#endif  // ICPBENCH_HARNESS_RESULTS_STORE_INTERNAL_H_
