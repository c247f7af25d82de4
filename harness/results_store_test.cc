// The results store's tests of keys, writing and reading back: round trips
// through the file, replaced runs and their attempts, rollback, a killed
// writer, a large store. Schema, merging and read-only opens have their own
// results_store_*_test.cc (one executable, results_store_test).
#include "harness/results_store.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

#include "harness/metrics.h"
#include "harness/results_store_testing.h"

namespace icp {
namespace {

using testing::ExpectSameRun;
using testing::FreshPath;
using testing::kInf;
using testing::MakeRun;
using testing::RawQuery;

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

}  // namespace
}  // namespace icp
