#include "harness/runner.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "algorithms/fault/fault.h"
#include "algorithms/registry.h"
#include "harness/metrics.h"
#include "harness/results_store.h"

namespace icp {
namespace {

std::string FreshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "runner_" + name;
  std::filesystem::remove_all(dir);
  return dir;
}

// The peak resident memory of this process, KiB, after resetting it to the
// current one (/proc/self/clear_refs, Linux >= 4.0); -1 where unsupported.
long PeakMemoryKiB() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}
long ResetPeakMemoryKiB() {
  std::ofstream("/proc/self/clear_refs") << "5";
  return PeakMemoryKiB();
}

std::vector<std::string> StepFilesIn(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(".steps-", 0) == 0) files.push_back(name);
  }
  return files;
}

SweepSummary Sweep(const std::string& yaml, const std::string& dir, int jobs = 2,
                   bool force = false, bool no_retry = false) {
  Spec spec = ParseSpec(yaml, "test.yaml");
  RunnerOptions options;
  options.out_dir = dir;
  options.jobs = jobs;
  options.force = force;
  options.no_retry = no_retry;
  options.kill_grace_s = 0.5;
  std::ostringstream progress;
  return RunSweep(spec, options, progress, false);
}

TEST(RunnerTest, ExecuteRunRecordsEveryStepAndKeepsTheTruth) {
  RunRecord r = ExecuteRun(RunSpec{"hc4", {}, "chain", {{"w", "10"}}, 3, 0});
  ASSERT_EQ(r.status, RunStatus::kOk) << r.reason;
  ASSERT_EQ(r.steps.size(), 1u);
  const StepRecord& s = r.steps[0];
  ASSERT_EQ(s.vars.size(), 3u);  // the newest state: x, y, theta
  EXPECT_EQ(s.vars[0].name, "x");
  EXPECT_EQ(s.contained, 1);
  EXPECT_GT(s.area, 0);
  EXPECT_EQ(r.metrics.consistency_rate, 1.0);
  EXPECT_NEAR(s.area, (s.vars[0].hi - s.vars[0].lo) * (s.vars[1].hi - s.vars[1].lo), 1e-9);
}

TEST(RunnerTest, TheProblemsAnnotationsJoinTheStepProperties) {
  const RunRecord r = ExecuteRun(RunSpec{"hc4", {}, "car-track", {{"steps", "3"}}, 1, 0});
  ASSERT_EQ(r.status, RunStatus::kOk) << r.reason;
  ASSERT_EQ(r.steps.size(), 3u);
  for (const StepRecord& s : r.steps) {
    const auto lo = NumberProperty(s.properties, "gps_x_lo");
    const auto hi = NumberProperty(s.properties, "gps_x_hi");
    ASSERT_TRUE(lo && hi);
    EXPECT_LE(*lo, s.vars[0].truth);
    EXPECT_GE(*hi, s.vars[0].truth);
  }
}

// timeout_s stops a run whose steps are each far shorter than the limit
// (HC4, 50 ms a step, 0.3 s allowed): between steps, keeping the steps done.
TEST(RunnerTest, TheTimeLimitStopsARunBetweenShortSteps) {
  RunSpec spec{"fault", {{"mode", "slow"}, {"slow_ms", "50"}}, "car-track", {{"steps", "40"}}, 1, 0.3};
  const RunRecord r = ExecuteRun(spec);
  EXPECT_EQ(r.status, RunStatus::kTimeout) << r.reason;
  EXPECT_NE(r.reason.find("time limit of 0.3 s reached"), std::string::npos) << r.reason;
  EXPECT_GE(r.steps.size(), 5u);
  EXPECT_LT(r.steps.size(), 40u);
  EXPECT_EQ(static_cast<std::size_t>(r.metrics.steps), r.steps.size());
}

// A run whose last step ends past the limit did every step: it is ok, not
// a timeout (which `run` would redo every time).
TEST(RunnerTest, ARunWhoseLastStepEndsPastTheLimitIsComplete) {
  RunSpec spec{"fault", {{"mode", "slow"}, {"slow_ms", "150"}}, "car-track", {{"steps", "2"}}, 1, 0.2};
  const RunRecord r = ExecuteRun(spec);
  EXPECT_EQ(r.status, RunStatus::kOk) << r.reason;
  EXPECT_EQ(r.steps.size(), 2u);
}

TEST(RunnerTest, FaultsAreRecordedAndTheSweepGoesOn) {
  const std::string dir = FreshDir("faults");
  SweepSummary s = Sweep(R"(
timeout_s: 1
algorithms:
  - hc4
  - {name: fault, params: {mode: [segfault, abort, hang, throw, garbage]}}
problems: [chain]
)", dir);
  EXPECT_EQ(s.planned, 6);
  EXPECT_EQ(s.ok, 1);
  EXPECT_EQ(s.failed, 4);
  EXPECT_EQ(s.timed_out, 1);
  ResultsStore store(StorePath(dir));
  std::map<std::string, RunRecord> by_mode;
  for (RunRecord& r : store.LoadRuns(false))
    by_mode[r.spec.algorithm_params.count("mode") ? r.spec.algorithm_params.at("mode") : "hc4"] = r;
  EXPECT_EQ(by_mode["hc4"].status, RunStatus::kOk);
  EXPECT_NE(by_mode["segfault"].reason.find("signal 11"), std::string::npos) << by_mode["segfault"].reason;
  EXPECT_NE(by_mode["abort"].reason.find("signal 6"), std::string::npos) << by_mode["abort"].reason;
  EXPECT_EQ(by_mode["hang"].status, RunStatus::kTimeout);
  EXPECT_NE(by_mode["throw"].reason.find("injected fault"), std::string::npos);
  EXPECT_NE(by_mode["garbage"].reason.find("invalid result"), std::string::npos)
      << by_mode["garbage"].reason;
  EXPECT_FALSE(by_mode["hc4"].provenance.git_revision.empty());
  EXPECT_FALSE(by_mode["hc4"].provenance.date.empty());
}

// A worker that crashes, hangs and is killed, throws, exits or returns a
// broken box after some good steps: its run is recorded as failed or timed
// out with those steps and their metrics (they reached the step file one by
// one), not with none, and its reason says why and that they are kept.
TEST(RunnerTest, ARunThatDiesKeepsTheStepsItFinished) {
  const std::string dir = FreshDir("dies_mid_run");
  Sweep(R"(
timeout_s: 1
algorithms:
  - {name: fault, params: {mode: [segfault, hang, throw, exit, garbage, nan, paving-nan, particles-nan], after_calls: 3}}
problems: [{name: car-track, params: {steps: 10}}]
)", dir);
  ResultsStore store(StorePath(dir));
  std::map<std::string, RunRecord> by_mode;
  for (RunRecord& r : store.LoadRuns(true)) by_mode[r.spec.algorithm_params.at("mode")] = r;
  ASSERT_EQ(by_mode.size(), 8u);
  EXPECT_EQ(by_mode["segfault"].status, RunStatus::kFailed);
  EXPECT_EQ(by_mode["hang"].status, RunStatus::kTimeout);
  EXPECT_EQ(by_mode["throw"].reason.rfind("exception: injected fault;", 0), 0u) << by_mode["throw"].reason;
  EXPECT_EQ(by_mode["exit"].reason.rfind("worker exited with code 0 before sending its result;", 0), 0u)
      << by_mode["exit"].reason;
  EXPECT_NE(by_mode["garbage"].reason.find("is not inside its domain"), std::string::npos) << by_mode["garbage"].reason;
  // A NaN bound reads as an empty interval: it must not pass as an empty box.
  EXPECT_EQ(by_mode["nan"].reason.rfind("invalid result at step 3: x has a NaN bound;", 0), 0u)
      << by_mode["nan"].reason;
  // So must a NaN in one part of a paving or a cloud, which their hull skips.
  EXPECT_EQ(by_mode["paving-nan"].reason.rfind(
                "invalid result at step 3: the paving's boundary box 0: x has a NaN bound;", 0),
            0u)
      << by_mode["paving-nan"].reason;
  EXPECT_EQ(by_mode["particles-nan"].reason.rfind("invalid result at step 3: particle 1: x is NaN;", 0), 0u)
      << by_mode["particles-nan"].reason;
  for (const char* mode : {"throw", "exit", "garbage", "nan", "paving-nan", "particles-nan"}) EXPECT_EQ(by_mode[mode].status, RunStatus::kFailed) << mode;
  for (const auto& [mode, r] : by_mode) {
    EXPECT_EQ(r.metrics.steps, 3) << mode << ": " << r.reason;
    EXPECT_EQ(r.steps.size(), 3u) << mode;
    EXPECT_NE(r.reason.find("the 3 steps finished before are kept"), std::string::npos) << r.reason;
    EXPECT_GT(r.metrics.mean_area, 0) << mode;
  }
}

#if !defined(ICPBENCH_SANITIZED)
// A worker that allocates without bound stops at its memory limit
// (memory_limit_mb) with bad_alloc: its run fails as "out of memory", the
// others go on. (Sanitizer builds run without the limit.)
TEST(RunnerTest, AWorkerOverItsMemoryLimitFailsAlone) {
  const std::string dir = FreshDir("memory");
  SweepSummary s = Sweep(R"(
memory_limit_mb: 256
algorithms:
  - hc4
  - {name: fault, params: {mode: allocate}}
problems: [chain]
)", dir);
  EXPECT_EQ(s.ok, 1);
  EXPECT_EQ(s.failed, 1);
  ResultsStore store(StorePath(dir));
  for (const RunRecord& r : store.LoadRuns(false)) {
    if (r.spec.algorithm != "fault") continue;
    EXPECT_NE(r.reason.find("out of memory at step 0"), std::string::npos) << r.reason;
    EXPECT_NE(r.reason.find("memory_limit_mb = 256 MiB"), std::string::npos) << r.reason;
  }
}

// A size in range that needs more than the limit (accumulator cells =
// 20000: 1.5 GiB of counts) fails before it is allocated, with the
// documented reason, the size and the limit; OpenCV's "Insufficient
// memory" was recorded instead.
TEST(RunnerTest, AnAccumulatorOverTheMemoryLimitFailsWithItsSize) {
  const std::string dir = FreshDir("accumulator_memory");
  SweepSummary s = Sweep(R"(
memory_limit_mb: 256
algorithms:
  - {name: accumulator, params: {cells: 20000}}
problems: [line-intersection]
)", dir, 1);
  EXPECT_EQ(s.failed, 1);
  ResultsStore store(StorePath(dir));
  const std::vector<RunRecord> runs = store.LoadRuns(false);
  ASSERT_EQ(runs.size(), 1u);
  const std::string& reason = runs[0].reason;
  EXPECT_EQ(reason.rfind("out of memory at step 0: ", 0), 0u) << reason;
  EXPECT_NE(reason.find("20000 x 20000 cells"), std::string::npos) << reason;
  EXPECT_NE(reason.find("needs 1526 MiB"), std::string::npos) << reason;
  EXPECT_NE(reason.find("memory_limit_mb = 256 MiB"), std::string::npos) << reason;
}
#endif

#if defined(ICPBENCH_SANITIZED)
// Only in the sanitizer build (scripts/sanitize.sh): a report in a forked
// worker makes it exit with ASAN_OPTIONS' exitcode (86 there), and the harness
// must record that run as failed, not as a finished one.
class HeapOverflowEstimator : public Estimator {
 public:
  StepResult Step(const Views&, const StopCondition&) override {
    std::vector<int> v(4);
    volatile int* p = v.data();
    const int past_the_end = p[v.size()];  // heap-buffer-overflow: ASan reports it
    throw std::runtime_error("not reported: " + std::to_string(past_the_end));
  }
};
std::unique_ptr<Estimator> MakeHeapOverflow(const ParamMap&, std::uint64_t) {
  return std::make_unique<HeapOverflowEstimator>();
}

TEST(RunnerTest, ASanReportInAWorkerFailsItsRun) {
  RegisterAlgorithm({"asan-overflow", "a heap-buffer-overflow (sanitizer build only)",
                     &MakeHeapOverflow, &DefaultParams<FaultParams>, &ResolveParams<FaultParams>,
                     View::kCsp, {"asan-overflow", 900, "#7f7f7f"}, nullptr, true});
  const std::string dir = FreshDir("asan");
  SweepSummary s = Sweep("algorithms: [asan-overflow]\nproblems: [chain]\n", dir);
  EXPECT_EQ(s.failed, 1);
  EXPECT_EQ(s.ok, 0);
  std::vector<RunRecord> runs = ResultsStore(StorePath(dir)).LoadRuns(false);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].status, RunStatus::kFailed);
  EXPECT_NE(runs[0].reason.find("worker exited with code"), std::string::npos) << runs[0].reason;
}
#endif

TEST(RunnerTest, RerunSkipsStoredRunsAndForceRerunsThem) {
  const std::string dir = FreshDir("resume");
  const std::string yaml = "seeds: [1, 2, 3]\nalgorithms: [hc4, bc4]\nproblems: [chain]\n";
  SweepSummary first = Sweep(yaml, dir);
  EXPECT_EQ(first.ok, 6);
  SweepSummary second = Sweep(yaml, dir);
  EXPECT_EQ(second.already_stored, 6);
  EXPECT_EQ(second.ok, 0);
  SweepSummary forced = Sweep(yaml, dir, 2, true);
  EXPECT_EQ(forced.ok, 6);
  EXPECT_EQ(ResultsStore(StorePath(dir)).LoadRuns(false).size(), 6u);
}

// A rerun retries failed and timed-out runs (a transient kill must not be
// permanent) and keeps each earlier attempt; --no-retry keeps them as they
// are; timeout_s stays out of the key, so a raised limit retries the same run.
TEST(RunnerTest, RerunRetriesFailedAndTimedOutRunsUnlessNoRetry) {
  const std::string dir = FreshDir("retry");
  const std::string yaml = R"(
timeout_s: 1
algorithms:
  - hc4
  - {name: fault, params: {mode: [throw, hang]}}
problems: [chain]
)";
  SweepSummary first = Sweep(yaml, dir);
  EXPECT_EQ(first.ok, 1);
  EXPECT_EQ(first.failed, 1);
  EXPECT_EQ(first.timed_out, 1);
  SweepSummary kept = Sweep(yaml, dir, 2, false, /*no_retry=*/true);
  EXPECT_EQ(kept.already_stored, 3);
  EXPECT_EQ(ResultsStore(StorePath(dir)).Attempts().size(), 0u);
  SweepSummary retried = Sweep(yaml, dir);
  EXPECT_EQ(retried.planned, 3);
  EXPECT_EQ(retried.already_stored, 1);  // only the ok run is kept
  EXPECT_EQ(retried.failed, 1);
  EXPECT_EQ(retried.timed_out, 1);
  ResultsStore store(StorePath(dir));
  const std::vector<Attempt> attempts = store.Attempts();
  ASSERT_EQ(attempts.size(), 2u);  // the first failed and timeout runs
  for (const Attempt& a : attempts) {
    EXPECT_EQ(a.attempt, 1);
    EXPECT_NE(a.status, RunStatus::kOk);
    EXPECT_FALSE(a.reason.empty());
  }
  EXPECT_EQ(store.LoadRuns(false).size(), 3u);
}

TEST(RunnerTest, ShardsSplitTheMatrixWithoutOverlap) {
  const std::string yaml = "seeds: [1, 2, 3, 4, 5]\nalgorithms: [hc4]\nproblems: [chain]\n";
  Spec spec = ParseSpec(yaml, "test.yaml");
  int total = 0;
  for (int i = 0; i < 2; ++i) {
    RunnerOptions options;
    options.out_dir = FreshDir("shard" + std::to_string(i));
    options.shard_index = i;
    options.shard_count = 2;
    std::ostringstream progress;
    total += RunSweep(spec, options, progress, false).ok;
  }
  EXPECT_EQ(total, 5);
  const std::string merged_dir = FreshDir("merged");
  std::filesystem::create_directories(merged_dir);
  ResultsStore merged(StorePath(merged_dir));
  EXPECT_EQ(merged.MergeFrom(StorePath(::testing::TempDir() + "runner_shard0")) +
                merged.MergeFrom(StorePath(::testing::TempDir() + "runner_shard1")),
            5);
  EXPECT_EQ(ParseShard("1/3"), std::make_pair(1, 3));
  EXPECT_THROW(ParseShard("3/3"), std::invalid_argument);
  EXPECT_THROW(ParseShard("a/b"), std::invalid_argument);
}

// A shard's runs are the same after a rerun (--force), and are the ones
// ShardRuns names.
TEST(RunnerTest, AShardHoldsTheSameRunsAfterARerun) {
  const std::string yaml =
      "seeds: [1, 2, 3, 4, 5, 6, 7]\nalgorithms: [hc4, bc4]\nproblems: [chain]\n";
  const Spec spec = ParseSpec(yaml, "test.yaml");
  std::set<std::string> expected;
  for (std::size_t i : ShardRuns(spec, 1, 3)) expected.insert(spec.runs[i].spec.Key());
  ASSERT_EQ(expected.size(), 5u);  // runs 1, 4, 7, 10, 13 of 14
  const std::string dir = FreshDir("shard_rerun");
  for (bool force : {false, true}) {
    RunnerOptions options;
    options.out_dir = dir;
    options.shard_index = 1;
    options.shard_count = 3;
    options.force = force;
    std::ostringstream progress;
    EXPECT_EQ(RunSweep(ParseSpec(yaml, "test.yaml"), options, progress, false).ok, 5);
    const std::vector<std::string> keys = ResultsStore(StorePath(dir)).RunKeys();
    EXPECT_EQ(std::set<std::string>(keys.begin(), keys.end()), expected);
  }
}

// record: runs keeps the run rows (metrics, properties) and no step rows;
// the metrics equal those of record: steps, except the times.
TEST(RunnerTest, RecordRunsStoresNoStepsButTheSameMetrics) {
  const std::string body =
      "seeds: [1, 2]\nalgorithms: [hc4]\nproblems: [{name: car-track, params: {steps: 6, w: 3}}]\n";
  const std::string steps_dir = FreshDir("record_steps"), runs_dir = FreshDir("record_runs");
  EXPECT_EQ(Sweep(body, steps_dir).ok, 2);
  EXPECT_EQ(Sweep("record: runs\n" + body, runs_dir).ok, 2);
  EXPECT_TRUE(StepFilesIn(runs_dir).empty());
  // In the order of their keys: two workers may finish in either order.
  auto load = [](const std::string& dir) {
    std::vector<RunRecord> runs = ResultsStore(StorePath(dir)).LoadRuns(true);
    std::sort(runs.begin(), runs.end(),
              [](const RunRecord& a, const RunRecord& b) { return a.spec.Key() < b.spec.Key(); });
    return runs;
  };
  const std::vector<RunRecord> with = load(steps_dir);
  const std::vector<RunRecord> without = load(runs_dir);
  ASSERT_EQ(with.size(), 2u);
  ASSERT_EQ(without.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(with[i].spec.Key(), without[i].spec.Key());  // record is not part of the key
    EXPECT_EQ(with[i].steps.size(), 6u);
    EXPECT_TRUE(without[i].steps.empty());
    const RunMetrics &a = with[i].metrics, &b = without[i].metrics;
    EXPECT_EQ(a.steps, 6);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_EQ(a.mean_area, b.mean_area);
    EXPECT_EQ(a.consistency_rate, b.consistency_rate);
    EXPECT_EQ(a.centre_rmse, b.centre_rmse);
    ASSERT_EQ(a.corridors.size(), b.corridors.size());
    for (std::size_t k = 0; k < a.corridors.size(); ++k) {
      EXPECT_EQ(a.corridors[k].var, b.corridors[k].var);
      EXPECT_EQ(a.corridors[k].mean_lower, b.corridors[k].mean_lower);
      EXPECT_EQ(a.corridors[k].max_upper, b.corridors[k].max_upper);
    }
    ASSERT_EQ(with[i].properties.size(), without[i].properties.size());
    for (std::size_t k = 0; k < with[i].properties.size(); ++k)
      EXPECT_EQ(with[i].properties[k].name, without[i].properties[k].name);
  }
  // Per experiment, overriding the top level.
  const Spec spec = ParseSpec(
      "record: runs\nexperiments:\n  - {name: a, algorithms: [hc4], problems: [chain]}\n"
      "  - {name: b, record: steps, algorithms: [bc4], problems: [chain]}\n",
      "test.yaml");
  ASSERT_EQ(spec.runs.size(), 2u);
  EXPECT_FALSE(spec.runs[0].spec.record_steps);
  EXPECT_TRUE(spec.runs[1].spec.record_steps);
  EXPECT_TRUE(ParseSpec("algorithms: [hc4]\nproblems: [chain]\n", "t").runs[0].spec.record_steps);
  try {
    ParseSpec("algorithms: [hc4]\nproblems: [chain]\nrecord: all\n", "t.yaml");
    ADD_FAILURE() << "record: all was accepted";
  } catch (const SpecError& e) {
    EXPECT_EQ(std::string(e.what()), "t.yaml:3:9: key 'record': 'all' must be steps or runs");
  }
}

// A sweep killed with SIGKILL keeps every run it finished; running the spec
// again completes the matrix without redoing them.
TEST(RunnerTest, AKilledSweepLosesOnlyTheRunsInFlight) {
  const std::string dir = FreshDir("killed");
  const std::string yaml =
      "seeds: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16]\n"
      "algorithms: [bc4]\nproblems: [{name: car-track, params: {w: 20, steps: 300}}]\n";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    Sweep(yaml, dir, 2);
    _exit(0);
  }
  // Wait until some runs are stored, then kill the whole sweep.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  std::size_t stored = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (!std::filesystem::exists(StorePath(dir))) continue;
    try {
      stored = ResultsStore(StorePath(dir)).RunKeys().size();
    } catch (const StoreError&) {
      continue;
    }
    if (stored >= 3) break;
  }
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  ASSERT_GE(stored, 3u) << "the sweep did not store runs in time";
  std::vector<RunRecord> kept = ResultsStore(StorePath(dir)).LoadRuns(true);
  ASSERT_LT(kept.size(), 16u) << "the sweep finished before it was killed";
  for (const RunRecord& r : kept) {
    EXPECT_EQ(r.status, RunStatus::kOk);
    EXPECT_EQ(r.steps.size(), 300u);  // complete runs only
  }
  SweepSummary resumed = Sweep(yaml, dir, 2);
  EXPECT_EQ(resumed.already_stored, static_cast<int>(kept.size()));
  EXPECT_EQ(resumed.ok + resumed.already_stored, 16);
  EXPECT_TRUE(StepFilesIn(dir).empty());  // the killed workers' files are gone
}

// The parent (this process) streams a worker's steps into the store: its
// peak memory grows by far less than the run's steps take (they used to
// cross the pipe as one JSON text parsed whole: ~1.4 kB a step in the
// parent), and no step file is left behind.
TEST(RunnerTest, TheParentsMemoryDoesNotGrowWithTheRunsLength) {
#if defined(ICPBENCH_SANITIZED)
  GTEST_SKIP() << "ASan's quarantine keeps freed memory resident: peak memory means nothing here";
#endif
  const std::string dir = FreshDir("long_run");
  const int steps = 20000;
  const long before = ResetPeakMemoryKiB();
  if (before < 0) GTEST_SKIP() << "no /proc/self/status VmHWM here";
  const SweepSummary s = Sweep("algorithms: [hc4]\nproblems: [{name: car-track, params: {w: 1, steps: " +
                                   std::to_string(steps) + "}}]\n",
                               dir, 1);
  const long growth_kib = PeakMemoryKiB() - before;
  ASSERT_EQ(s.ok, 1);
  EXPECT_LT(growth_kib, 16 * 1024) << "the parent's peak memory grew by " << growth_kib << " KiB";
  EXPECT_TRUE(StepFilesIn(dir).empty());
  const std::vector<RunRecord> runs = ResultsStore(StorePath(dir)).LoadRuns(true);
  ASSERT_EQ(runs.size(), 1u);
  ASSERT_EQ(runs[0].steps.size(), static_cast<std::size_t>(steps));
  EXPECT_EQ(runs[0].metrics.steps, steps);
  // The worker's streamed metrics are those of the stored steps.
  const RunMetrics again = ComputeMetrics(runs[0].steps, runs[0].spec.seed);
  EXPECT_EQ(again.mean_area, runs[0].metrics.mean_area);
  EXPECT_EQ(again.time_median_s, runs[0].metrics.time_median_s);
  EXPECT_EQ(again.consistency_rate, runs[0].metrics.consistency_rate);
}

// A step file left by a killed sweep is removed by the next one on the
// directory; one a worker leaves unreadable fails its run, not the sweep.
TEST(RunnerTest, StaleStepFilesAreRemoved) {
  const std::string dir = FreshDir("stale_steps");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/.steps-1-1.ndjson") << "[1, \"half a line";
  const SweepSummary s = Sweep("algorithms: [hc4]\nproblems: [chain]\n", dir, 1);
  EXPECT_EQ(s.ok, 1);
  EXPECT_TRUE(StepFilesIn(dir).empty());
}

}  // namespace
}  // namespace icp
