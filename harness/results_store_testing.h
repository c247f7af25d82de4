// Runs and checks shared by the results store's tests
// (harness/results_store*_test.cc): a run with every field set, the
// comparison of a loaded run with the stored one, raw SQL on the file, and
// fresh paths.
#ifndef ICPBENCH_HARNESS_RESULTS_STORE_TESTING_H_
#define ICPBENCH_HARNESS_RESULTS_STORE_TESTING_H_

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <system_error>
#include <variant>

#include "harness/metrics.h"
#include "harness/run_record.h"

namespace icp::testing {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// A fresh store path per test, with no file or WAL left from an earlier run.
inline std::string FreshPath(const std::string& name) {
  std::string path = ::testing::TempDir() + "/icpbench_store_" + name + ".sqlite";
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::remove((path + suffix).c_str());
  return path;
}

// A run with every field set, NaN and infinities included; the same i gives
// the same run.
inline RunRecord MakeRun(int i, int num_steps, const std::string& algorithm = "hc4",
                         bool with_metrics = true) {
  RunRecord r;
  r.spec.algorithm = algorithm;
  r.spec.algorithm_params = {{"ratio", "0.01"}, {"odd", "a,b=c|{d}\\"}};
  r.spec.problem = "car-track";
  r.spec.problem_params = {{"w", "20"}, {"steps", std::to_string(num_steps)}};
  r.spec.seed = static_cast<std::uint64_t>(i);
  r.spec.timeout_s = 2.5;
  r.spec_file = "specs/table1.yaml";
  r.status = i % 4 == 3 ? RunStatus::kTimeout : RunStatus::kOk;
  r.reason = i % 4 == 3 ? "stopped after 2.5 s" : "";
  r.wall_time_s = 0.125 * i + 1.0 / 3;
  for (int k = 0; k < num_steps; ++k) {
    StepRecord s;
    s.step = k;
    const bool empty = k % 7 == 3;
    const bool unknown = k % 5 == 4;
    s.status = empty ? "empty" : "contracted";
    const double t = unknown ? kNaN : 0.1 * k;
    for (const char* name : {"x", "y", "theta"}) {
      VariableRecord v;
      v.name = name;
      v.lo = empty ? kInf : 0.1 * k - 1.0 / 7;
      v.hi = empty ? -kInf : 0.1 * k + 2.0 / 3;
      v.truth = t;
      s.vars.push_back(v);
    }
    if (k % 11 == 10 && !empty) s.vars[2].hi = kInf;  // unbounded heading
    s.contained = unknown ? -1 : empty ? 0 : 1;
    s.area = empty ? kNaN : 1.0 / (k + 3);
    s.centre_error = unknown || empty ? kNaN : 0.01 * k;
    s.solve_time_s = 1e-4 * (k % 13) + 1e-6 * i;
    s.estimate = k % 3 == 1 ? "paving" : "box";
    // Sorted by name: the store loads them so.
    s.properties = {{"boxes", std::int64_t{k}},
                    {"message", std::string(k % 2 ? "stopped: ratio" : "")},
                    {"q", k % 4 == 1 ? kNaN : 0.25 * k}};
    r.steps.push_back(s);
  }
  r.properties = {{"bisections", std::int64_t{-3}}, {"revise_calls", std::int64_t{1} << 40},
                  {"spread", kInf}};
  if (with_metrics) r.metrics = ComputeMetrics(r.steps, 3);
  r.metrics.corridors.push_back({"inf-test", kNaN, kInf, -kInf, 1.5});
  r.provenance = {"0123abc-dirty", "host1 / AMD EPYC", "GNU 12.2.0", "Release -O3",
                  "2024-05-01T12:00:00Z"};
  return r;
}

// Doubles as the store must give them back: NaN for NaN, the same value
// (infinities included) otherwise.
inline ::testing::AssertionResult Same(const char* what, double a, double b) {
  if ((std::isnan(a) && std::isnan(b)) || a == b) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": " << a << " != " << b;
}

inline void ExpectSameProperties(const Properties& a, const Properties& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    EXPECT_EQ(a[i].value.index(), b[i].value.index()) << a[i].name;
    if (a[i].value.index() == 1 && b[i].value.index() == 1)
      EXPECT_TRUE(Same(a[i].name.c_str(), std::get<double>(a[i].value),
                       std::get<double>(b[i].value)));
    else
      EXPECT_EQ(a[i].value, b[i].value) << a[i].name;
  }
}

inline void ExpectSameRun(const RunRecord& a, const RunRecord& b, bool with_steps) {
  SCOPED_TRACE(a.spec.Key());
  EXPECT_EQ(a.spec.Key(), b.spec.Key());
  EXPECT_EQ(a.spec.algorithm, b.spec.algorithm);
  EXPECT_EQ(a.spec.algorithm_params, b.spec.algorithm_params);
  EXPECT_EQ(a.spec.problem, b.spec.problem);
  EXPECT_EQ(a.spec.problem_params, b.spec.problem_params);
  EXPECT_EQ(a.spec.seed, b.spec.seed);
  EXPECT_TRUE(Same("timeout_s", a.spec.timeout_s, b.spec.timeout_s));
  EXPECT_EQ(a.spec_file, b.spec_file);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_TRUE(Same("wall_time_s", a.wall_time_s, b.wall_time_s));
  const RunMetrics& m = a.metrics;
  const RunMetrics& n = b.metrics;
  EXPECT_EQ(m.steps, n.steps);
  EXPECT_TRUE(Same("mean_area", m.mean_area, n.mean_area));
  EXPECT_TRUE(Same("consistency_rate", m.consistency_rate, n.consistency_rate));
  EXPECT_TRUE(Same("centre_rmse", m.centre_rmse, n.centre_rmse));
  EXPECT_TRUE(Same("time_mean_s", m.time_mean_s, n.time_mean_s));
  EXPECT_TRUE(Same("time_median_s", m.time_median_s, n.time_median_s));
  EXPECT_TRUE(Same("time_p90_s", m.time_p90_s, n.time_p90_s));
  EXPECT_TRUE(Same("time_mean_ci_lo_s", m.time_mean_ci_lo_s, n.time_mean_ci_lo_s));
  EXPECT_TRUE(Same("time_mean_ci_hi_s", m.time_mean_ci_hi_s, n.time_mean_ci_hi_s));
  EXPECT_EQ(m.corridors.size(), n.corridors.size());
  for (std::size_t i = 0; i < std::min(m.corridors.size(), n.corridors.size()); ++i) {
    EXPECT_EQ(m.corridors[i].var, n.corridors[i].var);
    EXPECT_TRUE(Same("mean_lower", m.corridors[i].mean_lower, n.corridors[i].mean_lower));
    EXPECT_TRUE(Same("mean_upper", m.corridors[i].mean_upper, n.corridors[i].mean_upper));
    EXPECT_TRUE(Same("min_lower", m.corridors[i].min_lower, n.corridors[i].min_lower));
    EXPECT_TRUE(Same("max_upper", m.corridors[i].max_upper, n.corridors[i].max_upper));
  }
  EXPECT_EQ(a.provenance.git_revision, b.provenance.git_revision);
  EXPECT_EQ(a.provenance.machine, b.provenance.machine);
  EXPECT_EQ(a.provenance.compiler, b.provenance.compiler);
  EXPECT_EQ(a.provenance.flags, b.provenance.flags);
  EXPECT_EQ(a.provenance.date, b.provenance.date);
  if (!with_steps) {
    EXPECT_TRUE(b.steps.empty());
    return;
  }
  ExpectSameProperties(a.properties, b.properties);
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    const StepRecord& s = a.steps[k];
    const StepRecord& t = b.steps[k];
    SCOPED_TRACE("step " + std::to_string(s.step));
    EXPECT_EQ(s.step, t.step);
    EXPECT_EQ(s.status, t.status);
    EXPECT_EQ(s.contained, t.contained);
    EXPECT_TRUE(Same("area", s.area, t.area));
    EXPECT_TRUE(Same("centre_error", s.centre_error, t.centre_error));
    EXPECT_TRUE(Same("solve_time_s", s.solve_time_s, t.solve_time_s));
    EXPECT_EQ(s.estimate, t.estimate);
    ExpectSameProperties(s.properties, t.properties);
    ASSERT_EQ(s.vars.size(), t.vars.size());
    for (std::size_t v = 0; v < s.vars.size(); ++v) {
      EXPECT_EQ(s.vars[v].name, t.vars[v].name);
      EXPECT_TRUE(Same("lo", s.vars[v].lo, t.vars[v].lo));
      EXPECT_TRUE(Same("hi", s.vars[v].hi, t.vars[v].hi));
      EXPECT_TRUE(Same("truth", s.vars[v].truth, t.vars[v].truth));
    }
  }
}

// One value of a query on the raw file, as text ("<null>" for NULL).
inline std::string RawQuery(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  std::string out = "<error>";
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr) == SQLITE_OK &&
      sqlite3_step(stmt) == SQLITE_ROW) {
    const unsigned char* text = sqlite3_column_text(stmt, 0);
    out = text == nullptr ? "<null>" : reinterpret_cast<const char*>(text);
  } else {
    ADD_FAILURE() << sql << ": " << sqlite3_errmsg(db);
  }
  sqlite3_finalize(stmt);
  sqlite3_close(db);
  return out;
}

// Writes a store as schema version 1 wrote it (no estimate kind, no
// properties): one run 'hc4{}|chain{}|seed=1' of one step.
inline void WriteVersionOneStore(const std::string& path) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  const char* v1 = R"sql(
CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT);
INSERT INTO meta VALUES ('schema_version', '1'), ('conventions', 'old'), ('writer', 'icpbench');
CREATE TABLE runs (id INTEGER PRIMARY KEY, key TEXT UNIQUE NOT NULL, spec_file TEXT,
  algorithm TEXT, algorithm_params TEXT, problem TEXT, problem_params TEXT, seed INTEGER,
  timeout_s REAL, status TEXT, reason TEXT, wall_time_s REAL, steps INTEGER, mean_area REAL,
  consistency_rate REAL, centre_rmse REAL, time_mean_s REAL, time_median_s REAL,
  time_p90_s REAL, time_mean_ci_lo_s REAL, time_mean_ci_hi_s REAL, corridors TEXT,
  git_revision TEXT, machine TEXT, compiler TEXT, flags TEXT, date TEXT);
CREATE TABLE steps (run_id INTEGER NOT NULL REFERENCES runs(id), step INTEGER NOT NULL,
  status TEXT, contained INTEGER, area REAL, centre_error REAL, solve_time_s REAL,
  PRIMARY KEY (run_id, step)) WITHOUT ROWID;
CREATE TABLE step_values (run_id INTEGER NOT NULL, step INTEGER NOT NULL, pos INTEGER NOT NULL,
  var TEXT NOT NULL, lo REAL, hi REAL, truth REAL, PRIMARY KEY (run_id, step, pos),
  UNIQUE (run_id, step, var), FOREIGN KEY (run_id, step) REFERENCES steps(run_id, step))
  WITHOUT ROWID;
INSERT INTO runs (id, key, algorithm, algorithm_params, problem, problem_params, seed, status,
  steps) VALUES (1, 'hc4{}|chain{}|seed=1', 'hc4', '{}', 'chain', '{}', 1, 'ok', 1);
INSERT INTO steps VALUES (1, 0, 'contracted', 1, 2.5, 0.1, 1e-5);
INSERT INTO step_values VALUES (1, 0, 0, 'x', -1, 1, 0);
)sql";
  ASSERT_EQ(sqlite3_exec(db, v1, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_close(db);
}

// Bytes of a file ("" when missing).
inline std::string FileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A fresh directory holding no store.
inline std::string FreshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/icpbench_store_dir_" + name;
  std::error_code ec;  // a read-only leftover of an earlier run is made removable
  std::filesystem::permissions(dir, std::filesystem::perms::owner_all,
                               std::filesystem::perm_options::add, ec);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace icp::testing

#endif  // ICPBENCH_HARNESS_RESULTS_STORE_TESTING_H_
