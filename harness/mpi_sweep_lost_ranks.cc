// Rank 0's watch on the worker ranks of the MPI sweep: heartbeats to them,
// and a lost rank's runs in flight handed to other ranks, or recorded as
// failed when lost with a second rank.
#include <cstdio>
#include <string>
#include <vector>

#include "harness/mpi_sweep_internal.h"

namespace icp::detail {

void Dispatcher::SendHeartbeats() {
  const auto now = Clock::now();
  for (std::size_t r = 1; r < ranks_.size(); ++r) {
    Rank& rank = ranks_[r];
    if (rank.lost || Seconds(now - rank.sent) < mpi_.heartbeat_s) continue;
    Send(static_cast<int>(r), kHeartbeat, "");  // a rank it cannot reach falls silent
    rank.sent = now;
  }
}

void Dispatcher::Lose(std::size_t r, const std::string& why) {
  Rank& rank = ranks_[r];
  rank.lost = true;
  *rank_lost_ = true;
  messages_ << "icpbench: " << RankName(static_cast<int>(r)) << " lost (" << why << "): ";
  if (rank.in_flight.empty()) messages_ << "no run was in flight there\n";
  int requeued = 0;
  std::vector<Pending> failed;
  for (auto it = rank.in_flight.rbegin(); it != rank.in_flight.rend(); ++it) {
    InFlightRun& run = it->second;
    Discard(run);
    run.pending.lost_with.push_back(static_cast<int>(r));
    if (run.pending.lost_with.size() >= 2) {
      failed.push_back(run.pending);
    } else {
      queue_.push_front(run.pending);
      ++requeued;
    }
  }
  const int lost = static_cast<int>(rank.in_flight.size());
  rank.in_flight.clear();
  if (lost > 0)
    messages_ << requeued << " of its " << lost << " runs in flight go to other ranks, "
              << failed.size() << " (lost with a rank before) are recorded as failed\n";
  for (const Pending& p : failed) {
    RunRecord record;
    record.spec = spec_.runs[p.index].spec;
    record.status = RunStatus::kFailed;
    record.reason = "lost with worker ranks";
    for (int lost_rank : p.lost_with) record.reason += " " + std::to_string(lost_rank);
    record.reason += " (" + why + ")";
    Store(record, p.index, "", RankName(static_cast<int>(r)));
  }
}

void Dispatcher::Discard(InFlightRun& run) {
  if (run.steps != nullptr) std::fclose(run.steps);
  run.steps = nullptr;
  if (!run.step_file.empty()) std::remove(run.step_file.c_str());
}

}  // namespace icp::detail
