#include "harness/results_store.h"

#include <sqlite3.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <nlohmann/json.hpp>
#include <string_view>
#include <set>
#include <system_error>
#include <unordered_map>
#include <type_traits>
#include <utility>
#include <variant>

#include "harness/environment_error.h"

namespace icp {

namespace {

constexpr int kSchemaVersion = 3;
constexpr int kBusyTimeoutMs = 30000;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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

constexpr const char* kRunColumns =
    "key, spec_file, algorithm, algorithm_params, problem, problem_params, seed, timeout_s, "
    "status, reason, wall_time_s, steps, mean_area, consistency_rate, centre_rmse, time_mean_s, "
    "time_median_s, time_p90_s, time_mean_ci_lo_s, time_mean_ci_hi_s, corridors, git_revision, "
    "machine, compiler, flags, date";

[[noreturn]] void Fail(const std::string& path, const std::string& what, sqlite3* db) {
  std::string message = "results store '" + path + "': " + what;
  if (db != nullptr) message += ": " + std::string(sqlite3_errmsg(db));
  // The environment's failures (exit 3), with what to do about them.
  switch (db != nullptr ? sqlite3_errcode(db) & 0xff : SQLITE_OK) {
    case SQLITE_FULL: throw EnvironmentError(message + " (free disk space and rerun)");
    case SQLITE_CANTOPEN:
      throw EnvironmentError(message + " (check permissions; raise ulimit -n or reduce --jobs)");
    case SQLITE_READONLY: throw EnvironmentError(message + " (check the permissions of the store)");
    case SQLITE_IOERR: throw EnvironmentError(message + " (check the disk and its free space)");
    case SQLITE_NOMEM: throw EnvironmentError(message + " (out of memory: reduce --jobs)");
    default: break;
  }
  throw StoreError(message);
}

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
  double ColumnDouble(int i) const { return IsNull(i) ? kNaN : sqlite3_column_double(stmt_, i); }

 private:
  void Check(int rc) {
    if (rc != SQLITE_OK) Fail(path_, "binding a value", db_);
  }
  sqlite3* db_;
  const std::string& path_;
  sqlite3_stmt* stmt_ = nullptr;
};

void Exec(sqlite3* db, const std::string& path, const char* sql) {
  char* error = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &error) != SQLITE_OK) {
    std::string message = error != nullptr ? error : sqlite3_errmsg(db);
    sqlite3_free(error);
    throw StoreError("results store '" + path + "': " + message);
  }
}

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

sqlite3* Open(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, flags, nullptr) != SQLITE_OK) {
    std::string message = "cannot open: ";
    message += db != nullptr ? sqlite3_errmsg(db) : "out of memory";
    // The OS's reason: descriptors, permissions or memory are the environment.
    const int os_error = db != nullptr ? sqlite3_system_errno(db) : ENOMEM;
    sqlite3_close_v2(db);
    if (IsEnvironmentErrno(os_error))
      throw EnvironmentError("results store '" + path + "': " + message + ": " +
                             std::strerror(os_error) + " (" + EnvironmentAdvice(os_error) + ")");
    std::error_code ec;
    std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec)) {
      message += " (directory '" + parent.string() + "' does not exist)";
    } else if (std::filesystem::is_directory(path, ec)) {
      message += " (it is a directory)";
    }
    throw StoreError("results store '" + path + "': " + message);
  }
  sqlite3_extended_result_codes(db, 1);
  sqlite3_busy_timeout(db, kBusyTimeoutMs);
  return db;
}

// Checks that db is an icpbench store and returns its schema version. With
// may_create (a writer), makes an empty file (or one without tables) into a
// store and migrates an older version to this one; without (a reader),
// accepts versions 1 to kSchemaVersion as they are.
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
    return StoreError("results store '" + path + "': not an icpbench results store (no meta table)");
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

std::string ParamsToJson(const ParamMap& params, const std::string& path) {
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [key, value] : params) object[key] = value;
  try {
    return object.dump();
  } catch (const nlohmann::json::exception& e) {
    throw StoreError("results store '" + path + "': parameters are not UTF-8 text: " + e.what());
  }
}

ParamMap ParamsFromJson(const std::string& text, const std::string& path) {
  ParamMap params;
  if (text.empty()) return params;
  try {
    nlohmann::json object = nlohmann::json::parse(text);
    for (const auto& [key, value] : object.items()) params[key] = value.get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw StoreError("results store '" + path + "': bad parameter JSON '" + text + "': " + e.what());
  }
  return params;
}

nlohmann::ordered_json NumberToJson(double v) {
  if (std::isnan(v)) return nullptr;
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

double NumberFromJson(const nlohmann::ordered_json& j) {
  if (j.is_null()) return kNaN;
  if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    throw nlohmann::json::other_error::create(501, "bad number '" + s + "'", &j);
  }
  return j.get<double>();
}

std::string CorridorsToJson(const std::vector<Corridor>& corridors) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const Corridor& c : corridors) {
    array.push_back({{"var", c.var},
                     {"mean_lower", NumberToJson(c.mean_lower)},
                     {"mean_upper", NumberToJson(c.mean_upper)},
                     {"min_lower", NumberToJson(c.min_lower)},
                     {"max_upper", NumberToJson(c.max_upper)}});
  }
  return array.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::vector<Corridor> CorridorsFromJson(const std::string& text, const std::string& path) {
  std::vector<Corridor> corridors;
  if (text.empty()) return corridors;
  try {
    for (const auto& j : nlohmann::ordered_json::parse(text)) {
      Corridor c;
      c.var = j.at("var").get<std::string>();
      c.mean_lower = NumberFromJson(j.at("mean_lower"));
      c.mean_upper = NumberFromJson(j.at("mean_upper"));
      c.min_lower = NumberFromJson(j.at("min_lower"));
      c.max_upper = NumberFromJson(j.at("max_upper"));
      corridors.push_back(std::move(c));
    }
  } catch (const nlohmann::json::exception& e) {
    throw StoreError("results store '" + path + "': bad corridors JSON: " + e.what());
  }
  return corridors;
}

// Binds a property's name, type and value to columns i, i + 1, i + 2.
void BindProperty(Statement& q, int i, const Property& p) {
  q.Text(i, p.name);
  q.Text(i + 1, TypeName(p));
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::int64_t>) q.Int(i + 2, v);
        else if constexpr (std::is_same_v<T, double>) q.Double(i + 2, v);
        else q.Text(i + 2, v);
      },
      p.value);
}

// A property from columns name, type, value at i, i + 1, i + 2.
Property ReadProperty(const Statement& q, int i) {
  Property p{q.ColumnText(i), std::int64_t{0}};
  const std::string type = q.ColumnText(i + 1);
  if (type == "int") p.value = q.ColumnInt(i + 2);
  else if (type == "real") p.value = q.ColumnDouble(i + 2);
  else p.value = q.ColumnText(i + 2);
  return p;
}

// Appends a.* as the key's next attempt (a.attempt is ignored). Runs inside
// the caller's transaction.
void AddAttempt(sqlite3* db, const std::string& path, const Attempt& a) {
  Statement q(db, path,
              "INSERT INTO attempts (run_key, attempt, status, reason, wall_time_s, timeout_s, "
              "steps, date, git_revision, machine) VALUES (?1, (SELECT coalesce(max(attempt), 0) "
              "+ 1 FROM attempts WHERE run_key = ?1), ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
  q.Text(1, a.run_key);
  q.Text(2, ToString(a.status));
  q.Text(3, a.reason);
  q.Double(4, a.wall_time_s);
  q.Double(5, a.timeout_s);
  q.Int(6, a.steps);
  q.Text(7, a.date);
  q.Text(8, a.git_revision);
  q.Text(9, a.machine);
  q.Run();
}

// The summary of a run, as an attempt.
Attempt AttemptOf(const RunRecord& run) {
  Attempt a;
  a.run_key = run.spec.Key();
  a.status = run.status;
  a.reason = run.reason;
  a.wall_time_s = run.wall_time_s;
  a.timeout_s = run.spec.timeout_s;
  a.steps = run.metrics.steps;
  a.date = run.provenance.date;
  a.git_revision = run.provenance.git_revision;
  a.machine = run.provenance.machine;
  return a;
}

// Reads status, reason, wall_time_s, timeout_s, steps, date, git_revision
// and machine from columns first, first + 1, ... into a (a.run_key is set).
void ReadAttemptFields(const Statement& q, int first, const std::string& path, Attempt* a) {
  try {
    a->status = ParseRunStatus(q.ColumnText(first));
  } catch (const std::invalid_argument& e) {
    throw StoreError("results store '" + path + "': run '" + a->run_key + "': " + e.what());
  }
  a->reason = q.ColumnText(first + 1);
  a->wall_time_s = q.ColumnDouble(first + 2);
  a->timeout_s = q.ColumnDouble(first + 3);
  a->steps = static_cast<int>(q.ColumnInt(first + 4));
  a->date = q.ColumnText(first + 5);
  a->git_revision = q.ColumnText(first + 6);
  a->machine = q.ColumnText(first + 7);
}

// The summary of the stored run with this key, and its id; nullopt if none.
std::optional<std::pair<std::int64_t, Attempt>> StoredSummary(sqlite3* db, const std::string& path,
                                                              const std::string& key) {
  Statement find(db, path,
                 "SELECT id, status, reason, wall_time_s, timeout_s, steps, date, git_revision, "
                 "machine FROM runs WHERE key = ?");
  find.Text(1, key);
  if (!find.Step()) return std::nullopt;
  Attempt a;
  a.run_key = key;
  ReadAttemptFields(find, 1, path, &a);
  return std::make_pair(find.ColumnInt(0), a);
}

// Whether two summaries are one measurement (the attempt number aside): a
// merge records a dropped copy only if it is not a duplicate of one kept.
bool SameMeasurement(const Attempt& a, const Attempt& b) {
  auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return a.run_key == b.run_key && a.status == b.status && a.reason == b.reason &&
         same(a.wall_time_s, b.wall_time_s) && same(a.timeout_s, b.timeout_s) &&
         a.steps == b.steps && a.date == b.date && a.git_revision == b.git_revision &&
         a.machine == b.machine;
}

// Writes one run with its steps, replacing a run with the same key (whose
// summary goes to attempts first, so no measurement vanishes silently). Runs
// inside the caller's transaction.
// The steps come from next_step (run.steps is not read): a run of any
// length is written without holding its steps.
void WriteRun(sqlite3* db, const std::string& path, const RunRecord& run, const StepSource& next_step) {
  const std::string key = run.spec.Key();
  {
    if (auto stored = StoredSummary(db, path, key)) {
      const std::int64_t old_id = stored->first;
      AddAttempt(db, path, stored->second);
      for (const char* sql : {"DELETE FROM step_values WHERE run_id = ?",
                              "DELETE FROM step_properties WHERE run_id = ?",
                              "DELETE FROM run_properties WHERE run_id = ?",
                              "DELETE FROM steps WHERE run_id = ?", "DELETE FROM runs WHERE id = ?"}) {
        Statement del(db, path, sql);
        del.Int(1, old_id);
        del.Run();
      }
    }
  }

  Statement insert(db, path,
                   std::string("INSERT INTO runs (") + kRunColumns +
                       ") VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
  const RunMetrics& m = run.metrics;
  const Provenance& p = run.provenance;
  int i = 0;
  insert.Text(++i, key);
  insert.Text(++i, run.spec_file);
  insert.Text(++i, run.spec.algorithm);
  insert.Text(++i, ParamsToJson(run.spec.algorithm_params, path));
  insert.Text(++i, run.spec.problem);
  insert.Text(++i, ParamsToJson(run.spec.problem_params, path));
  insert.Int(++i, static_cast<std::int64_t>(run.spec.seed));
  insert.Double(++i, run.spec.timeout_s);
  insert.Text(++i, ToString(run.status));
  insert.Text(++i, run.reason);
  insert.Double(++i, run.wall_time_s);
  insert.Int(++i, m.steps);
  insert.Double(++i, m.mean_area);
  insert.Double(++i, m.consistency_rate);
  insert.Double(++i, m.centre_rmse);
  insert.Double(++i, m.time_mean_s);
  insert.Double(++i, m.time_median_s);
  insert.Double(++i, m.time_p90_s);
  insert.Double(++i, m.time_mean_ci_lo_s);
  insert.Double(++i, m.time_mean_ci_hi_s);
  insert.Text(++i, CorridorsToJson(m.corridors));
  insert.Text(++i, p.git_revision);
  insert.Text(++i, p.machine);
  insert.Text(++i, p.compiler);
  insert.Text(++i, p.flags);
  insert.Text(++i, p.date);
  insert.Run();
  const std::int64_t run_id = sqlite3_last_insert_rowid(db);
  {
    Statement run_property(db, path,
                           "INSERT OR REPLACE INTO run_properties (run_id, name, type, value) "
                           "VALUES (?,?,?,?)");
    for (const Property& p : run.properties) {
      run_property.Int(1, run_id);
      BindProperty(run_property, 2, p);
      run_property.Run();
      run_property.Reset();
    }
  }

  Statement step_insert(db, path,
                        "INSERT INTO steps (run_id, step, status, contained, area, centre_error, "
                        "solve_time_s, estimate) VALUES (?,?,?,?,?,?,?,?)");
  Statement property_insert(db, path,
                            "INSERT OR REPLACE INTO step_properties (run_id, step, name, type, value) "
                            "VALUES (?,?,?,?,?)");
  Statement value_insert(db, path,
                         "INSERT INTO step_values (run_id, step, var, pos, lo, hi, truth) "
                         "VALUES (?,?,?,?,?,?,?)");
  StepRecord s;
  while (next_step(&s)) {
    step_insert.Int(1, run_id);
    step_insert.Int(2, s.step);
    step_insert.Text(3, s.status);
    if (s.contained == -1) {
      step_insert.Null(4);
    } else {
      step_insert.Int(4, s.contained);
    }
    step_insert.Double(5, s.area);
    step_insert.Double(6, s.centre_error);
    step_insert.Double(7, s.solve_time_s);
    step_insert.Text(8, s.estimate);
    step_insert.Run();
    step_insert.Reset();
    for (const Property& p : s.properties) {
      property_insert.Int(1, run_id);
      property_insert.Int(2, s.step);
      BindProperty(property_insert, 3, p);
      property_insert.Run();
      property_insert.Reset();
    }
    for (std::size_t pos = 0; pos < s.vars.size(); ++pos) {
      const VariableRecord& v = s.vars[pos];
      value_insert.Int(1, run_id);
      value_insert.Int(2, s.step);
      value_insert.Text(3, v.name);
      value_insert.Int(4, static_cast<std::int64_t>(pos));
      value_insert.Double(5, v.lo);
      value_insert.Double(6, v.hi);
      value_insert.Double(7, v.truth);
      value_insert.Run();
      value_insert.Reset();
    }
  }
}

// Every run, in insertion order, with one query per table.
// A version-1 store (read-only) has no estimate column and no properties.
std::vector<RunRecord> ReadRuns(sqlite3* db, const std::string& path, int version,
                                bool with_steps) {
  std::vector<RunRecord> runs;
  std::unordered_map<std::int64_t, std::size_t> index_of;  // runs.id -> index in runs
  {
    Statement q(db, path, std::string("SELECT id, ") + kRunColumns + " FROM runs ORDER BY id");
    while (q.Step()) {
      RunRecord r;
      RunMetrics& m = r.metrics;
      Provenance& p = r.provenance;
      int i = 0;
      const std::int64_t id = q.ColumnInt(i++);
      const std::string key = q.ColumnText(i++);
      r.spec_file = q.ColumnText(i++);
      r.spec.algorithm = q.ColumnText(i++);
      r.spec.algorithm_params = ParamsFromJson(q.ColumnText(i++), path);
      r.spec.problem = q.ColumnText(i++);
      r.spec.problem_params = ParamsFromJson(q.ColumnText(i++), path);
      r.spec.seed = static_cast<std::uint64_t>(q.ColumnInt(i++));
      r.spec.timeout_s = q.ColumnDouble(i++);
      const std::string status = q.ColumnText(i++);
      try {
        r.status = ParseRunStatus(status);
      } catch (const std::invalid_argument& e) {
        throw StoreError("results store '" + path + "': run '" + key + "': " + e.what());
      }
      r.reason = q.ColumnText(i++);
      r.wall_time_s = q.ColumnDouble(i++);
      m.steps = static_cast<int>(q.ColumnInt(i++));
      m.mean_area = q.ColumnDouble(i++);
      m.consistency_rate = q.ColumnDouble(i++);
      m.centre_rmse = q.ColumnDouble(i++);
      m.time_mean_s = q.ColumnDouble(i++);
      m.time_median_s = q.ColumnDouble(i++);
      m.time_p90_s = q.ColumnDouble(i++);
      m.time_mean_ci_lo_s = q.ColumnDouble(i++);
      m.time_mean_ci_hi_s = q.ColumnDouble(i++);
      m.corridors = CorridorsFromJson(q.ColumnText(i++), path);
      p.git_revision = q.ColumnText(i++);
      p.machine = q.ColumnText(i++);
      p.compiler = q.ColumnText(i++);
      p.flags = q.ColumnText(i++);
      p.date = q.ColumnText(i++);
      index_of[id] = runs.size();
      runs.push_back(std::move(r));
    }
  }
  if (!with_steps || runs.empty()) return runs;

  {
    Statement q(db, path,
                std::string("SELECT run_id, step, status, contained, area, centre_error, "
                            "solve_time_s, ") +
                    (version >= 2 ? "estimate" : "NULL") + " FROM steps ORDER BY run_id, step");
    RunRecord* run = nullptr;
    std::int64_t run_id = 0;
    while (q.Step()) {
      const std::int64_t id = q.ColumnInt(0);
      if (run == nullptr || id != run_id) {
        auto it = index_of.find(id);
        if (it == index_of.end()) continue;  // no such run: ignored
        run = &runs[it->second];
        run_id = id;
      }
      StepRecord s;
      s.step = static_cast<int>(q.ColumnInt(1));
      s.status = q.ColumnText(2);
      s.contained = q.IsNull(3) ? -1 : static_cast<int>(q.ColumnInt(3));
      s.area = q.ColumnDouble(4);
      s.centre_error = q.ColumnDouble(5);
      s.solve_time_s = q.ColumnDouble(6);
      s.estimate = q.IsNull(7) ? "box" : q.ColumnText(7);  // version 1 stored boxes only
      run->steps.push_back(std::move(s));
    }
  }
  {
    Statement q(db, path,
                "SELECT run_id, step, var, lo, hi, truth FROM step_values "
                "ORDER BY run_id, step, pos");
    std::int64_t last_run = 0;
    std::int64_t last_step = 0;
    StepRecord* step = nullptr;
    while (q.Step()) {
      const std::int64_t id = q.ColumnInt(0);
      const std::int64_t number = q.ColumnInt(1);
      if (step == nullptr || id != last_run || number != last_step) {
        step = nullptr;
        last_run = id;
        last_step = number;
        auto it = index_of.find(id);
        if (it != index_of.end()) {
          std::vector<StepRecord>& steps = runs[it->second].steps;
          auto s = std::lower_bound(steps.begin(), steps.end(), number,
                                    [](const StepRecord& a, std::int64_t n) { return a.step < n; });
          if (s != steps.end() && s->step == number) step = &*s;
        }
        if (step == nullptr) continue;  // no such step: ignored
      }
      VariableRecord v;
      v.name = q.ColumnText(2);
      v.lo = q.ColumnDouble(3);
      v.hi = q.ColumnDouble(4);
      v.truth = q.ColumnDouble(5);
      step->vars.push_back(std::move(v));
    }
  }
  if (version < 2) return runs;
  {
    Statement q(db, path, "SELECT run_id, name, type, value FROM run_properties ORDER BY run_id, name");
    while (q.Step()) {
      auto it = index_of.find(q.ColumnInt(0));
      if (it != index_of.end()) runs[it->second].properties.push_back(ReadProperty(q, 1));
    }
  }
  {
    Statement q(db, path,
                "SELECT run_id, step, name, type, value FROM step_properties "
                "ORDER BY run_id, step, name");
    while (q.Step()) {
      auto it = index_of.find(q.ColumnInt(0));
      if (it == index_of.end()) continue;
      std::vector<StepRecord>& steps = runs[it->second].steps;
      const std::int64_t number = q.ColumnInt(1);
      auto s = std::lower_bound(steps.begin(), steps.end(), number,
                                [](const StepRecord& a, std::int64_t n) { return a.step < n; });
      if (s != steps.end() && s->step == number) s->properties.push_back(ReadProperty(q, 2));
    }
  }
  return runs;
}

// The attempts table, by key then attempt (none before version 3).
std::vector<Attempt> ReadAttempts(sqlite3* db, const std::string& path, int version) {
  std::vector<Attempt> attempts;
  if (version < 3) return attempts;
  Statement q(db, path,
              "SELECT run_key, attempt, status, reason, wall_time_s, timeout_s, steps, date, "
              "git_revision, machine FROM attempts ORDER BY run_key, attempt");
  while (q.Step()) {
    Attempt a;
    a.run_key = q.ColumnText(0);
    a.attempt = static_cast<int>(q.ColumnInt(1));
    ReadAttemptFields(q, 2, path, &a);
    attempts.push_back(std::move(a));
  }
  return attempts;
}

// Runs body inside one read transaction (one snapshot for all its queries).
template <class Body>
void InReadTransaction(sqlite3* db, const std::string& path, Body&& body) {
  InTransaction(db, path, std::forward<Body>(body), "BEGIN");
}

// Opens an existing store file for reading only. Without a -wal file no
// writer has the store open, so it is opened immutable: SQLite then creates
// no -wal/-shm files (a plain read-only open of a WAL file does, and cannot
// on a read-only directory). With one, a sweep may be writing: a plain
// read-only open shares its WAL index.
sqlite3* OpenExistingReadOnly(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw StoreError("results store '" + path + "': no such file");
  }
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw StoreError("results store '" + path + "': not a regular file");
  }
  if (std::filesystem::file_size(path, ec) == 0) {
    throw StoreError("results store '" + path + "': empty file (0 bytes), not a results store");
  }
  if (std::filesystem::exists(path + "-wal", ec)) return Open(path, SQLITE_OPEN_READONLY);
  std::string uri = "file:";
  for (char c : std::filesystem::absolute(path, ec).string()) {
    // Percent-encode what a URI path cannot hold literally.
    if (c == '%' || c == '?' || c == '#') {
      static const char kHex[] = "0123456789ABCDEF";
      uri += '%';
      uri += kHex[(static_cast<unsigned char>(c) >> 4) & 15];
      uri += kHex[static_cast<unsigned char>(c) & 15];
    } else {
      uri += c;
    }
  }
  uri += "?immutable=1";
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(uri.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr) !=
      SQLITE_OK) {
    std::string message = db != nullptr ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close_v2(db);
    throw StoreError("results store '" + path + "': cannot open read-only: " + message);
  }
  sqlite3_extended_result_codes(db, 1);
  sqlite3_busy_timeout(db, kBusyTimeoutMs);
  return db;
}

// Rank for PreferredOver: a finished measurement beats a deterministic skip,
// which beats a run that did not finish.
int Rank(RunStatus s) {
  switch (s) {
    case RunStatus::kOk: return 2;
    case RunStatus::kSkipped: return 1;
    case RunStatus::kFailed:
    case RunStatus::kTimeout: return 0;
  }
  return 0;
}

}  // namespace

bool PreferredOver(RunStatus a, RunStatus b) { return Rank(a) > Rank(b); }

ResultsStore::ResultsStore(const std::string& path) : path_(path) {
  db_ = Open(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
  try {
    // Each run commits on its own; WAL lets reports read while a sweep writes.
    std::string mode;
    {
      Statement wal(db_, path_, "PRAGMA journal_mode=WAL");
      if (wal.Step()) mode = wal.ColumnText(0);
    }
    if (mode != "wal") {
      throw StoreError("results store '" + path_ + "': cannot use WAL journal mode (got '" + mode +
                       "')");
    }
    Exec(db_, path_, "PRAGMA foreign_keys=ON");
    version_ = CheckOrCreateSchema(db_, path_, /*may_create=*/true);
  } catch (...) {
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw;
  }
}

ResultsStore::ResultsStore(const std::string& path, ReadOnlyTag) : path_(path), read_only_(true) {
  db_ = OpenExistingReadOnly(path);
  try {
    version_ = CheckOrCreateSchema(db_, path_, /*may_create=*/false);
  } catch (...) {
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw;
  }
}

std::unique_ptr<ResultsStore> ResultsStore::OpenReadOnly(const std::string& path) {
  return std::unique_ptr<ResultsStore>(new ResultsStore(path, ReadOnlyTag{}));
}

ResultsStore::~ResultsStore() { sqlite3_close_v2(db_); }

std::vector<std::string> ResultsStore::RunKeys() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> keys;
  Statement q(db_, path_, "SELECT key FROM runs ORDER BY id");
  while (q.Step()) keys.push_back(q.ColumnText(0));
  return keys;
}

bool ResultsStore::HasRun(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  Statement q(db_, path_, "SELECT 1 FROM runs WHERE key = ?");
  q.Text(1, key);
  return q.Step();
}

std::vector<StoredRun> ResultsStore::StoredRuns() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<StoredRun> runs;
  Statement q(db_, path_, "SELECT key, status FROM runs ORDER BY id");
  while (q.Step()) {
    StoredRun r{q.ColumnText(0), RunStatus::kOk};
    try {
      r.status = ParseRunStatus(q.ColumnText(1));
    } catch (const std::invalid_argument& e) {
      throw StoreError("results store '" + path_ + "': run '" + r.key + "': " + e.what());
    }
    runs.push_back(std::move(r));
  }
  return runs;
}

void ResultsStore::Insert(const RunRecord& run) { Insert(run, StepsOf(run)); }

void ResultsStore::Insert(const RunRecord& run, const StepSource& steps) {
  if (read_only_) throw StoreError("results store '" + path_ + "': opened read-only");
  std::lock_guard<std::mutex> lock(mutex_);
  InTransaction(db_, path_, [&] { WriteRun(db_, path_, run, steps); });
}

StepSource StepsOf(const RunRecord& run) {
  return [&run, next = std::size_t{0}](StepRecord* step) mutable {
    if (next == run.steps.size()) return false;
    *step = run.steps[next++];
    return true;
  };
}

std::vector<Attempt> ResultsStore::Attempts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return ReadAttempts(db_, path_, version_);
}

std::vector<RunRecord> ResultsStore::LoadRuns(bool with_steps) const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<RunRecord> runs;
  InReadTransaction(db_, path_, [&] { runs = ReadRuns(db_, path_, version_, with_steps); });
  return runs;
}

int ResultsStore::MergeFrom(const std::string& other_path) {
  if (read_only_) throw StoreError("results store '" + path_ + "': opened read-only");
  std::vector<RunRecord> others;
  {
    std::unique_ptr<ResultsStore> other = OpenReadOnly(other_path);
    others = other->LoadRuns(/*with_steps=*/true);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  int copied = 0;
  InTransaction(db_, path_, [&] {
    for (const RunRecord& run : others) {
      if (auto here = StoredSummary(db_, path_, run.spec.Key())) {
        if (!PreferredOver(run.status, here->second.status)) {
          // The dropped copy is kept as an attempt, unless it is this very run.
          const Attempt dropped = AttemptOf(run);
          if (!SameMeasurement(dropped, here->second)) AddAttempt(db_, path_, dropped);
          continue;
        }
      }
      WriteRun(db_, path_, run, StepsOf(run));  // a replaced copy goes to attempts
      ++copied;
    }
  });
  return copied;
}

std::string MergeSummary::ConflictMessage() const {
  if (duplicates == 0) return "";
  std::string m = "merge: " + std::to_string(duplicates) + " conflicting key" +
                  (duplicates == 1 ? "" : "s") + ":";
  const char* sep = " ";
  for (const auto& [statuses, n] : kept_over) {
    m += sep + std::string("kept ") + std::string(ToString(statuses.first)) + " over " +
         std::string(ToString(statuses.second)) + " for " + std::to_string(n);
    sep = ", ";
  }
  if (equal_kept_first > 0) {
    m += sep + std::string("kept the first of equal-status copies for ") +
         std::to_string(equal_kept_first);
  }
  return m + " (dropped copies are in table attempts)";
}

MergeSummary MergeStores(const std::string& out_dir, const std::vector<std::string>& in_dirs) {
  namespace fs = std::filesystem;
  const std::string out_path = StorePath(out_dir);
  // Read everything first: a missing or bad input fails before OUT is touched.
  struct Input {
    std::vector<RunRecord> runs;
    std::vector<Attempt> attempts;
  };
  std::vector<Input> inputs;
  std::error_code ec;
  const bool out_exists = fs::exists(out_path, ec);
  std::vector<std::string> sources;
  if (out_exists) sources.push_back(out_path);
  for (const std::string& dir : in_dirs) sources.push_back(StorePath(dir));
  for (const std::string& source : sources) {
    std::unique_ptr<ResultsStore> store = ResultsStore::OpenReadOnly(source);
    Input input;
    input.runs = store->LoadRuns(/*with_steps=*/true);
    input.attempts = store->Attempts();
    inputs.push_back(std::move(input));
  }

  // Per key the preferred copy, among equals the first; drops become attempts.
  MergeSummary summary;
  summary.from_input.assign(in_dirs.size(), 0);
  struct Chosen {
    const RunRecord* run;
    std::size_t input;
    std::set<RunStatus> dropped;
    bool equal = false;
  };
  std::vector<std::string> order;  // keys in first-seen order
  std::unordered_map<std::string, Chosen> chosen;
  std::vector<Attempt> attempts;
  std::unordered_map<std::string, std::vector<std::size_t>> attempts_of;  // key -> indices
  // A copy of one measurement (a store merged twice, overlapping shards) is
  // recorded once.
  auto add_attempt = [&](const Attempt& a) {
    std::vector<std::size_t>& same_key = attempts_of[a.run_key];
    for (std::size_t j : same_key) {
      if (SameMeasurement(a, attempts[j])) return;
    }
    same_key.push_back(attempts.size());
    attempts.push_back(a);
  };
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    for (const Attempt& a : inputs[i].attempts) add_attempt(a);
    for (const RunRecord& run : inputs[i].runs) {
      const std::string key = run.spec.Key();
      auto [it, inserted] = chosen.try_emplace(key, Chosen{&run, i, {}, false});
      if (inserted) {
        order.push_back(key);
        continue;
      }
      Chosen& c = it->second;
      if (PreferredOver(run.status, c.run->status)) {
        add_attempt(AttemptOf(*c.run));
        c.dropped.insert(c.run->status);
        c.run = &run;
        c.input = i;
      } else if (!SameMeasurement(AttemptOf(run), AttemptOf(*c.run))) {
        // A copy of the very same measurement is no conflict.
        add_attempt(AttemptOf(run));
        if (run.status == c.run->status) c.equal = true;
        else c.dropped.insert(run.status);
      }
    }
  }
  for (const std::string& key : order) {
    const Chosen& c = chosen.at(key);
    if (c.dropped.empty() && !c.equal) continue;
    ++summary.duplicates;
    if (c.dropped.empty()) ++summary.equal_kept_first;
    for (RunStatus d : c.dropped) ++summary.kept_over[{c.run->status, d}];
  }

  // Write a temporary store beside OUT and rename it over OUT at the end.
  fs::create_directories(out_dir);
  const std::string tmp_path =
      out_path + ".merge-" + std::to_string(static_cast<long long>(getpid())) + ".tmp";
  auto remove_tmp = [&] {
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) fs::remove(tmp_path + suffix, ec);
  };
  remove_tmp();
  try {
    {
      ResultsStore out(tmp_path);
      std::lock_guard<std::mutex> lock(out.mutex_);
      InTransaction(out.db_, tmp_path, [&] {
        for (const std::string& key : order) {
          const Chosen& c = chosen.at(key);
          WriteRun(out.db_, tmp_path, *c.run, StepsOf(*c.run));
          if (c.input >= (out_exists ? 1u : 0u)) ++summary.from_input[c.input - (out_exists ? 1 : 0)];
          ++summary.runs;
        }
        for (const Attempt& a : attempts) AddAttempt(out.db_, tmp_path, a);
      });
      // Fold the WAL into the file and leave WAL mode, so the rename moves
      // one complete file and no -wal is left behind under the old name.
      Exec(out.db_, tmp_path, "PRAGMA journal_mode=DELETE");
    }
    // The old OUT was read above; stale side files must not be replayed
    // into the new one.
    for (const char* suffix : {"-wal", "-shm"}) fs::remove(out_path + suffix, ec);
    fs::rename(tmp_path, out_path);
  } catch (...) {
    remove_tmp();
    throw;
  }
  return summary;
}

std::string StorePath(const std::string& out_dir) { return out_dir + "/results.sqlite"; }

}  // namespace icp
