#include "harness/results_store.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <utility>
#include <string>
#include <thread>
#include <vector>

#include "harness/environment_error.h"
#include "harness/metrics.h"

namespace icp {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// A fresh store path per test, with no file or WAL left from an earlier run.
std::string FreshPath(const std::string& name) {
  std::string path = ::testing::TempDir() + "/icpbench_store_" + name + ".sqlite";
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::remove((path + suffix).c_str());
  return path;
}

// A run with every field set, NaN and infinities included; the same i gives
// the same run.
RunRecord MakeRun(int i, int num_steps, const std::string& algorithm = "hc4",
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
  r.provenance = {"0123abc-dirty", "host1 / AMD EPYC", "GNU 12.2.0", "Release -O3", "2024-05-01T12:00:00Z"};
  return r;
}

// Doubles as the store must give them back: NaN for NaN, the same value
// (infinities included) otherwise.
::testing::AssertionResult Same(const char* what, double a, double b) {
  if ((std::isnan(a) && std::isnan(b)) || a == b) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": " << a << " != " << b;
}

void ExpectSameProperties(const Properties& a, const Properties& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    EXPECT_EQ(a[i].value.index(), b[i].value.index()) << a[i].name;
    if (a[i].value.index() == 1 && b[i].value.index() == 1)
      EXPECT_TRUE(Same(a[i].name.c_str(), std::get<double>(a[i].value), std::get<double>(b[i].value)));
    else
      EXPECT_EQ(a[i].value, b[i].value) << a[i].name;
  }
}

void ExpectSameRun(const RunRecord& a, const RunRecord& b, bool with_steps) {
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
std::string RawQuery(const std::string& path, const std::string& sql) {
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

TEST(RunSpecTest, KeyIsCanonical) {
  RunSpec spec;
  spec.algorithm = "hc4";
  spec.algorithm_params = {{"ratio", "0.01"}};
  spec.problem = "car-track";
  spec.problem_params = {{"w", "20"}, {"steps", "100"}};
  spec.seed = 3;
  spec.timeout_s = 10;
  EXPECT_EQ(spec.Key(), "hc4{ratio=0.01}|car-track{steps=100,w=20}|seed=3");
  RunSpec no_timeout = spec;
  no_timeout.timeout_s = 0;
  EXPECT_EQ(no_timeout.Key(), spec.Key());
  RunSpec bare;
  bare.algorithm = "3b";
  bare.problem = "chain";
  bare.seed = 18446744073709551615u;
  EXPECT_EQ(bare.Key(), "3b{}|chain{}|seed=18446744073709551615");
}

TEST(RunSpecTest, SpecialCharactersCannotMakeKeysCollide) {
  auto key = [](std::string algorithm, ParamMap params) {
    RunSpec spec;
    spec.algorithm = std::move(algorithm);
    spec.algorithm_params = std::move(params);
    spec.problem = "p";
    return spec.Key();
  };
  EXPECT_NE(key("a", {{"x", "1,y=2"}}), key("a", {{"x", "1"}, {"y", "2"}}));
  EXPECT_NE(key("a", {{"x=1", "2"}}), key("a", {{"x", "1=2"}}));
  EXPECT_NE(key("a{x=1}", {}), key("a", {{"x", "1"}}));
  EXPECT_NE(key("a", {{"x", "1}|p{"}}), key("a", {{"x", "1"}}));
  EXPECT_NE(key("a", {{"x", "\\,"}}), key("a", {{"x", "\\"}, {"", ""}}));
  EXPECT_EQ(key("a", {{"x", "1,2"}}), "a{x=1\\,2}|p{}|seed=0");
}

TEST(RunStatusTest, TextRoundTrip) {
  for (RunStatus s : {RunStatus::kOk, RunStatus::kFailed, RunStatus::kTimeout, RunStatus::kSkipped}) {
    EXPECT_EQ(ParseRunStatus(ToString(s)), s);
  }
  EXPECT_EQ(ToString(RunStatus::kOk), "ok");
  EXPECT_EQ(ToString(RunStatus::kFailed), "failed");
  EXPECT_EQ(ToString(RunStatus::kTimeout), "timeout");
  EXPECT_EQ(ToString(RunStatus::kSkipped), "skipped");
  EXPECT_THROW(ParseRunStatus("OK"), std::invalid_argument);
  EXPECT_THROW(ParseRunStatus(""), std::invalid_argument);
}

TEST(ResultsStoreTest, StorePath) { EXPECT_EQ(StorePath("out/table1"), "out/table1/results.sqlite"); }

TEST(ResultsStoreTest, RoundTripThroughTheFile) {
  const std::string path = FreshPath("round_trip");
  std::vector<RunRecord> runs = {MakeRun(0, 40), MakeRun(3, 25), MakeRun(1, 0)};
  runs[1].spec.seed = 18446744073709551557u;  // above 2^63
  runs[2].metrics = ComputeMetrics({});       // all NaN
  runs[2].status = RunStatus::kFailed;
  runs[2].reason = "hc4.ratio = -1: must be in [0, 1)";
  runs[2].spec.timeout_s = kInf;
  {
    ResultsStore store(path);
    for (const RunRecord& r : runs) store.Insert(r);
  }
  ResultsStore store(path);
  EXPECT_EQ(store.path(), path);
  std::vector<RunRecord> loaded = store.LoadRuns(/*with_steps=*/true);
  ASSERT_EQ(loaded.size(), runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) ExpectSameRun(runs[i], loaded[i], true);
  std::vector<RunRecord> heads = store.LoadRuns(/*with_steps=*/false);
  ASSERT_EQ(heads.size(), runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) ExpectSameRun(runs[i], heads[i], false);
}

TEST(ResultsStoreTest, FileIsSelfDescribingWithTypedColumns) {
  const std::string path = FreshPath("typed");
  {
    ResultsStore store(path);
    store.Insert(MakeRun(2, 10));
  }
  EXPECT_EQ(RawQuery(path, "SELECT value FROM meta WHERE key='schema_version'"), "3");
  EXPECT_EQ(RawQuery(path, "PRAGMA journal_mode"), "wal");
  EXPECT_EQ(RawQuery(path, "SELECT typeof(seed) || typeof(timeout_s) || typeof(wall_time_s) FROM runs"),
            "integerrealreal");
  EXPECT_EQ(RawQuery(path, "SELECT json_extract(algorithm_params, '$.ratio') FROM runs"), "0.01");
  EXPECT_EQ(RawQuery(path, "SELECT json_extract(corridors, '$[0].var') FROM runs"), "x");
  // Step 3 has an empty box: lo = +inf, hi = -inf as REAL; step 4 an unknown truth: NULLs.
  EXPECT_EQ(RawQuery(path, "SELECT lo > 1e308 AND hi < -1e308 AND typeof(lo) = 'real' "
                           "FROM step_values WHERE step = 3 AND var = 'x'"),
            "1");
  EXPECT_EQ(RawQuery(path, "SELECT typeof(truth) FROM step_values WHERE step = 4 AND var = 'y'"),
            "null");
  EXPECT_EQ(RawQuery(path, "SELECT typeof(contained) FROM steps WHERE step = 4"), "null");
  EXPECT_EQ(RawQuery(path, "SELECT count(*) FROM step_values"), "30");
  // Open properties keep their SQL type.
  EXPECT_EQ(RawQuery(path, "SELECT typeof(value) || type FROM step_properties WHERE step = 2 AND name = 'boxes'"),
            "integerint");
  EXPECT_EQ(RawQuery(path, "SELECT typeof(value) || type FROM step_properties WHERE step = 2 AND name = 'q'"),
            "realreal");
  EXPECT_EQ(RawQuery(path, "SELECT value FROM run_properties WHERE name = 'revise_calls'"),
            "1099511627776");
  EXPECT_EQ(RawQuery(path, "SELECT estimate FROM steps WHERE step = 1"), "paving");
}

// Writes a store as schema version 1 wrote it (no estimate kind, no
// properties): one run 'hc4{}|chain{}|seed=1' of one step.
void WriteVersionOneStore(const std::string& path) {
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

// A store written by schema version 1 (no estimate kind, no properties) is
// migrated when opened: its runs load, new runs with properties go in.
TEST(ResultsStoreTest, MigratesAVersionOneStore) {
  const std::string path = FreshPath("v1");
  WriteVersionOneStore(path);
  {
    ResultsStore store(path);
    const std::vector<RunRecord> runs = store.LoadRuns(true);
    ASSERT_EQ(runs.size(), 1u);
    ASSERT_EQ(runs[0].steps.size(), 1u);
    EXPECT_EQ(runs[0].steps[0].estimate, "box");
    EXPECT_TRUE(runs[0].steps[0].properties.empty());
    EXPECT_EQ(runs[0].steps[0].vars[0].hi, 1);
    store.Insert(MakeRun(1, 5));
    ASSERT_EQ(store.LoadRuns(true).size(), 2u);
    ExpectSameRun(MakeRun(1, 5), store.LoadRuns(true)[1], true);
    EXPECT_TRUE(store.Attempts().empty());
  }
  EXPECT_EQ(RawQuery(path, "SELECT value FROM meta WHERE key='schema_version'"), "3");
  EXPECT_EQ(RawQuery(path, "SELECT count(*) FROM attempts"), "0");
}

TEST(ResultsStoreTest, SameKeyReplacesTheRun) {
  const std::string path = FreshPath("replace");
  ResultsStore store(path);
  RunRecord first = MakeRun(1, 30);
  store.Insert(first);
  store.Insert(MakeRun(2, 5));
  RunRecord second = MakeRun(1, 30);
  second.steps.resize(4);
  second.metrics = ComputeMetrics(second.steps);
  second.status = RunStatus::kFailed;
  second.reason = "rerun with --force";
  second.provenance.git_revision = "fedcba9";
  ASSERT_EQ(first.spec.Key(), second.spec.Key());
  store.Insert(second);

  std::vector<RunRecord> loaded = store.LoadRuns(true);
  ASSERT_EQ(loaded.size(), 2u);
  ExpectSameRun(MakeRun(2, 5), loaded[0], true);
  ExpectSameRun(second, loaded[1], true);  // a replaced run counts as inserted last
  EXPECT_EQ(RawQuery(path, "SELECT count(*) FROM steps"), "9");
  EXPECT_EQ(RawQuery(path, "SELECT count(*) FROM step_values"), "27");
}

TEST(ResultsStoreTest, RunKeysAndHasRun) {
  const std::string path = FreshPath("keys");
  ResultsStore store(path);
  EXPECT_TRUE(store.RunKeys().empty());
  const RunRecord a = MakeRun(5, 3);
  const RunRecord b = MakeRun(2, 3, "bc4");
  EXPECT_FALSE(store.HasRun(a.spec.Key()));
  store.Insert(a);
  store.Insert(b);
  EXPECT_TRUE(store.HasRun(a.spec.Key()));
  EXPECT_TRUE(store.HasRun(b.spec.Key()));
  EXPECT_FALSE(store.HasRun(MakeRun(6, 3).spec.Key()));
  EXPECT_EQ(store.RunKeys(), (std::vector<std::string>{a.spec.Key(), b.spec.Key()}));
  // Another connection sees the committed runs.
  ResultsStore reader(path);
  EXPECT_TRUE(reader.HasRun(b.spec.Key()));
}

TEST(ResultsStoreTest, FailedInsertLeavesNothingBehind) {
  const std::string path = FreshPath("rollback");
  ResultsStore store(path);
  const RunRecord good = MakeRun(1, 10);
  store.Insert(good);
  RunRecord bad = MakeRun(1, 10);  // same key: would replace good
  bad.steps[7].step = 2;           // duplicate step number fails mid-insert
  EXPECT_THROW(store.Insert(bad), StoreError);
  std::vector<RunRecord> loaded = store.LoadRuns(true);
  ASSERT_EQ(loaded.size(), 1u);
  ExpectSameRun(good, loaded[0], true);
  store.Insert(MakeRun(2, 10));  // still usable after the rollback
  EXPECT_EQ(store.RunKeys().size(), 2u);
}

TEST(ResultsStoreTest, MergeFromCopiesOnlyAbsentRuns) {
  const std::string path_a = FreshPath("merge_a");
  const std::string path_b = FreshPath("merge_b");
  {
    ResultsStore b(path_b);
    for (int i : {2, 3, 4}) b.Insert(MakeRun(i, 6, "bc4"));
    RunRecord overlap = MakeRun(1, 6);
    overlap.reason = "from b";
    b.Insert(overlap);
  }
  ResultsStore a(path_a);
  for (int i : {0, 1}) a.Insert(MakeRun(i, 6));
  EXPECT_EQ(a.MergeFrom(path_b), 3);
  EXPECT_EQ(a.MergeFrom(path_b), 0);  // idempotent

  std::vector<RunRecord> loaded = a.LoadRuns(true);
  ASSERT_EQ(loaded.size(), 5u);
  ExpectSameRun(MakeRun(0, 6), loaded[0], true);
  ExpectSameRun(MakeRun(1, 6), loaded[1], true);  // a's copy kept
  for (int i : {2, 3, 4}) ExpectSameRun(MakeRun(i, 6, "bc4"), loaded[i], true);
  ResultsStore b(path_b);
  EXPECT_EQ(b.RunKeys().size(), 4u);  // the source is left as it was
}

TEST(ResultsStoreTest, MergeFromMissingStoreFailsAndCreatesNothing) {
  const std::string path = FreshPath("merge_missing");
  const std::string missing = FreshPath("does_not_exist");
  ResultsStore store(path);
  try {
    store.MergeFrom(missing);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(missing));
}

// Out of file descriptors when the store is opened: the environment (exit
// code 3 in the CLI), not bad input. Run in a child, whose limit is lowered
// to the descriptors it already has.
TEST(ResultsStoreTest, NoDescriptorLeftToOpenIsTheEnvironment) {
#if defined(ICPBENCH_SANITIZED)
  // UBSan's vptr check tests memory with a pipe; without descriptors it
  // reports a virtual call on a valid object (e.what() here) as invalid.
  GTEST_SKIP() << "the sanitizers' runtime needs descriptors of its own";
#endif
  const std::string path = FreshPath("no_fd");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // Less one: the listing's own descriptor, closed once it is read.
    const auto open_now = std::distance(std::filesystem::directory_iterator("/proc/self/fd"),
                                        std::filesystem::directory_iterator{}) - 1;
    const rlimit limit{static_cast<rlim_t>(open_now), static_cast<rlim_t>(open_now)};
    setrlimit(RLIMIT_NOFILE, &limit);
    try {
      ResultsStore store(path);
    } catch (const EnvironmentError& e) {
      _exit(std::string(e.what()).find("ulimit -n") != std::string::npos ? 0 : 2);
    } catch (...) {
      _exit(3);
    }
    _exit(4);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "2: no advice, 3: another error, 4: opened";
}

TEST(ResultsStoreTest, BadPathsSayWhatAndWhere) {
  const std::string dir_missing = ::testing::TempDir() + "/icpbench_no_such_dir/sub/results.sqlite";
  try {
    ResultsStore store(dir_missing);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(dir_missing), std::string::npos) << what;
    EXPECT_NE(what.find("unable to open database file"), std::string::npos) << what;
    EXPECT_NE(what.find("does not exist"), std::string::npos) << what;
  }

  const std::string not_db = FreshPath("not_a_database");
  {
    std::ofstream out(not_db);
    for (int i = 0; i < 100; ++i) out << "this is a text file, not a database\n";
  }
  try {
    ResultsStore store(not_db);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(not_db), std::string::npos) << what;
    EXPECT_NE(what.find("file is not a database"), std::string::npos) << what;
  }

  const std::string foreign = FreshPath("foreign");
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(foreign.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "CREATE TABLE t(a)", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  try {
    ResultsStore store(foreign);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("not an icpbench results store"), std::string::npos)
        << e.what();
  }
}

TEST(ResultsStoreTest, RejectsAnotherSchemaVersion) {
  const std::string path = FreshPath("version");
  { ResultsStore store(path); }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "UPDATE meta SET value='99' WHERE key='schema_version'", nullptr,
                         nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  try {
    ResultsStore store(path);
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("schema version '99'"), std::string::npos) << e.what();
  }
}

// A sweep killed while writing loses only the run in flight: the child
// commits a few runs, signalling each, then starts a run far too large
// (800000 rows) to finish before the parent kills it with SIGKILL; had it
// finished, the store would hold one run too many.
TEST(ResultsStoreCrashTest, KilledWriterLeavesOnlyCompleteRuns) {
  const std::string path = FreshPath("crash");
  constexpr int kCommitted = 5;
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    close(fds[0]);
    try {
      ResultsStore store(path);
      for (int i = 0;; ++i) {
        const bool big = i >= kCommitted;
        RunRecord run = MakeRun(i, big ? 200000 : 2000, "hc4", /*with_metrics=*/!big);
        const char mark = big ? 'b' : 'r';
        if (big && write(fds[1], &mark, 1) != 1) _exit(3);
        store.Insert(run);
        if (!big && write(fds[1], &mark, 1) != 1) _exit(3);
      }
    } catch (...) {
      _exit(2);
    }
    _exit(0);
  }
  close(fds[1]);
  int committed = 0;
  bool big_started = false;
  char mark;
  while (!big_started && read(fds[0], &mark, 1) == 1) {
    if (mark == 'r') ++committed;
    if (mark == 'b') big_started = true;
  }
  close(fds[0]);
  // Let the big insert write for a while (pages spill to the WAL), then kill.
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  kill(pid, SIGKILL);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exited with " << WEXITSTATUS(status);
  ASSERT_EQ(WTERMSIG(status), SIGKILL);
  ASSERT_TRUE(big_started);
  ASSERT_EQ(committed, kCommitted);

  ResultsStore store(path);
  std::vector<RunRecord> loaded = store.LoadRuns(true);
  ASSERT_EQ(loaded.size(), static_cast<std::size_t>(kCommitted));
  for (int i = 0; i < kCommitted; ++i) {
    EXPECT_EQ(loaded[i].steps.size(), 2000u);
    ExpectSameRun(MakeRun(i, 2000), loaded[i], true);
  }
  EXPECT_EQ(RawQuery(path, "PRAGMA integrity_check"), "ok");
  store.Insert(MakeRun(kCommitted, 10));  // and the sweep can go on
  EXPECT_EQ(store.RunKeys().size(), static_cast<std::size_t>(kCommitted + 1));
}

// 20 runs x 2000 steps x 3 variables: loading reads each table once. The
// time is reported, not asserted (STYLE.md: no wall-clock thresholds).
TEST(ResultsStoreTest, LoadsALargeStore) {
  const std::string path = FreshPath("large");
  {
    ResultsStore store(path);
    for (int i = 0; i < 20; ++i) store.Insert(MakeRun(i, 2000));
  }
  ResultsStore store(path);
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  std::vector<RunRecord> loaded = store.LoadRuns(true);
  const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("load_seconds", std::to_string(seconds));
  std::printf("loaded 20 x 2000 x 3 in %.3f s (%.3f s CPU)\n", seconds, cpu_seconds);
  ASSERT_EQ(loaded.size(), 20u);
  for (int i = 0; i < 20; ++i) {
    ASSERT_EQ(loaded[i].steps.size(), 2000u);
    EXPECT_EQ(loaded[i].steps[1999].vars.size(), 3u);
    EXPECT_EQ(loaded[i].steps[1999].vars[2].name, "theta");
  }
  ExpectSameRun(MakeRun(19, 2000), loaded[19], true);
}


// A replaced run (retry, --force) leaves its summary in attempts, numbered
// per key in the order of replacement.
TEST(ResultsStoreTest, ReplacedRunsAreKeptAsAttempts) {
  const std::string path = FreshPath("attempts");
  ResultsStore store(path);
  RunRecord first = MakeRun(3, 4);  // i % 4 == 3: a timeout
  first.provenance.date = "2026-01-01T00:00:00Z";
  first.provenance.git_revision = "aaaa";
  ASSERT_EQ(first.status, RunStatus::kTimeout);
  store.Insert(first);
  EXPECT_TRUE(store.Attempts().empty());
  RunRecord second = first;
  second.status = RunStatus::kFailed;
  second.reason = "worker killed by signal 9";
  second.provenance.date = "2026-01-02T00:00:00Z";
  store.Insert(second);
  RunRecord third = first;
  third.status = RunStatus::kOk;
  third.reason = "";
  store.Insert(third);
  store.Insert(MakeRun(1, 4));  // another key: no attempt

  const std::vector<Attempt> attempts = store.Attempts();
  ASSERT_EQ(attempts.size(), 2u);
  EXPECT_EQ(attempts[0].run_key, first.spec.Key());
  EXPECT_EQ(attempts[0].attempt, 1);
  EXPECT_EQ(attempts[0].status, RunStatus::kTimeout);
  EXPECT_EQ(attempts[0].reason, first.reason);
  EXPECT_EQ(attempts[0].wall_time_s, first.wall_time_s);
  EXPECT_EQ(attempts[0].timeout_s, first.spec.timeout_s);
  EXPECT_EQ(attempts[0].steps, 4);
  EXPECT_EQ(attempts[0].date, "2026-01-01T00:00:00Z");
  EXPECT_EQ(attempts[0].git_revision, "aaaa");
  EXPECT_EQ(attempts[1].attempt, 2);
  EXPECT_EQ(attempts[1].status, RunStatus::kFailed);
  EXPECT_EQ(attempts[1].reason, "worker killed by signal 9");
  const std::vector<StoredRun> runs = store.StoredRuns();
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].key, first.spec.Key());
  EXPECT_EQ(runs[0].status, RunStatus::kOk);  // the newest attempt is the run
  EXPECT_EQ(RawQuery(path, "SELECT count(*) FROM attempts"), "2");
}

// A version-2 store (no attempts table) is migrated to version 3.
TEST(ResultsStoreTest, MigratesAVersionTwoStore) {
  const std::string path = FreshPath("v2");
  {
    ResultsStore store(path);
    store.Insert(MakeRun(3, 4));
  }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db,
                         "DROP TABLE attempts; UPDATE meta SET value='2' WHERE key='schema_version'",
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  {
    ResultsStore store(path);
    EXPECT_EQ(store.schema_version(), 3);
    RunRecord retry = MakeRun(3, 4);
    retry.status = RunStatus::kOk;
    store.Insert(retry);
    ASSERT_EQ(store.Attempts().size(), 1u);
    EXPECT_EQ(store.Attempts()[0].status, RunStatus::kTimeout);
  }
  EXPECT_EQ(RawQuery(path, "SELECT value FROM meta WHERE key='schema_version'"), "3");
}

// MergeFrom prefers an ok copy over a timeout one, whichever store has it.
TEST(ResultsStoreTest, MergeFromPrefersOkOverTimeout) {
  const std::string path_a = FreshPath("merge_pref_a");
  const std::string path_b = FreshPath("merge_pref_b");
  RunRecord ok = MakeRun(3, 4);
  ok.status = RunStatus::kOk;
  ok.reason = "";
  const RunRecord timeout = MakeRun(3, 4);
  { ResultsStore(path_b).Insert(ok); }
  ResultsStore a(path_a);
  a.Insert(timeout);
  EXPECT_EQ(a.MergeFrom(path_b), 1);
  ASSERT_EQ(a.StoredRuns().size(), 1u);
  EXPECT_EQ(a.StoredRuns()[0].status, RunStatus::kOk);
  ASSERT_EQ(a.Attempts().size(), 1u);
  EXPECT_EQ(a.Attempts()[0].status, RunStatus::kTimeout);
}

// Bytes of a file ("" when missing).
std::string FileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A fresh directory holding no store.
std::string FreshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/icpbench_store_dir_" + name;
  std::error_code ec;  // a read-only leftover of an earlier run is made removable
  std::filesystem::permissions(dir, std::filesystem::perms::owner_all,
                               std::filesystem::perm_options::add, ec);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(MergeStoresTest, PrefersOkAndSaysWhatItDidAboutConflicts) {
  const std::string a = FreshDir("merge_a");
  const std::string b = FreshDir("merge_b");
  const std::string out = FreshDir("merge_out");
  std::filesystem::remove_all(out);  // OUT need not exist
  RunRecord ok3 = MakeRun(3, 4);     // MakeRun(3) is a timeout; this its ok copy
  ok3.status = RunStatus::kOk;
  ok3.reason = "";
  RunRecord ok7 = MakeRun(7, 4);
  ok7.status = RunStatus::kOk;
  ok7.reason = "";
  {
    ResultsStore sa(StorePath(a));
    sa.Insert(MakeRun(3, 4));  // timeout first: a keep-first merge would keep it
    sa.Insert(ok7);
    sa.Insert(MakeRun(1, 4));
  }
  {
    ResultsStore sb(StorePath(b));
    sb.Insert(ok3);
    sb.Insert(MakeRun(7, 4));  // a timeout that must not replace a's ok
    RunRecord later1 = MakeRun(1, 4);  // equal status, another measurement: a's kept
    later1.provenance.date = "2026-02-02T00:00:00Z";
    sb.Insert(later1);
    sb.Insert(MakeRun(2, 4));
    sb.Insert(MakeRun(5, 4));
  }
  {
    ResultsStore sa(StorePath(a));
    sa.Insert(MakeRun(5, 4));  // the very same run in both: no conflict, no attempt
  }
  const MergeSummary m = MergeStores(out, {a, b});
  EXPECT_EQ(m.runs, 5);
  EXPECT_EQ(m.from_input, (std::vector<int>{3, 2}));
  EXPECT_EQ(m.duplicates, 3);
  EXPECT_EQ(m.equal_kept_first, 1);
  EXPECT_EQ(m.ConflictMessage(),
            "merge: 3 conflicting keys: kept ok over timeout for 2, kept the first of "
            "equal-status copies for 1 (dropped copies are in table attempts)");

  std::map<std::string, RunStatus> status;
  {
    std::unique_ptr<ResultsStore> merged = ResultsStore::OpenReadOnly(StorePath(out));
    for (const StoredRun& r : merged->StoredRuns()) status[r.key] = r.status;
    EXPECT_EQ(merged->Attempts().size(), 3u);  // every dropped copy
    for (const RunRecord& r : merged->LoadRuns(true)) {
      if (r.spec.Key() == ok3.spec.Key()) ExpectSameRun(ok3, r, true);
    }
  }
  EXPECT_EQ(status.size(), 5u);
  EXPECT_EQ(status[ok3.spec.Key()], RunStatus::kOk);
  EXPECT_EQ(status[ok7.spec.Key()], RunStatus::kOk);
  // One complete file: no WAL, no temporary left in OUT.
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(out))
    names.push_back(e.path().filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"results.sqlite"}));

  // Merging again into the existing OUT keeps it as the first input.
  const MergeSummary again = MergeStores(out, {b});
  EXPECT_EQ(again.runs, 5);
  EXPECT_EQ(again.from_input, (std::vector<int>{0}));
  EXPECT_EQ(again.duplicates, 2);  // b's timeout 7 and later 1 differ from OUT's copies
  std::unique_ptr<ResultsStore> merged = ResultsStore::OpenReadOnly(StorePath(out));
  EXPECT_EQ(merged->Attempts().size(), 3u);  // and are in its attempts already: not added
}

TEST(MergeStoresTest, AMissingOrBadInputLeavesOutAsItWas) {
  const std::string a = FreshDir("merge_in_a");
  const std::string missing = FreshDir("merge_in_missing");
  const std::string empty = FreshDir("merge_in_empty");
  const std::string out = FreshDir("merge_out2");
  { ResultsStore(StorePath(a)).Insert(MakeRun(1, 4)); }
  std::ofstream(StorePath(empty)).close();  // zero bytes
  // No OUT store yet: a failed merge creates none.
  EXPECT_THROW(MergeStores(out, {a, missing}), StoreError);
  EXPECT_FALSE(std::filesystem::exists(StorePath(out)));
  EXPECT_THROW(MergeStores(out, {a, empty}), StoreError);
  EXPECT_FALSE(std::filesystem::exists(StorePath(out)));
  EXPECT_EQ(std::filesystem::file_size(StorePath(empty)), 0u);  // not made a store
  const std::string out_missing_dir = ::testing::TempDir() + "/icpbench_store_dir_merge_nodir";
  std::filesystem::remove_all(out_missing_dir);
  EXPECT_THROW(MergeStores(out_missing_dir, {missing}), StoreError);
  EXPECT_FALSE(std::filesystem::exists(out_missing_dir));
  // An OUT store stays byte for byte as it was.
  MergeStores(out, {a});
  const std::string before = FileBytes(StorePath(out));
  ASSERT_FALSE(before.empty());
  try {
    MergeStores(out, {a, missing});
    FAIL() << "expected StoreError";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find(StorePath(missing)), std::string::npos) << e.what();
  }
  EXPECT_EQ(FileBytes(StorePath(out)), before);
}

// A read-only open writes nothing: not the file, no -wal/-shm (tests may
// run as root, where permissions do not stop writes, so the bytes and the
// directory listing are checked too).
TEST(ResultsStoreReadOnlyTest, ReadsAReadOnlyStoreWithoutWritingIt) {
  namespace fs = std::filesystem;
  const std::string dir = FreshDir("readonly");
  const std::string path = StorePath(dir);
  {
    ResultsStore store(path);
    store.Insert(MakeRun(1, 6));
    store.Insert(MakeRun(2, 6, "bc4"));
  }
  ASSERT_FALSE(fs::exists(path + "-wal"));
  const std::string before = FileBytes(path);
  fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                           fs::perms::group_exec);
  {
    std::unique_ptr<ResultsStore> store = ResultsStore::OpenReadOnly(path);
    EXPECT_EQ(store->schema_version(), 3);
    const std::vector<RunRecord> runs = store->LoadRuns(true);
    ASSERT_EQ(runs.size(), 2u);
    ExpectSameRun(MakeRun(2, 6, "bc4"), runs[1], true);
    EXPECT_THROW(store->Insert(MakeRun(3, 6)), StoreError);
  }
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"results.sqlite"}));
  EXPECT_EQ(FileBytes(path), before);
  fs::permissions(dir, fs::perms::owner_all);
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
}

// While a writer has the store open (a -wal exists) a reader sees its
// committed runs.
TEST(ResultsStoreReadOnlyTest, SeesTheRunsOfAnOpenWriter) {
  const std::string path = FreshPath("readonly_live");
  ResultsStore writer(path);
  writer.Insert(MakeRun(1, 3));
  ASSERT_TRUE(std::filesystem::exists(path + "-wal"));
  EXPECT_EQ(ResultsStore::OpenReadOnly(path)->LoadRuns(false).size(), 1u);
  writer.Insert(MakeRun(2, 3));
  EXPECT_EQ(ResultsStore::OpenReadOnly(path)->LoadRuns(false).size(), 2u);
}

// Old versions are read as they are, not migrated.
TEST(ResultsStoreReadOnlyTest, ReadsAVersionOneStoreWithoutMigratingIt) {
  const std::string path = FreshPath("readonly_v1");
  WriteVersionOneStore(path);
  const std::string before = FileBytes(path);
  {
    std::unique_ptr<ResultsStore> store = ResultsStore::OpenReadOnly(path);
    EXPECT_EQ(store->schema_version(), 1);
    const std::vector<RunRecord> runs = store->LoadRuns(true);
    ASSERT_EQ(runs.size(), 1u);
    ASSERT_EQ(runs[0].steps.size(), 1u);
    EXPECT_EQ(runs[0].steps[0].estimate, "box");
    EXPECT_TRUE(store->Attempts().empty());
  }
  EXPECT_EQ(FileBytes(path), before);
}

TEST(ResultsStoreReadOnlyTest, AMissingEmptyOrForeignFileIsAnError) {
  const std::string missing = FreshPath("readonly_missing");
  const std::string empty = FreshPath("readonly_empty");
  std::ofstream(empty).close();
  for (const auto& [path, what] : {std::pair{missing, "no such file"},
                                   std::pair{empty, "empty file (0 bytes)"}}) {
    try {
      ResultsStore::OpenReadOnly(path);
      FAIL() << "expected StoreError for " << path;
    } catch (const StoreError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(std::filesystem::exists(missing));
  EXPECT_EQ(std::filesystem::file_size(empty), 0u);
  const std::string foreign = FreshPath("readonly_foreign");
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(foreign.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "CREATE TABLE t(a)", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  EXPECT_THROW(ResultsStore::OpenReadOnly(foreign), StoreError);
}

}  // namespace
}  // namespace icp
