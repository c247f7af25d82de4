// The results store's schema: its tables, the conventions recorded with them,
// creating a store and migrating versions 1 and 2 to version 3.
#include <string>
#include <utility>

#include "harness/results_store_internal.h"

namespace icp::detail {

namespace {

constexpr int kSchemaVersion = 3;

constexpr const char* kConventions =
    "NaN doubles are NULL; +-inf are REAL infinities; steps.contained is 1 (truth in box), "
    "0 (not) or NULL (truth unknown); empty boxes have lo=+inf, hi=-inf; times in s, areas in "
    "m^2, distances in m; *_params are JSON objects of text values; corridors is a JSON array "
    "(NaN as null, +-inf as \"inf\"/\"-inf\"); seed is the uint64 read as int64; step_values.pos "
    "is the variable's place in its step (0-based); steps.estimate is the estimate's kind "
    "(box, paving, accumulator, particles); step_properties and run_properties hold what an "
    "estimator reports beyond the typed columns, as (name, type, value) with type int, real or "
    "text and value of that SQL type; *_params hold the effective parameters (defaults "
    "resolved), as the run key does; attempts holds the summary of each replaced run row "
    "(attempt 1, 2, ... per run_key), the row in runs being the newest or merge-preferred one.";

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS meta (
  key TEXT PRIMARY KEY,
  value TEXT
);
CREATE TABLE IF NOT EXISTS runs (
  id INTEGER PRIMARY KEY,
  key TEXT UNIQUE NOT NULL,
  spec_file TEXT,
  algorithm TEXT,
  algorithm_params TEXT,
  problem TEXT,
  problem_params TEXT,
  seed INTEGER,
  timeout_s REAL,
  status TEXT,
  reason TEXT,
  wall_time_s REAL,
  steps INTEGER,
  mean_area REAL,
  consistency_rate REAL,
  centre_rmse REAL,
  time_mean_s REAL,
  time_median_s REAL,
  time_p90_s REAL,
  time_mean_ci_lo_s REAL,
  time_mean_ci_hi_s REAL,
  corridors TEXT,
  git_revision TEXT,
  machine TEXT,
  compiler TEXT,
  flags TEXT,
  date TEXT
);
CREATE TABLE IF NOT EXISTS steps (
  run_id INTEGER NOT NULL REFERENCES runs(id),
  step INTEGER NOT NULL,
  status TEXT,
  contained INTEGER,
  area REAL,
  centre_error REAL,
  solve_time_s REAL,
  estimate TEXT,
  PRIMARY KEY (run_id, step)
) WITHOUT ROWID;
CREATE TABLE IF NOT EXISTS step_values (
  run_id INTEGER NOT NULL,
  step INTEGER NOT NULL,
  pos INTEGER NOT NULL,
  var TEXT NOT NULL,
  lo REAL,
  hi REAL,
  truth REAL,
  PRIMARY KEY (run_id, step, pos),
  UNIQUE (run_id, step, var),
  FOREIGN KEY (run_id, step) REFERENCES steps(run_id, step)
) WITHOUT ROWID;
)sql";

// Tables added by version 2; also the migration of a version-1 store.
constexpr const char* kPropertiesSchema = R"sql(
CREATE TABLE IF NOT EXISTS step_properties (
  run_id INTEGER NOT NULL,
  step INTEGER NOT NULL,
  name TEXT NOT NULL,
  type TEXT NOT NULL,
  value,
  PRIMARY KEY (run_id, step, name),
  FOREIGN KEY (run_id, step) REFERENCES steps(run_id, step)
) WITHOUT ROWID;
CREATE TABLE IF NOT EXISTS run_properties (
  run_id INTEGER NOT NULL REFERENCES runs(id),
  name TEXT NOT NULL,
  type TEXT NOT NULL,
  value,
  PRIMARY KEY (run_id, name)
) WITHOUT ROWID;
)sql";

// Table added by version 3; also the migration of a version-2 store.
constexpr const char* kAttemptsSchema = R"sql(
CREATE TABLE IF NOT EXISTS attempts (
  run_key TEXT NOT NULL,
  attempt INTEGER NOT NULL,
  status TEXT,
  reason TEXT,
  wall_time_s REAL,
  timeout_s REAL,
  steps INTEGER,
  date TEXT,
  git_revision TEXT,
  machine TEXT,
  PRIMARY KEY (run_key, attempt)
) WITHOUT ROWID;
)sql";

}  // namespace

int CheckOrCreateSchema(sqlite3* db, const std::string& path, bool may_create) {
  auto has_meta = [&] {
    Statement q(db, path, "SELECT count(*) FROM sqlite_master WHERE type='table' AND name='meta'");
    q.Step();
    return q.ColumnInt(0) > 0;
  };
  auto table_count = [&] {
    Statement q(db, path, "SELECT count(*) FROM sqlite_master WHERE type='table'");
    q.Step();
    return q.ColumnInt(0);
  };
  auto version = [&] {
    Statement q(db, path, "SELECT value FROM meta WHERE key='schema_version'");
    return q.Step() ? q.ColumnText(0) : std::string();
  };
  auto set_version = [&](int v) {
    Statement update(db, path, "UPDATE meta SET value = ? WHERE key = 'schema_version'");
    update.Text(1, std::to_string(v));
    update.Run();
    Statement conventions(db, path, "UPDATE meta SET value = ? WHERE key = 'conventions'");
    conventions.Text(1, kConventions);
    conventions.Run();
  };
  auto check_version = [&]() -> int {
    const std::string v = version();
    if (may_create && (v == "1" || v == "2")) {
      // One transaction for the whole chain, so a reader never sees a half
      // migrated store.
      InTransaction(db, path, [&] {
        if (version() == "1") {
          // Version 1 lacks the estimate kind and the open properties; its
          // runs keep their keys (typed parameters), so a rerun of their
          // spec, now keyed on effective parameters, runs them again.
          Exec(db, path, "ALTER TABLE steps ADD COLUMN estimate TEXT");
          Exec(db, path, kPropertiesSchema);
          set_version(2);
        }
        if (version() == "2") {
          // Version 2 kept no record of replaced runs.
          Exec(db, path, kAttemptsSchema);
          set_version(3);
        }
      });
      return kSchemaVersion;
    }
    for (int known = 1; known <= kSchemaVersion; ++known) {
      if (v == std::to_string(known) && (known == kSchemaVersion || !may_create)) return known;
    }
    throw StoreError("results store '" + path + "': schema version '" + v +
                     "', this build reads versions 1 to " + std::to_string(kSchemaVersion) +
                     " (older ones are migrated when opened for writing)");
  };
  // Reading the catalogue is also what reports "file is not a database".
  if (has_meta()) return check_version();
  auto not_a_store = [&] {
    return StoreError("results store '" + path +
                      "': not an icpbench results store (no meta table)");
  };
  if (!may_create) throw not_a_store();
  InTransaction(db, path, [&] {
    if (has_meta()) return;  // another process created it meanwhile
    if (table_count() > 0) throw not_a_store();
    Exec(db, path, kSchema);
    Exec(db, path, kPropertiesSchema);
    Exec(db, path, kAttemptsSchema);
    Statement insert(db, path, "INSERT INTO meta(key, value) VALUES (?, ?)");
    const std::pair<const char*, std::string> rows[] = {
        {"schema_version", std::to_string(kSchemaVersion)},
        {"conventions", kConventions},
        {"writer", "icpbench"},
    };
    for (const auto& [key, value] : rows) {
      insert.Text(1, key);
      insert.Text(2, value);
      insert.Run();
      insert.Reset();
    }
  });
  return check_version();
}

}  // namespace icp::detail
