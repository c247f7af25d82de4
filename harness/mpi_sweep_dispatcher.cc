// Rank 0 of the MPI sweep: hands the runs out to the worker ranks as they
// have room, takes their results in and stores them. Heartbeats and lost
// ranks are in mpi_sweep_lost_ranks.cc.
#include <mpi.h>

#include <cerrno>
#include <cstdio>
#include <exception>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/params.h"
#include "harness/environment_error.h"
#include "harness/mpi_sweep_internal.h"
#include "harness/worker_output.h"

namespace icp::detail {

Dispatcher::Dispatcher(const Spec& spec, int ranks, const MpiSweepOptions& mpi,
                       SweepRecorder* recorder, std::ostream& messages, bool* rank_lost)
    : spec_(spec),
      mpi_(mpi),
      recorder_(recorder),
      messages_(messages),
      rank_lost_(rank_lost),
      ranks_(static_cast<std::size_t>(ranks)) {
  for (std::size_t i = 0; i < spec.runs.size(); ++i) index_of_[spec.runs[i].spec.Key()] = i;
  for (const PlannedRun& run : recorder->queue())
    queue_.push_back({index_of_.at(run.spec.Key()), {}});
  recorder->queue().clear();
  const auto now = Clock::now();
  for (Rank& r : ranks_) r.heard = r.sent = now;
  ranks_[0].lost = true;  // this one: it runs nothing
}

Dispatcher::~Dispatcher() {
  for (Rank& rank : ranks_)
    for (auto& [index, run] : rank.in_flight) Discard(run);
}

void Dispatcher::Run() {
  const StopSignals signals;
  IdleBackoff backoff(std::chrono::milliseconds(1));
  Clock::time_point last_check = Clock::now();
  while (StopSignals::Caught() == 0) {
    const double start = ThreadCpuSeconds();
    const bool sent = Dispatch();
    if (queue_.empty() && InFlight() == 0) {
      busy_s_ += ThreadCpuSeconds() - start;
      return;
    }
    if (LiveRanks() == 0) {
      throw EnvironmentError("every worker rank is lost or could not run the spec: " +
                             std::to_string(queue_.size() + InFlight()) +
                             " runs not run (rerunning resumes)");
    }
    bool received = false, drained = false;
    Message m;
    for (int i = 0; i < 64; ++i) {
      if (!TryReceive(MPI_ANY_SOURCE, &m)) {
        drained = true;
        break;
      }
      received = true;
      Handle(m);
    }
    if (sent || received) busy_s_ += ThreadCpuSeconds() - start;
    SendHeartbeats();
    // Only with every waiting message taken: after a long store here, a
    // live rank's heartbeats may still be queued.
    const auto now = Clock::now();
    // Longer than the timeout since the last check: rank 0 did not run
    // (suspended with the job, as `scontrol suspend` does, or storing a
    // large run), so a rank's silence meanwhile says nothing: each has a
    // fresh timeout to speak.
    if (Seconds(now - last_check) > mpi_.rank_timeout_s)
      for (Rank& r : ranks_) r.heard = now;
    last_check = now;
    for (std::size_t r = 1; r < ranks_.size() && drained; ++r) {
      if (!ranks_[r].lost && Seconds(now - ranks_[r].heard) > mpi_.rank_timeout_s)
        Lose(r, "nothing from it for " + FormatDouble(mpi_.rank_timeout_s) + " s");
    }
    if (sent || received) {
      backoff.Reset();
    } else {
      backoff.Sleep();
    }
  }
  interrupted_by_ = StopSignals::Caught();
}

bool Dispatcher::Dispatch() {
  bool sent = false;
  for (std::size_t r = 1; r < ranks_.size(); ++r) {
    Rank& rank = ranks_[r];
    while (rank.ready && !rank.lost && static_cast<int>(rank.in_flight.size()) < rank.jobs &&
           !queue_.empty()) {
      Pending p = queue_.front();
      queue_.pop_front();
      const PlannedRun& run = spec_.runs[p.index];
      if (!run.skip_reason.empty()) {
        Store(SweepRecorder::Skipped(run), p.index, "", "rank 0");
        continue;
      }
      if (!Send(static_cast<int>(r), kRun, WithIndex(p.index, run.spec.Key()))) {
        queue_.push_front(p);
        Lose(r, "a message to it failed");
        break;
      }
      rank.sent = Clock::now();
      rank.in_flight[p.index] = InFlightRun{p, "", nullptr};
      sent = true;
    }
  }
  if (sent) recorder_->progress().InFlight(recorder_->summary(), InFlightText());
  return sent;
}

void Dispatcher::Store(const RunRecord& r, std::size_t index, const std::string& step_file,
                       const std::string& where) {
  const double start = ThreadCpuSeconds();
  recorder_->Record(r, spec_.runs[index].experiment, step_file, where, InFlightText(),
                    [this] { SendHeartbeats(); });
  storing_s_ += ThreadCpuSeconds() - start;
}

void Dispatcher::Handle(const Message& m) {
  const auto r = static_cast<std::size_t>(m.source);
  if (r == 0 || r >= ranks_.size()) return;
  Rank& rank = ranks_[r];
  if (rank.lost) {  // too late: its runs went elsewhere
    Send(m.source, kStop, "");
    return;
  }
  rank.heard = Clock::now();
  if (m.tag == kReady) {
    const nlohmann::json j = nlohmann::json::parse(m.bytes, nullptr, false);
    rank.ready = true;
    rank.jobs = j.is_object() ? j.value("jobs", 0) : 0;
    const std::string error =
        j.is_object() ? j.value("error", std::string("bad ready message")) : "bad ready message";
    if (!error.empty()) {
      messages_ << "icpbench: " << RankName(m.source) << " runs nothing: " << error << "\n";
    } else {
      messages_ << "icpbench: " << RankName(m.source) << " on "
                << (j.is_object() ? j.value("machine", std::string("?")) : "?") << ": " << rank.jobs
                << " runs at a time\n";
    }
    return;
  }
  std::size_t index = 0;
  std::string rest;
  if ((m.tag != kSteps && m.tag != kDone) || !SplitIndex(m.bytes, &index, &rest)) return;
  auto it = rank.in_flight.find(index);
  if (it == rank.in_flight.end()) return;
  if (m.tag == kSteps) {
    InFlightRun& run = it->second;
    if (run.steps == nullptr && run.step_file.empty()) {
      run.step_file = StepFileFor(r, index);
      run.steps = std::fopen(run.step_file.c_str(), "we");
      if (run.steps == nullptr) ThrowErrno("cannot write the step file " + run.step_file, errno);
    }
    if (std::fwrite(rest.data(), 1, rest.size(), run.steps) != rest.size())
      ThrowErrno("cannot write the step file " + run.step_file, errno);
    return;
  }
  InFlightRun run = std::move(it->second);
  rank.in_flight.erase(it);  // before the progress counts what is in flight
  Dispatch();                // the rank's next run first: storing takes longer
  Finish(r, run, rest);
}

void Dispatcher::Finish(std::size_t r, InFlightRun& run, const std::string& done) {
  const PlannedRun& planned = spec_.runs[run.pending.index];
  RunRecord record;
  record.spec = planned.spec;
  bool steps = false;
  try {
    const nlohmann::json j = nlohmann::json::parse(done);
    record = DeserializeSummary(j.at("summary").get<std::string>(), planned.spec);
    record.provenance.machine = j.at("machine").get<std::string>();
    steps = j.at("steps").get<bool>();
  } catch (const std::exception& e) {
    record.status = RunStatus::kFailed;
    record.reason =
        UnreadableWorkerOutput(std::string(e.what()) + ", from " + RankName(static_cast<int>(r)));
  }
  if (run.steps != nullptr && std::fclose(run.steps) != 0) {
    run.steps = nullptr;
    ThrowErrno("cannot write the step file " + run.step_file, errno);
  }
  run.steps = nullptr;
  if (steps && run.step_file.empty()) {  // a run of no steps sends no chunk
    run.step_file = StepFileFor(r, run.pending.index);
    std::ofstream touch(run.step_file);
  }
  const std::string step_file = steps ? run.step_file : "";
  struct Unlink {
    std::string path;
    ~Unlink() {
      if (!path.empty()) std::remove(path.c_str());
    }
  } unlink_after{run.step_file};
  Store(record, run.pending.index, step_file, RankName(static_cast<int>(r)));
}

std::string Dispatcher::StepFileFor(std::size_t r, std::size_t index) const {
  return StepFilePath(recorder_->out_dir(),
                      "rank" + std::to_string(r) + "-" + std::to_string(index));
}

std::string Dispatcher::InFlightText() const {
  std::string text;
  for (std::size_t r = 1; r < ranks_.size(); ++r) {
    if (!text.empty()) text += " ";
    text += std::to_string(r) + ":" +
            (ranks_[r].lost ? "lost" : std::to_string(ranks_[r].in_flight.size()));
  }
  return text;
}

}  // namespace icp::detail
