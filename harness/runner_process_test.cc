// The runner's process handling (issue 13): workers die with their parent,
// SIGINT/SIGTERM stop a sweep cleanly, a lock per output directory, no
// overflow on an infinite timeout, bounds on the matrix and --jobs, and the
// environment's failures as exit code 3.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "harness/mpi_sweep.h"
#include "harness/results_store.h"
#include "harness/runner.h"
#include "tests/cli_helpers.h"
#include "tests/process_helpers.h"

namespace icp {
namespace {

using Clock = std::chrono::steady_clock;
using testing::Alive;
using testing::WaitFor;

std::string FreshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "runner_process_" + name;
  std::filesystem::remove_all(dir);
  return dir;
}

std::string Command(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/comm");
  std::string name;
  std::getline(in, name);
  return name;
}

// The sweep's workers: its children that run this test binary. A child the
// sweep forks to run a command (popen, for the git revision) runs this
// binary too until it execs, so a child counts only if it still does 100 ms
// later (without this, a loaded machine let the tests take such a child for
// a worker).
std::vector<pid_t> LiveChildrenOf(pid_t parent) {
  const std::string program = Command(parent);
  auto is_worker = [&](pid_t pid) { return Command(pid) == program; };
  const std::vector<pid_t> first = testing::LiveChildren(parent, is_worker);
  if (first.empty()) return first;
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const std::vector<pid_t> later = testing::LiveChildren(parent, is_worker);
  std::vector<pid_t> workers;
  for (pid_t pid : first)
    if (std::find(later.begin(), later.end(), pid) != later.end()) workers.push_back(pid);
  return workers;
}

// Forks a process that runs the sweep of yaml into dir and writes
// "interrupted_by stopped finished" to the returned pipe when it returns.
pid_t StartSweep(const std::string& yaml, const std::string& dir, int jobs, double grace,
                 int* result_fd) {
  int fds[2];
  if (pipe(fds) != 0) return -1;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    std::ostringstream progress;
    std::string line = "error";
    try {
      RunnerOptions options;
      options.out_dir = dir;
      options.jobs = jobs;
      options.kill_grace_s = grace;
      const SweepSummary s = RunSweep(ParseSpec(yaml, "test.yaml"), options, progress, false);
      line = std::to_string(s.interrupted_by) + " " + std::to_string(s.stopped) + " " +
             std::to_string(s.Finished());
    } catch (const std::exception& e) {
      line = std::string("error ") + e.what();
    }
    if (write(fds[1], line.data(), line.size()) < 0) _exit(2);
    _exit(0);
  }
  close(fds[1]);
  *result_fd = fds[0];
  return pid;
}

std::string ReadAll(int fd) {
  std::string out;
  char buf[512];
  ssize_t n;
  while ((n = read(fd, buf, sizeof buf)) > 0) out.append(buf, static_cast<std::size_t>(n));
  close(fd);
  return out;
}

constexpr const char* kTwoHangs = R"(
timeout_s: 60
seeds: [1, 2]
algorithms:
  - {name: fault, params: {mode: hang}}
problems: [chain]
)";

TEST(RunnerProcessTest, WorkersDieWithAParentKilledBySigkill) {
  int result_fd = -1;
  const pid_t sweep = StartSweep(kTwoHangs, FreshDir("sigkill"), 2, 2, &result_fd);
  ASSERT_GT(sweep, 0);
  std::vector<pid_t> workers;
  ASSERT_TRUE(WaitFor([&] { return (workers = LiveChildrenOf(sweep)).size() == 2; }, 5));
  kill(sweep, SIGKILL);
  waitpid(sweep, nullptr, 0);
  close(result_fd);
  for (pid_t w : workers) {
    EXPECT_TRUE(WaitFor([&] { return !Alive(w); }, 2)) << "worker " << w << " outlived its parent";
    if (Alive(w)) kill(w, SIGKILL);
  }
}

TEST(RunnerProcessTest, AWorkerEnforcesItsOwnLimitWhenItsParentCannot) {
  // A stopped parent cannot kill its hung worker (its kill is due at 0.5 +
  // 0.5 s); the worker's own limit (one second after that) ends it.
  int result_fd = -1;
  const pid_t sweep = StartSweep(R"(
timeout_s: 0.5
algorithms:
  - {name: fault, params: {mode: hang}}
problems: [chain]
)",
                                 FreshDir("hard_limit"), 1, 0.5, &result_fd);
  ASSERT_GT(sweep, 0);
  std::vector<pid_t> workers;
  ASSERT_TRUE(WaitFor([&] { return (workers = LiveChildrenOf(sweep)).size() == 1; }, 5));
  kill(sweep, SIGSTOP);
  const auto t0 = Clock::now();
  EXPECT_TRUE(WaitFor([&] { return !Alive(workers[0]); }, 4))
      << "worker still running while its parent is stopped";
  EXPECT_GT(std::chrono::duration<double>(Clock::now() - t0).count(), 0.3);
  kill(sweep, SIGKILL);
  waitpid(sweep, nullptr, 0);
  close(result_fd);
  if (Alive(workers[0])) kill(workers[0], SIGKILL);
}

TEST(RunnerProcessTest, SigtermStopsTheWorkersAndKeepsFinishedRuns) {
  const std::string dir = FreshDir("sigterm");
  int result_fd = -1;
  const pid_t sweep = StartSweep(R"(
timeout_s: 60
experiments:
  - {name: quick, algorithms: [hc4], problems: [chain]}
  - {name: hung, algorithms: [{name: fault, params: {mode: hang}}], problems: [chain], seeds: [1, 2]}
)",
                                 dir, 3, 2, &result_fd);
  ASSERT_GT(sweep, 0);
  std::vector<pid_t> workers;
  // The quick run has finished when only the two hung workers are left.
  ASSERT_TRUE(WaitFor([&] { return (workers = LiveChildrenOf(sweep)).size() == 2; }, 5));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  workers = LiveChildrenOf(sweep);
  ASSERT_EQ(workers.size(), 2u);
  const auto t0 = Clock::now();
  kill(sweep, SIGTERM);
  const std::string result = ReadAll(result_fd);
  int status = 0;
  waitpid(sweep, &status, 0);
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - t0).count(), 2);
  EXPECT_EQ(result, std::to_string(SIGTERM) + " 2 1");
  for (pid_t w : workers) EXPECT_FALSE(Alive(w));
  ResultsStore store(StorePath(dir));
  const std::vector<RunRecord> runs = store.LoadRuns(false);
  ASSERT_EQ(runs.size(), 1u);  // the hung runs are not recorded as failed
  EXPECT_EQ(runs[0].status, RunStatus::kOk);
  EXPECT_FALSE(std::filesystem::exists(dir + "/.lock") &&
               std::filesystem::file_size(dir + "/.lock") > 0)
      << "the lock file still names a holder";
}

// A worker that finished while its parent could not read it (stopped by
// Ctrl-Z, or busy storing another run) has finished: a stop that comes
// then keeps its run instead of counting it as in flight.
TEST(RunnerProcessTest, ARunThatFinishedBeforeTheStopIsKept) {
  const std::string dir = FreshDir("finished_before_stop");
  int result_fd = -1;
  const pid_t sweep = StartSweep(R"(
seeds: [1, 2]
algorithms: [{name: fault, params: {mode: slow, slow_ms: 100}}]
problems: [{name: car-track, params: {steps: 5}}]
)",
                                 dir, 2, 2, &result_fd);
  ASSERT_GT(sweep, 0);
  std::vector<pid_t> workers;
  ASSERT_TRUE(WaitFor([&] { return (workers = LiveChildrenOf(sweep)).size() == 2; }, 5));
  kill(sweep, SIGSTOP);
  // The workers are in process groups of their own: they finish meanwhile.
  ASSERT_TRUE(WaitFor([&] { return !Alive(workers[0]) && !Alive(workers[1]); }, 10));
  kill(sweep, SIGTERM);
  kill(sweep, SIGCONT);
  const std::string result = ReadAll(result_fd);
  waitpid(sweep, nullptr, 0);
  EXPECT_EQ(result, std::to_string(SIGTERM) + " 0 2");
  ResultsStore store(StorePath(dir));
  const std::vector<RunRecord> runs = store.LoadRuns(false);
  ASSERT_EQ(runs.size(), 2u);
  for (const RunRecord& r : runs) EXPECT_EQ(r.status, RunStatus::kOk) << r.reason;
}

SweepSummary QuickSweep(const std::string& dir, std::string* progress_text = nullptr,
                        const std::string& timeout = "10") {
  RunnerOptions options;
  options.out_dir = dir;
  std::ostringstream progress;
  const SweepSummary s = RunSweep(
      ParseSpec("timeout_s: " + timeout + "\nalgorithms: [hc4]\nproblems: [chain]\n", "t.yaml"),
      options, progress, false);
  if (progress_text) *progress_text = progress.str();
  return s;
}

TEST(RunnerProcessTest, ASecondSweepOnALockedDirectoryNamesTheLockAndItsHolder) {
  const std::string dir = FreshDir("locked");
  std::filesystem::create_directories(dir);
  const int fd = open((dir + "/.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(flock(fd, LOCK_EX | LOCK_NB), 0);
  ASSERT_EQ(write(fd, "4242\n", 5), 5);
  try {
    QuickSweep(dir);
    ADD_FAILURE() << "no DirectoryLockedError";
  } catch (const DirectoryLockedError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "/.lock"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("PID 4242"), std::string::npos) << e.what();
  }
  close(fd);
  EXPECT_FALSE(std::filesystem::exists(StorePath(dir))) << "the locked sweep opened the store";
}

TEST(RunnerProcessTest, AStaleLockIsTakenOverWithAMessage) {
  const std::string dir = FreshDir("stale");
  std::filesystem::create_directories(dir);
  // A holder that died without emptying the file (SIGKILL): its flock went
  // with it, its PID stayed.
  const pid_t gone = fork();
  if (gone == 0) _exit(0);
  waitpid(gone, nullptr, 0);
  std::ofstream(dir + "/.lock") << gone << "\n";
  std::string progress;
  const SweepSummary s = QuickSweep(dir, &progress);
  EXPECT_EQ(s.ok, 1);
  EXPECT_NE(progress.find("took over stale lock of PID " + std::to_string(gone)), std::string::npos)
      << progress;
  // Released: the next sweep takes it without a message.
  QuickSweep(dir, &progress);
  EXPECT_EQ(progress.find("stale"), std::string::npos) << progress;
}

TEST(RunnerProcessTest, AnInfiniteOrHugeTimeoutMeansNoLimit) {
  for (const std::string t : {"inf", ".inf", "1e10", "1e300"}) {
    const Spec spec = ParseSpec("timeout_s: " + t + "\nalgorithms: [hc4]\nproblems: [chain]\n", "t");
    ASSERT_EQ(spec.runs.size(), 1u);
    RunRecord r = ExecuteRun(spec.runs[0].spec);
    EXPECT_EQ(r.status, RunStatus::kOk) << t << ": " << r.reason;
    const SweepSummary s = QuickSweep(FreshDir("inf"), nullptr, t);
    EXPECT_EQ(s.ok, 1) << t;
  }
  EXPECT_TRUE(std::isinf(ParseSpec("timeout_s: .inf\nalgorithms: [hc4]\nproblems: [chain]\n", "t")
                             .runs[0]
                             .spec.timeout_s));
}

// A line's value from a /proc file of pid ("Threads:" of status, "Max cpu
// time" of limits), the text after the key; "" when absent.
std::string ProcField(pid_t pid, const std::string& file, const std::string& key) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/" + file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key, 0) == 0) return line.substr(key.size());
  return "";
}

// Time limits are wall-clock whatever a run's threads: a run hung busy on
// more threads than cores (fault mode spin) uses CPU time faster than the
// clock. Its CPU-time limit, which counts every thread, must not come
// before its wall-clock limits (the parent's kill at timeout_s + the grace,
// its own alarm a second later) even were every core its own; and the run
// is stored as a timeout by those. (The limit is read, not raced: on a
// loaded machine the threads may not get the cores to reach it.)
TEST(RunnerProcessTest, AMultiThreadedRunIsStoppedByTheWallClock) {
  const std::string dir = FreshDir("spin");
  int result_fd = -1;
  const pid_t sweep = StartSweep(R"(
timeout_s: 1
algorithms:
  - {name: fault, params: {mode: spin}}
problems: [chain]
)",
                                 dir, 1, 3, &result_fd);  // killed at 4 s, alarm at 5 s
  ASSERT_GT(sweep, 0);
  std::vector<pid_t> workers;
  ASSERT_TRUE(WaitFor([&] { return (workers = LiveChildrenOf(sweep)).size() == 1; }, 5));
  // Spinning: past its set-up, limits set.
  EXPECT_TRUE(WaitFor(
      [&] { return std::atoi(ProcField(workers[0], "status", "Threads:").c_str()) > 1; }, 5));
  std::istringstream limit(ProcField(workers[0], "limits", "Max cpu time"));
  std::string soft;
  limit >> soft;
  if (soft != "unlimited") {
    EXPECT_GE(std::atof(soft.c_str()), 5.0 * std::thread::hardware_concurrency())
        << "a CPU-time limit of " << soft << " s comes before the wall-clock limit of 5 s on "
        << std::thread::hardware_concurrency() << " cores";
  }
  const std::string result = ReadAll(result_fd);
  waitpid(sweep, nullptr, 0);
  EXPECT_EQ(result, "0 0 1");  // not interrupted, one run finished
  ResultsStore store(StorePath(dir));
  const std::vector<RunRecord> runs = store.LoadRuns(false);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].status, RunStatus::kTimeout) << runs[0].reason;
  // The parent's kill, or (a parent starved past it) the worker's own alarm.
  EXPECT_TRUE(runs[0].reason.rfind("killed after 4 s", 0) == 0 ||
              runs[0].reason.find("wall-clock") != std::string::npos)
      << runs[0].reason;
  EXPECT_GE(runs[0].wall_time_s, 4) << runs[0].reason;
}

TEST(RunnerProcessTest, AMatrixAboveTheLimitIsRejectedBeforeItIsExpanded) {
  const auto t0 = Clock::now();
  try {
    ParseSpec(R"(
repetitions: 100000
algorithms:
  - {name: fault, params: {after_calls: [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10]}}
problems: [chain]
)",
              "big.yaml");
    ADD_FAILURE() << "accepted 1.1 million runs";
  } catch (const SpecError& e) {
    EXPECT_NE(std::string(e.what()).find("1100000 runs"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("limit of 1000000"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - t0).count(), 2);
}

// --- The command line --------------------------------------------------------

testing::Result Icpbench(const std::string& args) {
  return testing::RunCommand(ICPBENCH_BINARY, args);
}

// SIGHUP (the terminal closed) stops a sweep as Ctrl-C does.
TEST(RunnerProcessTest, CliSigintAndSighupStopTheSweepWithItsMessageAndCode) {
  for (const int signal : {SIGINT, SIGHUP}) {
    SCOPED_TRACE(signal);
    const std::string dir = FreshDir("cli_sigint");
    const std::string spec = testing::WriteFile("process_hang.yaml", kTwoHangs);
    const std::string log = ::testing::TempDir() + "process_sigint.log";
    const pid_t pid = fork();
    if (pid == 0) {
      const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(fd, STDERR_FILENO);
      execl(ICPBENCH_BINARY, ICPBENCH_BINARY, "run", spec.c_str(), "--out", dir.c_str(), "--jobs", "2",
            static_cast<char*>(nullptr));
      _exit(127);
    }
    std::vector<pid_t> workers;
    ASSERT_TRUE(WaitFor([&] { return (workers = LiveChildrenOf(pid)).size() == 2; }, 5));
    kill(pid, signal);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    std::ifstream in(log);
    const std::string out((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(out.find("icpbench: interrupted: 2 runs in flight were stopped, 0 finished runs kept"),
              std::string::npos)
        << out;
    for (pid_t w : workers) EXPECT_FALSE(Alive(w));
  }
}

TEST(RunnerProcessTest, CliJobsAreCappedAndMustBePositive) {
  const std::string spec =
      testing::WriteFile("process_quick.yaml", "algorithms: [hc4]\nproblems: [chain]\n");
  testing::Result r = Icpbench("run " + spec + " --out " + FreshDir("cli_jobs") + " --jobs 100000");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("--jobs 100000 capped to"), std::string::npos) << r.out;
  r = Icpbench("run " + spec + " --out " + FreshDir("cli_jobs0") + " --jobs 0");
  EXPECT_EQ(r.exit_code, 2) << r.out;
}

// --mpi outside mpirun (one rank) or in a build without MPI: a usage error
// that says what to do, and nothing is run.
TEST(RunnerProcessTest, CliMpiWithOneRankOrWithoutMpiIsAUsageError) {
  const std::string spec =
      testing::WriteFile("process_quick.yaml", "algorithms: [hc4]\nproblems: [chain]\n");
  const std::string dir = FreshDir("cli_mpi");
  const testing::Result r = Icpbench("run " + spec + " --mpi --out " + dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(MpiBuilt() ? "needs at least 2 ranks" : "built without MPI"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(StorePath(dir)));
}

// --rank-timeout is checked when the command line is read (no mpirun
// needed): a finite number of seconds in its range, and only with --mpi.
TEST(RunnerProcessTest, CliRankTimeoutOutsideItsRangeOrWithoutMpiIsAUsageError) {
  const std::string spec =
      testing::WriteFile("process_quick.yaml", "algorithms: [hc4]\nproblems: [chain]\n");
  const std::string dir = FreshDir("cli_rank_timeout");
  for (const std::string value : {"nan", "inf", "-inf", "0", "1", "-5", "86401", "1e300", "x"}) {
    const testing::Result r =
        Icpbench("run " + spec + " --mpi --rank-timeout " + value + " --out " + dir);
    EXPECT_EQ(r.exit_code, 2) << value << ": " << r.out;
    EXPECT_NE(r.out.find("--rank-timeout"), std::string::npos) << value << ": " << r.out;
    EXPECT_NE(r.out.find("[2, 86400]"), std::string::npos) << value << ": " << r.out;
    EXPECT_LT(r.out.size(), 300u) << value << ": " << r.out;  // no number in 300 digits
  }
  const testing::Result r = Icpbench("run " + spec + " --rank-timeout 60 --out " + dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("--rank-timeout requires --mpi"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(StorePath(dir)));
}

TEST(RunnerProcessTest, CliAnUnwritableOutputDirectoryIsTheEnvironment) {
  // /sys refuses new files even to root: a real permission error.
  const std::string spec =
      testing::WriteFile("process_quick.yaml", "algorithms: [hc4]\nproblems: [chain]\n");
  const testing::Result r = Icpbench("run " + spec + " --out /sys/kernel");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("permissions"), std::string::npos) << r.out;
}

#if !defined(ICPBENCH_SANITIZED)
// Out of memory is the environment (exit 3), not a bug: a million variables
// (about 500 MB) under a 300 MB address-space limit (ulimit -v; ASan builds
// cannot run under one). The program itself, with its shared libraries
// (OpenCV's image codecs among them), needs about 200 MB to start.
TEST(RunnerProcessTest, CliOutOfMemoryIsTheEnvironment) {
  const std::string file = testing::WriteFile(
      "million.bch", "Variables\n  x[1000000] in [0, 1];\nConstraints\n  x(1) = 0;\nend\n");
  const testing::Result small = testing::RunCommand(
      "ulimit -v 300000; " + std::string(ICPBENCH_BINARY), "solve " + file);
  EXPECT_EQ(small.exit_code, 3) << small.out;
  EXPECT_NE(small.out.find("out of memory"), std::string::npos) << small.out;
  EXPECT_EQ(small.out.find("internal error"), std::string::npos) << small.out;
  // The same under a roomy limit solves.
  const testing::Result roomy = testing::RunCommand(
      "ulimit -v 4000000; " + std::string(ICPBENCH_BINARY), "solve " + file);
  EXPECT_EQ(roomy.exit_code, 0) << roomy.out;
}
#endif

TEST(RunnerProcessTest, CliDescriptorExhaustionIsTheEnvironmentAndLeavesNoWorker) {
#if defined(ICPBENCH_SANITIZED)
  // UBSan's vptr check tests memory with a pipe; without descriptors it
  // reports every virtual call as on an invalid object.
  GTEST_SKIP() << "the sanitizers' runtime needs descriptors of its own";
#endif
  const std::string dir = FreshDir("cli_fds");
  const std::string spec = testing::WriteFile(
      "process_fds.yaml", "repetitions: 16\nalgorithms: [hc4]\nproblems: [chain]\n");
  const testing::Result r = testing::RunCommand(
      "ulimit -n 14 && " + std::string(ICPBENCH_BINARY), "run " + spec + " --out " + dir + " --jobs 8");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("ulimit -n"), std::string::npos) << r.out;
  // What was stored is true: every stored run is ok.
  if (std::filesystem::exists(StorePath(dir))) {
    ResultsStore store(StorePath(dir));
    for (const RunRecord& run : store.LoadRuns(false)) EXPECT_EQ(run.status, RunStatus::kOk) << run.reason;
  }
}

// A file-size limit (ulimit -f, set by some batch systems) stops a sweep as
// a full disk does: exit 3 with advice, the runs stored before kept; not
// SIGXFSZ's silent exit 153.
TEST(RunnerProcessTest, CliAFileSizeLimitIsTheEnvironment) {
  const std::string dir = FreshDir("cli_fsize");
  const std::string spec = testing::WriteFile(
      "process_fsize.yaml", "repetitions: 8\nalgorithms: [hc4]\nproblems: [{name: car-track, params: {steps: 400}}]\n");
  const testing::Result r = testing::RunCommand(
      "ulimit -f 1000 && " + std::string(ICPBENCH_BINARY), "run " + spec + " --out " + dir + " --jobs 1");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("ulimit -f"), std::string::npos) << r.out;
  ResultsStore store(StorePath(dir));
  const std::vector<RunRecord> runs = store.LoadRuns(false);
  EXPECT_GE(runs.size(), 1u);
  EXPECT_LT(runs.size(), 8u);
  for (const RunRecord& run : runs) EXPECT_EQ(run.status, RunStatus::kOk) << run.reason;
}

}  // namespace
}  // namespace icp
