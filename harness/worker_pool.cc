#include "harness/worker_pool.h"

#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <thread>
#include <utility>

#include "core/params.h"
#include "harness/fork_hooks.h"
#include "harness/runner.h"
#include "harness/worker_output.h"

namespace icp {

namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// Values beyond this (inf, 1e300) mean no limit: alarm() and the clocks
// overflow long before.
constexpr double kNoLimitAbove = 1e8;

bool WriteAll(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    ssize_t n = write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// The most threads of a worker that can run at once: every processor the
// system has (a run may widen the affinity mask it inherits).
unsigned MaxParallelism() {
  const long configured = sysconf(_SC_NPROCESSORS_CONF);
  return std::max({1u, std::thread::hardware_concurrency(),
                   configured > 0 ? static_cast<unsigned>(configured) : 1u});
}

// A worker's CPU-time limit for a wall-clock limit of wall_s: RLIMIT_CPU
// counts the time of every thread, which grows up to MaxParallelism() times
// as fast as the clock, so the limit is scaled by it and cannot fire before
// the wall-clock alarm, whatever the run's threads. It stays as a last
// backstop (it ends a busy worker that cancelled the alarm).
rlim_t CpuLimitSeconds(unsigned wall_s) {
  return static_cast<rlim_t>(wall_s) * MaxParallelism() + 1;
}

// In the forked worker: die with the parent whatever kills it (a parent that
// died before prctl is caught by the getppid check), keep the terminal's
// Ctrl-C for the parent (it stops the workers itself), and enforce a hard
// limit of its own in case the parent cannot kill it: an alarm at
// alarm_s, wall-clock, and the CPU-time limit cpu_s (see CpuLimitSeconds).
void SetUpWorker(pid_t parent, unsigned alarm_s, rlim_t cpu_s, double memory_limit_mb) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(4);
  setpgid(0, 0);
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  signal(SIGHUP, SIG_DFL);
  signal(SIGPIPE, SIG_DFL);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (alarm_s > 0) {
    alarm(alarm_s);
    rlimit cpu{cpu_s, cpu_s + 1};
    setrlimit(RLIMIT_CPU, &cpu);
  }
#if !defined(ICPBENCH_SANITIZED)
  // RLIMIT_DATA counts the private writable memory (heap, anonymous maps,
  // thread stacks), not the address space that malloc arenas and libraries
  // reserve, so many threads (TBB, OpenCV) do not use the limit up. (ASan maps
  // terabytes of shadow memory: its builds run without the limit.)
  if (memory_limit_mb > 0) {
    // Beyond what rlim_t holds (inf, 1e300 MiB) the cast would be undefined: no limit.
    const double wanted = memory_limit_mb * 1024 * 1024;
    const rlim_t bytes = wanted < 0x1p63 ? static_cast<rlim_t>(wanted) : RLIM_INFINITY;
    rlimit data{bytes, bytes};
    setrlimit(RLIMIT_DATA, &data);
  }
#else
  (void)memory_limit_mb;
#endif
}

// The forked worker: one run, its summary on the pipe, no cleanup.
[[noreturn]] void WorkOn(const RunSpec& spec, const std::string& step_file, int out_fd) {
  signal(SIGPIPE, SIG_IGN);
  RunRecord record;
  record.spec = spec;
  try {
    if (spec.record_steps) {
      StepFileWriter steps(step_file);
      record = ExecuteRun(spec, [&](const StepRecord& s) { steps.Write(s); });
      steps.Close();
    } else {  // record: runs: the metrics are accumulated all the same
      record = ExecuteRun(spec, [](const StepRecord&) {});
    }
  } catch (const std::exception& e) {  // the step file failed (a failed write is caught in ExecuteRun)
    record.status = RunStatus::kFailed;
    record.reason = e.what();
    record.metrics = RunMetrics{};
  }
  const bool ok = WriteAll(out_fd, SerializeSummary(record));
  _exit(ok ? 0 : 3);
}

}  // namespace

int UsableCpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

WorkerPool::WorkerPool(std::string step_dir, int jobs, double kill_grace_s, std::vector<int> close_in_workers)
    : step_dir_(std::move(step_dir)),
      jobs_(std::max(1, jobs)),
      kill_grace_s_(kill_grace_s),
      close_in_workers_(std::move(close_in_workers)) {}

WorkerPool::~WorkerPool() { Stop(); }

bool WorkerPool::Start(const PlannedRun& run) {
  const double kill_after_s = run.spec.timeout_s > 0 && run.spec.timeout_s < kNoLimitAbove
                                  ? run.spec.timeout_s + kill_grace_s_
                                  : 0;
  // The worker's own limit comes after the parent's kill, which is the
  // normal way a hung run ends. Computed before fork: the child only sets it.
  const double hard_limit_s = kill_after_s > 0 ? kill_after_s + 1 : 0;
  const unsigned alarm_s = hard_limit_s > 0 && hard_limit_s < kNoLimitAbove
                               ? static_cast<unsigned>(std::ceil(hard_limit_s))
                               : 0;
  const rlim_t cpu_limit_s = alarm_s > 0 ? CpuLimitSeconds(alarm_s) : RLIM_INFINITY;
  int fds[2];
  if (pipe(fds) != 0) {
    start_errno_ = errno;
    start_error_ = "cannot create a pipe for a worker";
    return false;
  }
  const std::string step_file = StepFilePath(step_dir_, std::to_string(++started_));
  std::fflush(nullptr);
  const pid_t parent = getpid();
  const ForkHooks& hooks = CurrentForkHooks();
  if (hooks.before) hooks.before();
  const pid_t pid = fork();
  if (pid != 0 && hooks.after_in_parent) hooks.after_in_parent();
  if (pid < 0) {
    start_errno_ = errno;
    start_error_ = "cannot start a worker process (fork)";
    close(fds[0]);
    close(fds[1]);
    return false;
  }
  if (pid == 0) {
    if (hooks.after_in_child) hooks.after_in_child();
    SetUpWorker(parent, alarm_s, cpu_limit_s, run.spec.memory_limit_mb);
    close(fds[0]);
    for (int fd : close_in_workers_) close(fd);
    for (const Worker& w : workers_) close(w.fd);
    WorkOn(run.spec, step_file, fds[1]);
  }
  close(fds[1]);
  Worker w;
  w.pid = pid;
  w.fd = fds[0];
  w.started = Clock::now();
  w.kill_after_s = kill_after_s;
  w.hard_limit_s = hard_limit_s;
  w.cpu_limit_s = alarm_s > 0 ? static_cast<double>(cpu_limit_s) : 0;
  w.run = run;
  w.step_file = step_file;
  workers_.push_back(std::move(w));
  return true;
}

void WorkerPool::Poll(int timeout_ms, const std::function<void(FinishedRun&)>& on_finished) {
  if (workers_.empty()) return;
  std::vector<pollfd> fds;
  for (const Worker& w : workers_) fds.push_back({w.fd, POLLIN, 0});
  poll(fds.data(), fds.size(), timeout_ms);
  for (std::size_t i = 0; i < workers_.size();) {
    Worker& w = workers_[i];
    bool eof = false;
    if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) eof = ReadSome(w);
    if (!eof && !w.killed && w.kill_after_s > 0 && Seconds(Clock::now() - w.started) > w.kill_after_s) {
      kill(w.pid, SIGKILL);
      w.killed = true;
    }
    if (!eof) {
      ++i;
      continue;
    }
    int status = 0;
    while (waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
    }
    fds.erase(fds.begin() + static_cast<std::ptrdiff_t>(i));
    Hand(i, status, on_finished);
  }
}

bool WorkerPool::ReadSome(Worker& w) {
  char buf[65536];
  const ssize_t n = read(w.fd, buf, sizeof buf);
  if (n > 0) {
    w.output.append(buf, static_cast<std::size_t>(n));
    return false;
  }
  return n == 0 || errno != EINTR;
}

void WorkerPool::CollectExited(const std::function<void(FinishedRun&)>& on_finished) {
  for (std::size_t i = 0; i < workers_.size();) {
    Worker& w = workers_[i];
    int status = 0;
    if (waitpid(w.pid, &status, WNOHANG) != w.pid) {
      ++i;
      continue;
    }
    // It has exited: its end of the pipe is closed, so this read ends.
    while (!ReadSome(w)) {
    }
    Hand(i, status, on_finished);
  }
}

void WorkerPool::Hand(std::size_t i, int wait_status, const std::function<void(FinishedRun&)>& on_finished) {
  Worker& w = workers_[i];
  close(w.fd);
  FinishedRun finished = Finish(w, wait_status);
  const std::string step_file = w.step_file;
  workers_.erase(workers_.begin() + static_cast<std::ptrdiff_t>(i));
  try {
    on_finished(finished);
  } catch (...) {
    unlink(step_file.c_str());
    throw;
  }
  unlink(step_file.c_str());
}

void WorkerPool::Stop() {
  for (Worker& w : workers_) kill(w.pid, SIGKILL);
  for (Worker& w : workers_) {
    close(w.fd);
    while (waitpid(w.pid, nullptr, 0) < 0 && errno == EINTR) {
    }
    unlink(w.step_file.c_str());
  }
  workers_.clear();
}

FinishedRun WorkerPool::Finish(Worker& w, int wait_status) {
  FinishedRun f;
  f.run = w.run;
  RunRecord& r = f.record;
  r.spec = w.run.spec;
  if (w.killed) {
    r.status = RunStatus::kTimeout;
    r.reason = "killed after " + FormatDouble(w.kill_after_s) + " s (timeout " +
               FormatDouble(w.run.spec.timeout_s) + " s)";
  } else if (WIFSIGNALED(wait_status) && WTERMSIG(wait_status) == SIGALRM) {
    r.status = RunStatus::kTimeout;
    r.reason = "stopped by its own wall-clock limit of " + FormatDouble(w.hard_limit_s) +
               " s (timeout " + FormatDouble(w.run.spec.timeout_s) + " s)";
  } else if (WIFSIGNALED(wait_status) && WTERMSIG(wait_status) == SIGXCPU) {
    r.status = RunStatus::kTimeout;
    r.reason = "stopped by its own CPU-time limit of " + FormatDouble(w.cpu_limit_s) +
               " s, all threads (timeout " + FormatDouble(w.run.spec.timeout_s) + " s)";
  } else if (WIFSIGNALED(wait_status)) {
    const int sig = WTERMSIG(wait_status);
    r.status = RunStatus::kFailed;
    r.reason = "crashed: signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
  } else if (!WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0) {
    r.status = RunStatus::kFailed;
    r.reason = "worker exited with code " + std::to_string(WEXITSTATUS(wait_status));
  } else if (w.output.empty()) {
    // exit(0) inside the run (a plugin's, or a library's it calls).
    r.status = RunStatus::kFailed;
    r.reason = "worker exited with code 0 before sending its result";
  } else {
    try {
      r = DeserializeSummary(w.output, w.run.spec);
      if (w.run.spec.record_steps) f.step_file = w.step_file;
    } catch (const std::exception& e) {
      r.status = RunStatus::kFailed;
      r.reason = UnreadableWorkerOutput(e.what());
    }
  }
  if (r.status != RunStatus::kOk && r.wall_time_s == 0) r.wall_time_s = Seconds(Clock::now() - w.started);
  // A worker that died mid-run (no summary came) wrote its steps as it went:
  // those finished are kept, with their metrics.
  if (f.step_file.empty() && r.metrics.steps == 0 && w.run.spec.record_steps) {
    r.metrics = RecoverStepFile(w.step_file, w.run.spec.seed);
    if (r.metrics.steps > 0) {
      f.step_file = w.step_file;
      r.reason += "; the " + std::to_string(r.metrics.steps) + " steps finished before are kept";
    }
  }
  return f;
}

}  // namespace icp
