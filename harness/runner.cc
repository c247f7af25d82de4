#include "harness/runner.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <limits>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <type_traits>
#include <variant>

#include "algorithms/registry.h"
#include "harness/environment_error.h"
#include "harness/metrics.h"
#include "harness/provenance.h"
#include "harness/results_store.h"
#include "problems/registry.h"

namespace icp {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// --- One run -------------------------------------------------------------

}  // namespace

RunRecord ExecuteRun(const RunSpec& spec) {
  std::vector<StepRecord> steps;
  RunRecord record = ExecuteRun(spec, [&](const StepRecord& s) { steps.push_back(s); });
  record.steps = std::move(steps);
  return record;
}

RunRecord ExecuteRun(const RunSpec& spec, const StepSink& sink) {
  RunRecord record;
  MetricsAccumulator metrics;
  PostStateJudge post_states;
  record.spec = spec;
  const auto start = Clock::now();
  int step_index = 0;
  std::unique_ptr<Estimator> estimator;
  try {
    const AlgorithmInfo& algorithm = FindAlgorithm(spec.algorithm);
    std::unique_ptr<Problem> problem = FindProblem(spec.problem).make(spec.problem_params, spec.seed);
    estimator = algorithm.make(spec.algorithm_params, spec.seed);
    StopCondition stop = spec.timeout_s > 0
                             ? StopCondition::After(std::chrono::duration<double>(spec.timeout_s))
                             : StopCondition();
    Step step;
    while (problem->Next(&step)) {
      step_index = step.views.step;
      if (!step.views.Offers(algorithm.needs))
        throw std::invalid_argument("step " + std::to_string(step_index) + " offers no " +
                                    std::string(ToString(algorithm.needs)) + " view");
      const auto t0 = Clock::now();
      StepResult result = estimator->Step(step.views, stop);
      const double solve_time = Seconds(Clock::now() - t0);
      if (!result.estimate) throw InvalidResult("no estimate");
      if (std::string why = InvalidEstimateReason(step.views, *result.estimate); !why.empty())
        throw InvalidResult(why);
      StepRecord r = MeasureStep(step, *result.estimate);
      r.status = std::string(ToString(result.summary.status));
      r.solve_time_s = result.solve_time_s >= 0 ? result.solve_time_s : solve_time;
      post_states.Judge(step, &result.properties);
      for (Property& p : result.properties) r.properties.push_back(std::move(p));
      for (const Property& p : step.annotations) r.properties.push_back(p);
      for (Property& p : result.estimate->Extras()) r.properties.push_back(std::move(p));
      if (!result.summary.message.empty()) r.properties.push_back({"message", result.summary.message});
      sink(r);  // first: a step the sink could not take is not counted
      metrics.Add(r);
      if (result.summary.status == ContractStatus::kStopped && stop.ShouldStop()) {
        record.status = RunStatus::kTimeout;
        record.reason = "time limit of " + FormatDouble(spec.timeout_s) + " s reached at step " +
                        std::to_string(step_index);
        break;
      }
    }
  } catch (const InvalidResult& e) {
    record.status = RunStatus::kFailed;
    record.reason = "invalid result at step " + std::to_string(step_index) + ": " + e.what();
  } catch (const std::bad_alloc&) {
    record.status = RunStatus::kFailed;
    record.reason = "out of memory at step " + std::to_string(step_index) +
                    (spec.memory_limit_mb > 0
                         ? " (the worker's limit is memory_limit_mb = " +
                               FormatDouble(spec.memory_limit_mb) + " MiB: raise it in the spec)"
                         : "");
  } catch (const std::exception& e) {
    record.status = RunStatus::kFailed;
    record.reason = std::string("exception: ") + e.what();
  } catch (...) {
    record.status = RunStatus::kFailed;
    record.reason = "exception of unknown type";
  }
  if (estimator) record.properties = estimator->RunProperties();
  record.wall_time_s = Seconds(Clock::now() - start);
  record.metrics = metrics.Finish(spec.seed);
  return record;
}

namespace {

// --- Child-to-parent transport (JSON; NaN and infinities as strings) -----

nlohmann::json D(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}
double D(const nlohmann::json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "inf") return kInf;
  if (s == "-inf") return -kInf;
  return kNaN;
}

nlohmann::json PropertiesToJson(const Properties& properties) {
  nlohmann::json out = nlohmann::json::array();
  for (const Property& p : properties) {
    nlohmann::json value;
    std::visit([&](const auto& v) {
      if constexpr (std::is_same_v<std::decay_t<decltype(v)>, double>) value = D(v); else value = v;
    }, p.value);
    out.push_back({p.name, TypeName(p), value});
  }
  return out;
}

Properties PropertiesFromJson(const nlohmann::json& j) {
  Properties out;
  for (const auto& p : j) {
    const std::string type = p.at(1).get<std::string>();
    Property prop{p.at(0).get<std::string>(), std::int64_t{0}};
    if (type == "int") prop.value = p.at(2).get<std::int64_t>();
    else if (type == "real") prop.value = D(p.at(2));
    else prop.value = p.at(2).get<std::string>();
    out.push_back(std::move(prop));
  }
  return out;
}

nlohmann::json StepToJson(const StepRecord& s) {
  nlohmann::json vars = nlohmann::json::array();
  for (const VariableRecord& v : s.vars) vars.push_back({v.name, D(v.lo), D(v.hi), D(v.truth)});
  return {s.step, s.status, vars, s.contained, D(s.area), D(s.centre_error),
          D(s.solve_time_s), s.estimate, PropertiesToJson(s.properties)};
}

StepRecord StepFromJson(const nlohmann::json& s) {
  StepRecord sr;
  sr.step = s.at(0).get<int>();
  sr.status = s.at(1).get<std::string>();
  for (const auto& v : s.at(2)) sr.vars.push_back({v.at(0).get<std::string>(), D(v.at(1)), D(v.at(2)), D(v.at(3))});
  sr.contained = s.at(3).get<int>();
  sr.area = D(s.at(4));
  sr.centre_error = D(s.at(5));
  sr.solve_time_s = D(s.at(6));
  sr.estimate = s.at(7).get<std::string>();
  sr.properties = PropertiesFromJson(s.at(8));
  return sr;
}

nlohmann::json MetricsToJson(const RunMetrics& m) {
  nlohmann::json corridors = nlohmann::json::array();
  for (const Corridor& c : m.corridors)
    corridors.push_back({c.var, D(c.mean_lower), D(c.mean_upper), D(c.min_lower), D(c.max_upper)});
  return {m.steps, D(m.mean_area), D(m.consistency_rate), D(m.centre_rmse), D(m.time_mean_s),
          D(m.time_median_s), D(m.time_p90_s), D(m.time_mean_ci_lo_s), D(m.time_mean_ci_hi_s),
          corridors};
}

RunMetrics MetricsFromJson(const nlohmann::json& j) {
  RunMetrics m;
  m.steps = j.at(0).get<int>();
  double* fields[] = {&m.mean_area, &m.consistency_rate, &m.centre_rmse, &m.time_mean_s,
                      &m.time_median_s, &m.time_p90_s, &m.time_mean_ci_lo_s, &m.time_mean_ci_hi_s};
  for (std::size_t i = 0; i < std::size(fields); ++i) *fields[i] = D(j.at(i + 1));
  for (const auto& c : j.at(9))
    m.corridors.push_back({c.at(0).get<std::string>(), D(c.at(1)), D(c.at(2)), D(c.at(3)), D(c.at(4))});
  return m;
}

std::string Dump(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// The run without its steps (they went to the step file), for the pipe.
std::string SerializeSummary(const RunRecord& r) {
  return Dump({{"status", ToString(r.status)}, {"reason", r.reason},
               {"wall_time_s", D(r.wall_time_s)}, {"metrics", MetricsToJson(r.metrics)},
               {"properties", PropertiesToJson(r.properties)}});
}

RunRecord DeserializeSummary(const std::string& text, const RunSpec& spec) {
  const nlohmann::json j = nlohmann::json::parse(text);
  RunRecord r;
  r.spec = spec;
  r.status = ParseRunStatus(j.at("status").get<std::string>());
  r.reason = j.at("reason").get<std::string>();
  r.wall_time_s = D(j.at("wall_time_s"));
  r.metrics = MetricsFromJson(j.at("metrics"));
  r.properties = PropertiesFromJson(j.at("properties"));
  return r;
}

// Why a run failed whose worker's summary or step file cannot be read back.
std::string UnreadableWorkerOutput(const std::string& what) {
  return "invalid result: unreadable worker output (" + what + ")";
}

// A worker's step file that cannot be read back: the run failed, the sweep
// goes on.
class WorkerOutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The worker writes one JSON line per step to its step file as the run goes
// (so neither it nor the parent holds the steps); the parent reads them back
// one at a time into the store. Write errors throw (the run fails with the
// reason).
class StepFileWriter {
 public:
  explicit StepFileWriter(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "we")) {
    if (file_ == nullptr) Fail();
  }
  ~StepFileWriter() {
    if (file_ != nullptr) std::fclose(file_);
  }
  StepFileWriter(const StepFileWriter&) = delete;
  StepFileWriter& operator=(const StepFileWriter&) = delete;
  void Write(const StepRecord& s) {
    const std::string line = Dump(StepToJson(s)) + "\n";
    if (std::fwrite(line.data(), 1, line.size(), file_) != line.size()) Fail();
  }
  void Close() {
    std::FILE* f = file_;
    file_ = nullptr;
    if (std::fclose(f) != 0) Fail();
  }

 private:
  [[noreturn]] void Fail() const {
    throw std::runtime_error("cannot write the step file " + path_ + ": " + std::strerror(errno));
  }
  std::string path_;
  std::FILE* file_;
};

// Reads the steps back; expects exactly `count` of them.
StepSource ReadStepFile(const std::string& path, int count) {
  auto in = std::make_shared<std::ifstream>(path);
  if (!*in) throw WorkerOutputError("cannot open the step file " + path);
  return [in, path, count, read = 0](StepRecord* step) mutable {
    std::string line;
    if (!std::getline(*in, line)) {
      if (read != count)
        throw WorkerOutputError("the step file " + path + " holds " + std::to_string(read) +
                                " steps, the run " + std::to_string(count));
      return false;
    }
    try {
      *step = StepFromJson(nlohmann::json::parse(line));
    } catch (const std::exception& e) {
      throw WorkerOutputError("step file " + path + " line " + std::to_string(read + 1) + ": " + e.what());
    }
    ++read;
    return true;
  };
}

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

// --- The parent's bookkeeping ---------------------------------------------

struct Worker {
  pid_t pid = -1;
  int fd = -1;
  std::string output;
  Clock::time_point started;
  double kill_after_s = 0;  // 0: never
  double hard_limit_s = 0;  // the worker's own limit (alarm, CPU); 0: none
  bool killed = false;
  PlannedRun run;
  std::string step_file;  // where the worker writes its steps (removed when it is done)
};

class Progress {
 public:
  Progress(std::ostream& out, bool terminal, int total)
      : out_(out), terminal_(terminal), total_(total), start_(Clock::now()) {}

  void Done(const RunRecord& r, const SweepSummary& s) {
    ++done_;
    if (terminal_) {
      const int width = 30;
      const int filled = total_ ? width * done_ / total_ : width;
      out_ << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done_
           << "/" << total_ << " runs  ok " << s.ok << "  failed " << s.failed + s.timed_out
           << "  ETA " << Eta() << "   " << std::flush;
      if (r.status != RunStatus::kOk && r.status != RunStatus::kSkipped)
        out_ << "\n  " << ToString(r.status) << ": " << WithoutDefaults(r.spec).Key() << ": " << r.reason << "\n";
    } else {
      out_ << "[" << done_ << "/" << total_ << "] " << ToString(r.status) << " " << WithoutDefaults(r.spec).Key()
           << " (" << FormatSeconds(r.wall_time_s) << ")"
           << (r.reason.empty() ? "" : ": " + r.reason) << "\n" << std::flush;
    }
  }
  void Finish() {
    if (terminal_ && done_ > 0) out_ << "\n";
  }

 private:
  static std::string FormatSeconds(double s) {
    char buf[32];
    if (s < 60) {
      std::snprintf(buf, sizeof buf, "%.1fs", s);
    } else if (s < 3600) {
      std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
    } else {
      std::snprintf(buf, sizeof buf, "%dh%02dm", static_cast<int>(s) / 3600,
                    static_cast<int>(s) % 3600 / 60);
    }
    return buf;
  }
  std::string Eta() const {
    if (done_ == 0) return "?";
    const double elapsed = Seconds(Clock::now() - start_);
    return FormatSeconds(elapsed / done_ * (total_ - done_));
  }
  std::ostream& out_;
  bool terminal_;
  int total_;
  int done_ = 0;
  Clock::time_point start_;
};

// The finished worker's run without its steps; *steps_in_file tells whether
// the worker wrote them to w.step_file (a run it reported itself).
RunRecord Finalize(Worker& w, int wait_status, bool* steps_in_file) {
  *steps_in_file = false;
  RunRecord r;
  r.spec = w.run.spec;
  if (w.killed) {
    r.status = RunStatus::kTimeout;
    r.reason = "killed after " + FormatDouble(w.kill_after_s) + " s (timeout " +
               FormatDouble(w.run.spec.timeout_s) + " s)";
  } else if (WIFSIGNALED(wait_status) &&
             (WTERMSIG(wait_status) == SIGALRM || WTERMSIG(wait_status) == SIGXCPU)) {
    r.status = RunStatus::kTimeout;
    r.reason = "stopped by its own hard limit of " + FormatDouble(w.hard_limit_s) + " s (timeout " +
               FormatDouble(w.run.spec.timeout_s) + " s)";
  } else if (WIFSIGNALED(wait_status)) {
    const int sig = WTERMSIG(wait_status);
    r.status = RunStatus::kFailed;
    r.reason = "crashed: signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
  } else if (!WIFEXITED(wait_status) || WEXITSTATUS(wait_status) != 0) {
    r.status = RunStatus::kFailed;
    r.reason = "worker exited with code " + std::to_string(WEXITSTATUS(wait_status));
  } else {
    try {
      r = DeserializeSummary(w.output, w.run.spec);
      *steps_in_file = true;
    } catch (const std::exception& e) {
      r.status = RunStatus::kFailed;
      r.reason = UnreadableWorkerOutput(e.what());
    }
  }
  if (r.status != RunStatus::kOk && r.wall_time_s == 0) r.wall_time_s = Seconds(Clock::now() - w.started);
  return r;
}

// --- Signals, worker set-up, the directory lock ----------------------------

volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void OnStopSignal(int sig) { g_stop_signal = sig; }

// SIGINT/SIGTERM set g_stop_signal while a sweep runs; the previous handlers
// come back after it.
class StopSignals {
 public:
  StopSignals() {
    g_stop_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = OnStopSignal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
  }
  ~StopSignals() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

// Values beyond this (inf, 1e300) mean no limit: alarm() and the clocks
// overflow long before.
constexpr double kNoLimitAbove = 1e8;

// In the forked worker: die with the parent whatever kills it (a parent that
// died before prctl is caught by the getppid check), keep the terminal's
// Ctrl-C for the parent (it stops the workers itself), and enforce a hard
// limit of its own in case the parent cannot kill it.
void SetUpWorker(pid_t parent, double hard_limit_s, double memory_limit_mb) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(4);
  setpgid(0, 0);
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (hard_limit_s > 0 && hard_limit_s < kNoLimitAbove) {
    const auto s = static_cast<unsigned>(std::ceil(hard_limit_s));
    alarm(s);
    rlimit cpu{s, s + 1};
    setrlimit(RLIMIT_CPU, &cpu);
  }
#if !defined(ICPBENCH_SANITIZED)
  // RLIMIT_DATA counts the private writable memory (heap, anonymous maps,
  // thread stacks), not the address space that malloc arenas and libraries
  // reserve, so many threads (TBB, OpenCV) do not use the limit up. (ASan maps
  // terabytes of shadow memory: its builds run without the limit.)
  if (memory_limit_mb > 0) {
    const auto bytes = static_cast<rlim_t>(memory_limit_mb * 1024 * 1024);
    rlimit data{bytes, bytes};
    setrlimit(RLIMIT_DATA, &data);
  }
#else
  (void)memory_limit_mb;
#endif
}

// An exclusive flock on DIR/.lock holding the holder's PID; the kernel
// drops it when the holder dies, so a PID left in an unlocked file is stale.
// The file is emptied, not removed, on release (removing it would let a
// waiting process lock a deleted file).
class DirectoryLock {
 public:
  DirectoryLock(const std::string& dir, std::ostream& messages) {
    const std::string path = (std::filesystem::path(dir) / ".lock").string();
    fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) ThrowErrno("cannot create the lock file " + path, errno);
    const std::string holder = ReadPid();
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int e = errno;
      close(fd_);
      fd_ = -1;
      if (e != EWOULDBLOCK) ThrowErrno("cannot lock " + path, e);
      throw DirectoryLockedError("output directory " + dir + " is in use by another run: " + path +
                                 " is held by PID " + (holder.empty() ? "?" : holder));
    }
    if (!holder.empty() && holder != std::to_string(getpid()))
      messages << "icpbench: took over stale lock of PID " << holder << " (" << path << ")\n";
    const std::string pid = std::to_string(getpid()) + "\n";
    if (ftruncate(fd_, 0) != 0 || pwrite(fd_, pid.data(), pid.size(), 0) < 0)
      ThrowErrno("cannot write " + path, errno);
  }
  ~DirectoryLock() {
    if (fd_ < 0) return;
    if (ftruncate(fd_, 0) != 0) {
    }
    close(fd_);
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  int fd() const { return fd_; }

 private:
  std::string ReadPid() const {
    char buf[32] = {};
    const ssize_t n = pread(fd_, buf, sizeof buf - 1, 0);
    std::string s = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : "";
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
  }
  int fd_ = -1;
};

// Kills and reaps the workers still running when the sweep ends early
// (an exception, a signal), so none outlives it.
void StopWorkers(std::vector<Worker>& workers) {
  for (Worker& w : workers) kill(w.pid, SIGKILL);
  for (Worker& w : workers) {
    close(w.fd);
    while (waitpid(w.pid, nullptr, 0) < 0 && errno == EINTR) {
    }
    unlink(w.step_file.c_str());
  }
  workers.clear();
}

constexpr std::string_view kStepFilePrefix = ".steps-";
constexpr std::string_view kStepFileSuffix = ".ndjson";

// Step files left by a sweep that was killed before it could remove them
// (the directory lock says no other sweep writes here).
void RemoveStaleStepFiles(const std::string& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(kStepFilePrefix) && name.ends_with(kStepFileSuffix))
      std::filesystem::remove(entry.path(), ec);
  }
}

}  // namespace

SweepSummary RunSweep(const Spec& spec, const RunnerOptions& options, std::ostream& progress_out,
                      bool terminal) {
  {
    std::error_code ec;
    std::filesystem::create_directories(options.out_dir, ec);
    if (ec) ThrowErrno("cannot create the output directory " + options.out_dir, ec.value());
  }
  const DirectoryLock lock(options.out_dir, progress_out);
  RemoveStaleStepFiles(options.out_dir);
  ResultsStore store(StorePath(options.out_dir));
  SweepSummary summary;
  std::deque<PlannedRun> queue;
  // Kept: ok and skipped runs; failed and timed-out ones are retried (a
  // transient kill must not be permanent) unless no_retry.
  std::set<std::string> stored;
  for (const StoredRun& r : store.StoredRuns()) {
    const bool finished = r.status == RunStatus::kOk || r.status == RunStatus::kSkipped;
    if (finished || options.no_retry) stored.insert(r.key);
  }
  for (std::size_t i : ShardRuns(spec, options.shard_index, options.shard_count)) {
    ++summary.planned;
    if (!options.force && stored.count(spec.runs[i].spec.Key())) {
      ++summary.already_stored;
      continue;
    }
    queue.push_back(spec.runs[i]);
  }
  Progress progress(progress_out, terminal, static_cast<int>(queue.size()));
  // step_file: where the run's steps are (a worker's), else r.steps.
  auto store_record = [&](RunRecord r, const std::string& experiment, const std::string& step_file = "") {
    r.spec_file = spec.file + (experiment.empty() ? "" : "#" + experiment);
    r.provenance = CurrentProvenance();
    if (step_file.empty()) {
      store.Insert(r);
    } else {
      try {
        store.Insert(r, ReadStepFile(step_file, r.metrics.steps));
      } catch (const WorkerOutputError& e) {  // rolled back: stored as failed, without steps
        r.status = RunStatus::kFailed;
        r.reason = UnreadableWorkerOutput(e.what());
        r.metrics = RunMetrics{};
        store.Insert(r);
      }
    }
    switch (r.status) {
      case RunStatus::kOk: ++summary.ok; break;
      case RunStatus::kFailed: ++summary.failed; break;
      case RunStatus::kTimeout: ++summary.timed_out; break;
      case RunStatus::kSkipped: ++summary.skipped; break;
    }
    progress.Done(r, summary);
  };

  std::vector<Worker> workers;
  struct Reaper {
    std::vector<Worker>& workers;
    ~Reaper() { StopWorkers(workers); }
  } reaper{workers};
  const StopSignals signals;
  // Computed once (it runs git) while descriptors are still free: a sweep
  // that exhausts them must not store an empty provenance.
  CurrentProvenance();
  std::string start_error;  // pipe() or fork() failed: start nothing more
  int start_errno = 0;
  const int jobs = std::max(1, options.jobs);
  int workers_started = 0;
  while ((!queue.empty() && start_errno == 0) || !workers.empty()) {
    if (g_stop_signal != 0) break;
    while (static_cast<int>(workers.size()) < jobs && !queue.empty() && start_errno == 0) {
      PlannedRun run = std::move(queue.front());
      queue.pop_front();
      if (!run.skip_reason.empty()) {
        RunRecord r;
        r.spec = run.spec;
        r.status = RunStatus::kSkipped;
        r.reason = run.skip_reason;
        store_record(r, run.experiment);
        continue;
      }
      const double kill_after_s = run.spec.timeout_s > 0 && run.spec.timeout_s < kNoLimitAbove
                                      ? run.spec.timeout_s + options.kill_grace_s
                                      : 0;
      // The worker's own limit comes after the parent's kill, which is the
      // normal way a hung run ends.
      const double hard_limit_s = kill_after_s > 0 ? kill_after_s + 1 : 0;
      int fds[2];
      if (pipe(fds) != 0) {  // the run is not recorded: it never started
        start_errno = errno;
        start_error = "cannot create a pipe for a worker";
        queue.push_front(std::move(run));
        break;
      }
      const std::string step_file =
          (std::filesystem::path(options.out_dir) /
           (std::string(kStepFilePrefix) + std::to_string(getpid()) + "-" + std::to_string(++workers_started) +
            std::string(kStepFileSuffix)))
              .string();
      std::fflush(nullptr);
      const pid_t parent = getpid();
      const pid_t pid = fork();
      if (pid < 0) {
        start_errno = errno;
        start_error = "cannot start a worker process (fork)";
        close(fds[0]);
        close(fds[1]);
        queue.push_front(std::move(run));
        break;
      }
      if (pid == 0) {  // the worker: one run, its record on the pipe, no cleanup
        SetUpWorker(parent, hard_limit_s, run.spec.memory_limit_mb);
        close(fds[0]);
        close(lock.fd());
        for (const Worker& w : workers) close(w.fd);
        signal(SIGPIPE, SIG_IGN);
        RunRecord record;
        record.spec = run.spec;
        try {
          if (run.spec.record_steps) {
            StepFileWriter steps(step_file);
            record = ExecuteRun(run.spec, [&](const StepRecord& s) { steps.Write(s); });
            steps.Close();
          } else {  // record: runs: the metrics are accumulated all the same
            record = ExecuteRun(run.spec, [](const StepRecord&) {});
          }
        } catch (const std::exception& e) {  // the step file failed (a failed write is caught in ExecuteRun)
          record.status = RunStatus::kFailed;
          record.reason = e.what();
          record.metrics = RunMetrics{};
        }
        const bool ok = WriteAll(fds[1], SerializeSummary(record));
        _exit(ok ? 0 : 3);
      }
      close(fds[1]);
      Worker w;
      w.pid = pid;
      w.fd = fds[0];
      w.started = Clock::now();
      w.kill_after_s = kill_after_s;
      w.hard_limit_s = hard_limit_s;
      w.run = std::move(run);
      w.step_file = step_file;
      workers.push_back(std::move(w));
    }
    if (workers.empty()) continue;
    std::vector<pollfd> fds;
    for (const Worker& w : workers) fds.push_back({w.fd, POLLIN, 0});
    poll(fds.data(), fds.size(), 100);
    if (g_stop_signal != 0) break;
    for (std::size_t i = 0; i < workers.size();) {
      Worker& w = workers[i];
      bool eof = false;
      if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) {
        char buf[65536];
        ssize_t n = read(w.fd, buf, sizeof buf);
        if (n > 0) {
          w.output.append(buf, static_cast<std::size_t>(n));
        } else if (n == 0 || errno != EINTR) {
          eof = true;
        }
      }
      if (!eof && !w.killed && w.kill_after_s > 0 && Seconds(Clock::now() - w.started) > w.kill_after_s) {
        kill(w.pid, SIGKILL);
        w.killed = true;
      }
      if (!eof) {
        ++i;
        continue;
      }
      close(w.fd);
      int status = 0;
      while (waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
      }
      bool steps_in_file = false;
      RunRecord r = Finalize(w, status, &steps_in_file);
      const bool has_step_file = steps_in_file && w.run.spec.record_steps;
      store_record(std::move(r), w.run.experiment, has_step_file ? w.step_file : "");
      unlink(w.step_file.c_str());
      fds.erase(fds.begin() + static_cast<std::ptrdiff_t>(i));
      workers.erase(workers.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }
  if (g_stop_signal != 0) {
    summary.interrupted_by = g_stop_signal;
    summary.stopped = static_cast<int>(workers.size());
    StopWorkers(workers);
  }
  progress.Finish();
  if (start_errno != 0 && summary.interrupted_by == 0)
    ThrowErrno(start_error + " (" + std::to_string(summary.Finished()) + " finished runs kept, " +
                   std::to_string(queue.size()) + " not started)",
               start_errno);
  return summary;
}

}  // namespace icp
