// `mpirun -n N icpbench run SPEC --mpi` (issue 12): the same store as a
// local sweep, a killed worker rank costs only its runs in flight (handed to
// another rank), a killed rank 0 or a SIGTERM to mpirun leaves a store that
// a rerun completes, and bad input is exit code 2 on every rank. Runs the icpbench binary under
// mpirun --oversubscribe (3 ranks on any machine).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "harness/results_store.h"
#include "tests/cli_helpers.h"
#include "tests/process_helpers.h"

namespace icp {
namespace {

std::string FreshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "mpi_sweep_" + name;
  std::filesystem::remove_all(dir);
  return dir;
}

// mpirun with n ranks of icpbench and its arguments; as root (CI's
// containers) Open MPI wants to be told.
std::string MpiCommand(int n, const std::string& args, const std::string& mpirun_flags = "") {
  return std::string(ICPBENCH_MPIEXEC) + " --oversubscribe" + (geteuid() == 0 ? " --allow-run-as-root" : "") +
         " " + mpirun_flags + " -n " + std::to_string(n) + " " + ICPBENCH_BINARY + " " + args;
}

// Starts command in the background, output to log (emptied first); returns
// mpirun's PID.
pid_t Start(const std::string& command, const std::string& log) {
  std::ofstream{log};
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + command + " > " + log + " 2>&1").c_str(), nullptr);
    _exit(127);
  }
  return pid;
}

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The process of MPI rank `rank` among mpirun's children; -1 if none.
pid_t RankProcess(pid_t mpirun, int rank) {
  const std::string want = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
  const std::vector<pid_t> found = testing::LiveChildren(mpirun, [&](pid_t pid) {
    const std::string env = ReadFile("/proc/" + std::to_string(pid) + "/environ");
    std::size_t at = 0;
    for (std::size_t end; (end = env.find('\0', at)) != std::string::npos; at = end + 1)
      if (env.compare(at, end - at, want) == 0) return true;
    return false;
  });
  return found.empty() ? -1 : found[0];
}

// The exit code of pid within seconds, or nullopt (pid killed, with the
// ranks of its job) when it does not end by then.
std::optional<int> WaitExitWithin(pid_t pid, double seconds) {
  std::optional<int> code;
  testing::WaitFor(
      [&] {
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) != pid) return false;
        code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        return true;
      },
      seconds);
  if (!code) {
    for (int rank = 0; rank < 3; ++rank)
      if (const pid_t p = RankProcess(pid, rank); p > 0) kill(p, SIGKILL);
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
  }
  return code;
}

std::vector<RunRecord> RunsByKey(const std::string& dir, bool with_steps) {
  std::vector<RunRecord> runs = ResultsStore::OpenReadOnly(StorePath(dir))->LoadRuns(with_steps);
  std::sort(runs.begin(), runs.end(),
            [](const RunRecord& a, const RunRecord& b) { return a.spec.Key() < b.spec.Key(); });
  return runs;
}

bool Same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// Everything a run stores but its times.
void ExpectSameButTimes(const RunRecord& a, const RunRecord& b) {
  const std::string key = a.spec.Key();
  EXPECT_EQ(a.status, b.status) << key;
  EXPECT_EQ(a.reason, b.reason) << key;
  EXPECT_EQ(a.spec_file, b.spec_file) << key;
  const RunMetrics &m = a.metrics, &n = b.metrics;
  EXPECT_EQ(m.steps, n.steps) << key;
  EXPECT_TRUE(Same(m.mean_area, n.mean_area)) << key;
  EXPECT_TRUE(Same(m.consistency_rate, n.consistency_rate)) << key;
  EXPECT_TRUE(Same(m.centre_rmse, n.centre_rmse)) << key;
  ASSERT_EQ(m.corridors.size(), n.corridors.size()) << key;
  for (std::size_t k = 0; k < m.corridors.size(); ++k) {
    EXPECT_EQ(m.corridors[k].var, n.corridors[k].var) << key;
    EXPECT_TRUE(Same(m.corridors[k].mean_lower, n.corridors[k].mean_lower)) << key;
    EXPECT_TRUE(Same(m.corridors[k].max_upper, n.corridors[k].max_upper)) << key;
  }
  ASSERT_EQ(a.steps.size(), b.steps.size()) << key;
  for (std::size_t s = 0; s < a.steps.size(); ++s) {
    const StepRecord &x = a.steps[s], &y = b.steps[s];
    EXPECT_EQ(x.step, y.step) << key;
    EXPECT_EQ(x.status, y.status) << key;
    EXPECT_EQ(x.contained, y.contained) << key;
    EXPECT_TRUE(Same(x.area, y.area)) << key;
    ASSERT_EQ(x.vars.size(), y.vars.size()) << key;
    for (std::size_t v = 0; v < x.vars.size(); ++v) {
      EXPECT_EQ(x.vars[v].name, y.vars[v].name) << key;
      EXPECT_TRUE(Same(x.vars[v].lo, y.vars[v].lo) && Same(x.vars[v].hi, y.vars[v].hi)) << key;
    }
    ASSERT_EQ(x.properties.size(), y.properties.size()) << key;
    for (std::size_t p = 0; p < x.properties.size(); ++p) EXPECT_EQ(x.properties[p].name, y.properties[p].name);
  }
}

bool StepFilesLeft(const std::string& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename().string().starts_with(".steps-")) return true;
  return false;
}

// Runs the interrupted sweep's command again: it runs exactly the runs not
// kept, and every run ends stored once, ok.
void ExpectARerunRunsTheRest(const std::string& command, const std::string& dir, std::size_t kept) {
  const testing::Result rerun = testing::RunCommand(command, "");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.out;
  EXPECT_NE(rerun.out.find("6 planned, " + std::to_string(kept) + " already stored, " +
                           std::to_string(6 - kept) + " ok"),
            std::string::npos)
      << rerun.out;
  const std::vector<RunRecord> runs = RunsByKey(dir, false);
  ASSERT_EQ(runs.size(), 6u);
  for (const RunRecord& r : runs) EXPECT_EQ(r.status, RunStatus::kOk) << r.reason;
  EXPECT_FALSE(StepFilesLeft(dir));
}

// Six runs of about a second each (ten steps of 100 ms).
constexpr const char* kSlowRuns = R"(
algorithms: [{name: fault, params: {mode: slow, slow_ms: 100}}]
problems: [{name: car-track, params: {w: 1, steps: 10}}]
repetitions: 6
)";

TEST(MpiSweepTest, ThreeRanksStoreWhatALocalSweepWithTwoJobsStores) {
  // ok, crashed, thrown, invalid and skipped runs, with their steps.
  const std::string spec = testing::WriteFile("mpi_mixed.yaml", R"(
algorithms: [hc4, bc4, {name: fault, params: {mode: [segfault, throw, garbage], after_calls: 2}}, particle-filter]
problems: [chain, {name: car-track, params: {w: [1, 5], steps: 12}}]
seeds: [1, 2]
)");
  const std::string mpi_dir = FreshDir("same_mpi"), local_dir = FreshDir("same_local");
  const testing::Result mpi = testing::RunCommand(MpiCommand(3, "run " + spec + " --mpi --jobs 1 --out " + mpi_dir), "");
  ASSERT_EQ(mpi.exit_code, 0) << mpi.out;
  EXPECT_NE(mpi.out.find("to run on 2 worker ranks"), std::string::npos) << mpi.out;
  EXPECT_NE(mpi.out.find("rank 1 on "), std::string::npos) << mpi.out;  // its machine and jobs
  EXPECT_NE(mpi.out.find(": 1 runs at a time"), std::string::npos) << mpi.out;
  EXPECT_NE(mpi.out.find("rank 1)"), std::string::npos) << mpi.out;  // both ranks ran runs
  EXPECT_NE(mpi.out.find("rank 2)"), std::string::npos) << mpi.out;
  const testing::Result local =
      testing::RunCommand(ICPBENCH_BINARY, "run " + spec + " --jobs 2 --out " + local_dir);
  ASSERT_EQ(local.exit_code, 0) << local.out;
  const std::vector<RunRecord> a = RunsByKey(mpi_dir, true), b = RunsByKey(local_dir, true);
  ASSERT_EQ(a.size(), 36u);
  ASSERT_EQ(a.size(), b.size());
  int by_status[4] = {};
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].spec.Key(), b[i].spec.Key());
    ExpectSameButTimes(a[i], b[i]);
    EXPECT_FALSE(a[i].provenance.machine.empty());
    ++by_status[static_cast<int>(a[i].status)];
  }
  EXPECT_GT(by_status[static_cast<int>(RunStatus::kOk)], 0);
  EXPECT_GT(by_status[static_cast<int>(RunStatus::kFailed)], 0);
  EXPECT_GT(by_status[static_cast<int>(RunStatus::kSkipped)], 0);
  EXPECT_FALSE(StepFilesLeft(mpi_dir));
  // A rerun keeps the ok and skipped runs and retries the failed ones, as a
  // local sweep does.
  const int failed = by_status[static_cast<int>(RunStatus::kFailed)];
  const testing::Result again = testing::RunCommand(MpiCommand(3, "run " + spec + " --mpi --jobs 1 --out " + mpi_dir), "");
  EXPECT_EQ(again.exit_code, 0) << again.out;
  EXPECT_NE(again.out.find("36 planned, " + std::to_string(36 - failed) + " already stored, 0 ok, " +
                           std::to_string(failed) + " failed"),
            std::string::npos)
      << again.out;
}

TEST(MpiSweepTest, AKilledWorkerRanksRunInFlightGoesToAnotherRank) {
  const std::string spec = testing::WriteFile("mpi_slow.yaml", kSlowRuns);
  const std::string dir = FreshDir("killed_worker"), log = dir + ".log";
  // --enable-recovery: Open MPI keeps the job when a rank dies.
  const pid_t mpirun = Start(MpiCommand(3, "run " + spec + " --mpi --jobs 1 --rank-timeout 3 --out " + dir,
                                        "--enable-recovery"),
                             log);
  ASSERT_TRUE(testing::WaitFor([&] { return ReadFile(log).find("[1/6]") != std::string::npos; }, 20))
      << ReadFile(log);
  const pid_t rank1 = RankProcess(mpirun, 1);
  ASSERT_GT(rank1, 0);
  kill(rank1, SIGKILL);
  // Open MPI's recovery itself sometimes fails after the kill (a PMIx error,
  // then the surviving ranks wait in MPI forever; seen once in about twenty
  // runs): the dispatcher is then never told, which this test cannot judge.
  const std::optional<int> exited = WaitExitWithin(mpirun, 120);
  if (!exited && ReadFile(log).find("PMIX ERROR") != std::string::npos)
    GTEST_SKIP() << "Open MPI's recovery failed after the kill (PMIx error):\n" << ReadFile(log);
  ASSERT_TRUE(exited.has_value()) << "mpirun still running after 120 s:\n" << ReadFile(log);
  const int code = *exited;
  const std::string out = ReadFile(log);
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("rank 1 lost (nothing from it for 3 s): 1 of its 1 runs in flight go to other ranks"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("6 planned, 0 already stored, 6 ok, 0 failed"), std::string::npos) << out;
  // Every run exactly once: none replaced, none missing.
  const std::vector<RunRecord> runs = RunsByKey(dir, true);
  ASSERT_EQ(runs.size(), 6u);
  for (const RunRecord& r : runs) {
    EXPECT_EQ(r.status, RunStatus::kOk) << r.reason;
    EXPECT_EQ(r.steps.size(), 10u);
  }
  EXPECT_TRUE(ResultsStore::OpenReadOnly(StorePath(dir))->Attempts().empty());
  EXPECT_FALSE(StepFilesLeft(dir));
}

TEST(MpiSweepTest, AKilledRankZeroLeavesAStoreThatARerunCompletes) {
  const std::string spec = testing::WriteFile("mpi_slow.yaml", kSlowRuns);
  const std::string dir = FreshDir("killed_rank0"), log = dir + ".log";
  const std::string command = MpiCommand(3, "run " + spec + " --mpi --jobs 1 --out " + dir);
  const pid_t mpirun = Start(command, log);
  ASSERT_TRUE(testing::WaitFor([&] { return ReadFile(log).find("[2/6]") != std::string::npos; }, 20))
      << ReadFile(log);
  const pid_t rank0 = RankProcess(mpirun, 0);
  ASSERT_GT(rank0, 0);
  kill(rank0, SIGKILL);
  // Open MPI ends the job (or, as after SIGTERM below, its mpiexec is killed
  // when it hangs on its ranks).
  if (const std::optional<int> exited = WaitExitWithin(mpirun, 60)) {
    EXPECT_NE(*exited, 0);
  }
  const std::size_t kept = RunsByKey(dir, false).size();
  EXPECT_GE(kept, 2u);
  EXPECT_LT(kept, 6u);
  ExpectARerunRunsTheRest(command, dir, kept);
}

// With --enable-recovery (as examples/slurm/mpi.sbatch runs) Open MPI
// leaves the job to its ranks when rank 0 dies: a worker whose run finishes
// then cannot hand the result to anyone, and must still stop within
// --rank-timeout (a blocking send to the dead rank 0 once kept it forever).
TEST(MpiSweepTest, WorkersStopWhenRankZeroDiesUnderRecovery) {
  const std::string spec = testing::WriteFile("mpi_slow.yaml", kSlowRuns);
  const std::string dir = FreshDir("killed_rank0_recovery"), log = dir + ".log";
  const std::string command =
      MpiCommand(3, "run " + spec + " --mpi --jobs 1 --rank-timeout 2 --out " + dir, "--enable-recovery");
  const pid_t mpirun = Start(command, log);
  ASSERT_TRUE(testing::WaitFor([&] { return ReadFile(log).find("[1/6]") != std::string::npos; }, 20))
      << ReadFile(log);
  const pid_t rank0 = RankProcess(mpirun, 0);
  ASSERT_GT(rank0, 0);
  kill(rank0, SIGKILL);  // the runs in flight finish about a second later
  ASSERT_TRUE(WaitExitWithin(mpirun, 30).has_value()) << "the worker ranks did not stop\n" << ReadFile(log);
  const std::string out = ReadFile(log);
  EXPECT_NE(out.find("nothing from rank 0 for 2 s: stopping"), std::string::npos) << out;
  const std::size_t kept = RunsByKey(dir, false).size();
  ExpectARerunRunsTheRest(MpiCommand(3, "run " + spec + " --mpi --jobs 1 --out " + dir), dir, kept);
}

// Ctrl-C or scancel: mpirun passes SIGTERM on; rank 0 stops the runs in
// flight, keeps the finished ones and says so, and a rerun runs the rest.
TEST(MpiSweepTest, SigtermToMpirunKeepsTheFinishedRunsAndSaysSo) {
  const std::string spec = testing::WriteFile("mpi_slow.yaml", kSlowRuns);
  const std::string dir = FreshDir("sigterm"), log = dir + ".log";
  const std::string command = MpiCommand(3, "run " + spec + " --mpi --jobs 1 --out " + dir);
  const pid_t mpirun = Start(command, log);
  ASSERT_TRUE(testing::WaitFor([&] { return ReadFile(log).find("[1/6]") != std::string::npos; }, 20))
      << ReadFile(log);
  kill(mpirun, SIGTERM);
  // Open MPI's mpiexec now and then never reaps its ranks after passing
  // SIGTERM on (seen 2026-12-07: the ranks zombies, their output complete,
  // mpiexec asleep): it is killed then, and what the ranks wrote is checked.
  if (const std::optional<int> exited = WaitExitWithin(mpirun, 60)) {
    EXPECT_NE(*exited, 0);
  }
  const std::string out = ReadFile(log);
  EXPECT_NE(out.find("runs in flight were stopped"), std::string::npos) << out;
  const std::size_t kept = RunsByKey(dir, false).size();
  EXPECT_NE(out.find(std::to_string(kept) + " finished runs kept"), std::string::npos) << out;
  EXPECT_GE(kept, 1u);
  EXPECT_LT(kept, 6u);
  ExpectARerunRunsTheRest(command, dir, kept);
}

// A rank that SIGKILL or a crash ends leaves its step directory in the
// temporary directory; the next sweep's worker ranks remove those whose
// process is gone and leave one whose process lives.
TEST(MpiSweepTest, StepDirectoriesOfDeadRanksAreRemoved) {
  const pid_t dead = fork();
  if (dead == 0) _exit(0);
  waitpid(dead, nullptr, 0);
  const std::filesystem::path tmp = std::filesystem::temp_directory_path();
  const std::filesystem::path stale = tmp / ("icpbench-rank7-" + std::to_string(dead));
  const std::filesystem::path alive = tmp / ("icpbench-rank7-" + std::to_string(getpid()));
  std::filesystem::create_directories(stale);
  std::ofstream(stale / ".steps-1-2.ndjson") << "{}\n";
  std::filesystem::create_directories(alive);
  const std::string spec = testing::WriteFile("mpi_small.yaml", "algorithms: [hc4]\nproblems: [chain]\n");
  const std::string dir = FreshDir("stale_dirs");
  const testing::Result r = testing::RunCommand(MpiCommand(3, "run " + spec + " --mpi --out " + dir), "");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(alive));
  std::filesystem::remove_all(alive);
  std::filesystem::remove_all(stale);
}

TEST(MpiSweepTest, ABadSpecIsExitCodeTwoAndNamesTheError) {
  const std::string spec = testing::WriteFile("mpi_bad.yaml", "algorithms: [no-such]\nproblems: [chain]\n");
  const std::string dir = FreshDir("bad");
  const testing::Result r = testing::RunCommand(MpiCommand(3, "run " + spec + " --mpi --out " + dir), "");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("unknown algorithm 'no-such'"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(StorePath(dir)));
}

}  // namespace
}  // namespace icp
