// Merging results stores: which copy of a run is kept (PreferredOver), a
// store merged into another (MergeFrom), and stores merged into a new file
// (MergeStores), every dropped copy kept in table attempts.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <iostream>
#include <optional>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

#include "harness/directory_lock.h"
#include "harness/output_directory.h"
#include "harness/results_store_internal.h"

namespace icp {

namespace {

using detail::AddAttempt;
using detail::Exec;
using detail::InTransaction;
using detail::StoredSummary;
using detail::WriteRun;

// OUT/results.sqlite.merge-PID.tmp (and its -wal, -shm, -journal): the
// store a merge writes before its rename.
constexpr std::string_view kMergeFilePrefix = ".merge-";

void RemoveStaleMergeFiles(const std::string& out_dir) {
  const std::string prefix = std::filesystem::path(StorePath(out_dir)).filename().string() +
                             std::string(kMergeFilePrefix);
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(out_dir, ec)) {
    if (entry.path().filename().string().starts_with(prefix)) std::filesystem::remove(entry.path(), ec);
  }
}

// The summary of a run, as an attempt.
Attempt AttemptOf(const RunRecord& run) {
  Attempt a;
  a.run_key = run.spec.Key();
  a.status = run.status;
  a.reason = run.reason;
  a.wall_time_s = run.wall_time_s;
  a.timeout_s = run.spec.timeout_s;
  a.steps = run.metrics.steps;
  a.date = run.provenance.date;
  a.git_revision = run.provenance.git_revision;
  a.machine = run.provenance.machine;
  return a;
}

// Whether two summaries are one measurement (the attempt number aside): a
// merge records a dropped copy only if it is not a duplicate of one kept.
bool SameMeasurement(const Attempt& a, const Attempt& b) {
  auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return a.run_key == b.run_key && a.status == b.status && a.reason == b.reason &&
         same(a.wall_time_s, b.wall_time_s) && same(a.timeout_s, b.timeout_s) &&
         a.steps == b.steps && a.date == b.date && a.git_revision == b.git_revision &&
         a.machine == b.machine;
}

// Rank for PreferredOver: a finished measurement beats a deterministic skip,
// which beats a run that did not finish.
int Rank(RunStatus s) {
  switch (s) {
    case RunStatus::kOk: return 2;
    case RunStatus::kSkipped: return 1;
    case RunStatus::kFailed:
    case RunStatus::kTimeout: return 0;
  }
  return 0;
}

}  // namespace

bool PreferredOver(RunStatus a, RunStatus b) { return Rank(a) > Rank(b); }

int ResultsStore::MergeFrom(const std::string& other_path) {
  if (read_only_) throw StoreError("results store '" + path_ + "': opened read-only");
  std::vector<RunRecord> others;
  {
    std::unique_ptr<ResultsStore> other = OpenReadOnly(other_path);
    others = other->LoadRuns(/*with_steps=*/true);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  int copied = 0;
  InTransaction(db_, path_, [&] {
    for (const RunRecord& run : others) {
      if (auto here = StoredSummary(db_, path_, run.spec.Key())) {
        if (!PreferredOver(run.status, here->second.status)) {
          // The dropped copy is kept as an attempt, unless it is this very run.
          const Attempt dropped = AttemptOf(run);
          if (!SameMeasurement(dropped, here->second)) AddAttempt(db_, path_, dropped);
          continue;
        }
      }
      WriteRun(db_, path_, run, StepsOf(run));  // a replaced copy goes to attempts
      ++copied;
    }
  });
  return copied;
}

std::string MergeSummary::ConflictMessage() const {
  if (duplicates == 0) return "";
  std::string m = "merge: " + std::to_string(duplicates) + " conflicting key" +
                  (duplicates == 1 ? "" : "s") + ":";
  const char* sep = " ";
  for (const auto& [statuses, n] : kept_over) {
    m += sep + std::string("kept ") + std::string(ToString(statuses.first)) + " over " +
         std::string(ToString(statuses.second)) + " for " + std::to_string(n);
    sep = ", ";
  }
  if (equal_kept_first > 0) {
    m += sep + std::string("kept the first of equal-status copies for ") +
         std::to_string(equal_kept_first);
  }
  return m + " (dropped copies are in table attempts)";
}

MergeSummary MergeStores(const std::string& out_dir, const std::vector<std::string>& in_dirs) {
  namespace fs = std::filesystem;
  const std::string out_path = StorePath(out_dir);
  // Read everything first: a missing or bad input fails before OUT is touched.
  struct Input {
    std::vector<RunRecord> runs;
    std::vector<Attempt> attempts;
  };
  std::vector<Input> inputs;
  std::error_code ec;
  // A run storing into OUT meanwhile would store into the file the rename
  // replaces, and lose it: OUT's lock is held from before OUT is read until
  // after the rename (a stale lock's takeover is said on stderr). Under it,
  // the temporary files of a merge that was killed are removed.
  std::optional<DirectoryLock> lock;
  auto take_lock = [&] {
    lock.emplace(out_dir, std::cerr);
    RemoveStaleMergeFiles(out_dir);
  };
  if (fs::is_directory(out_dir, ec)) take_lock();
  const bool out_exists = fs::exists(out_path, ec);
  std::vector<std::string> sources;
  if (out_exists) sources.push_back(out_path);
  for (const std::string& dir : in_dirs) sources.push_back(StorePath(dir));
  for (const std::string& source : sources) {
    std::unique_ptr<ResultsStore> store = ResultsStore::OpenReadOnly(source);
    Input input;
    input.runs = store->LoadRuns(/*with_steps=*/true);
    input.attempts = store->Attempts();
    inputs.push_back(std::move(input));
  }

  // Per key the preferred copy, among equals the first; drops become attempts.
  MergeSummary summary;
  summary.from_input.assign(in_dirs.size(), 0);
  struct Chosen {
    const RunRecord* run;
    std::size_t input;
    std::set<RunStatus> dropped;
    bool equal = false;
  };
  std::vector<std::string> order;  // keys in first-seen order
  std::unordered_map<std::string, Chosen> chosen;
  std::vector<Attempt> attempts;
  std::unordered_map<std::string, std::vector<std::size_t>> attempts_of;  // key -> indices
  // A copy of one measurement (a store merged twice, overlapping shards) is
  // recorded once.
  auto add_attempt = [&](const Attempt& a) {
    std::vector<std::size_t>& same_key = attempts_of[a.run_key];
    for (std::size_t j : same_key) {
      if (SameMeasurement(a, attempts[j])) return;
    }
    same_key.push_back(attempts.size());
    attempts.push_back(a);
  };
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    for (const Attempt& a : inputs[i].attempts) add_attempt(a);
    for (const RunRecord& run : inputs[i].runs) {
      const std::string key = run.spec.Key();
      auto [it, inserted] = chosen.try_emplace(key, Chosen{&run, i, {}, false});
      if (inserted) {
        order.push_back(key);
        continue;
      }
      Chosen& c = it->second;
      if (PreferredOver(run.status, c.run->status)) {
        add_attempt(AttemptOf(*c.run));
        c.dropped.insert(c.run->status);
        c.run = &run;
        c.input = i;
      } else if (!SameMeasurement(AttemptOf(run), AttemptOf(*c.run))) {
        // A copy of the very same measurement is no conflict.
        add_attempt(AttemptOf(run));
        if (run.status == c.run->status) c.equal = true;
        else c.dropped.insert(run.status);
      }
    }
  }
  for (const std::string& key : order) {
    const Chosen& c = chosen.at(key);
    if (c.dropped.empty() && !c.equal) continue;
    ++summary.duplicates;
    if (c.dropped.empty()) ++summary.equal_kept_first;
    for (RunStatus d : c.dropped) ++summary.kept_over[{c.run->status, d}];
  }

  // Write a temporary store beside OUT and rename it over OUT at the end.
  CreateOutputDirectory(out_dir, "choose another OUT_DIR");
  if (!lock) take_lock();
  const std::string tmp_path =
      out_path + std::string(kMergeFilePrefix) + std::to_string(static_cast<long long>(getpid())) + ".tmp";
  auto remove_tmp = [&] {
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) fs::remove(tmp_path + suffix, ec);
  };
  try {
    {
      ResultsStore out(tmp_path);
      std::lock_guard<std::mutex> lock(out.mutex_);
      InTransaction(out.db_, tmp_path, [&] {
        for (const std::string& key : order) {
          const Chosen& c = chosen.at(key);
          WriteRun(out.db_, tmp_path, *c.run, StepsOf(*c.run));
          if (c.input >= (out_exists ? 1u : 0u))
            ++summary.from_input[c.input - (out_exists ? 1 : 0)];
          ++summary.runs;
        }
        for (const Attempt& a : attempts) AddAttempt(out.db_, tmp_path, a);
      });
      // Fold the WAL into the file and leave WAL mode, so the rename moves
      // one complete file and no -wal is left behind under the old name.
      Exec(out.db_, tmp_path, "PRAGMA journal_mode=DELETE");
    }
    // The old OUT was read above; stale side files must not be replayed
    // into the new one.
    for (const char* suffix : {"-wal", "-shm"}) fs::remove(out_path + suffix, ec);
    fs::rename(tmp_path, out_path);
  } catch (...) {
    remove_tmp();
    throw;
  }
  return summary;
}

}  // namespace icp
