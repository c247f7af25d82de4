// Reading the results store: its runs (with their steps, values and
// properties, one query per table), their keys and statuses, and attempts.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "harness/results_store_internal.h"

namespace icp {

namespace detail {

namespace {

// Reads status, reason, wall_time_s, timeout_s, steps, date, git_revision
// and machine from columns first, first + 1, ... into a (a.run_key is set).
void ReadAttemptFields(const Statement& q, int first, const std::string& path, Attempt* a) {
  a->status = ParseStoredStatus(q.ColumnText(first), path, a->run_key);
  a->reason = q.ColumnText(first + 1);
  a->wall_time_s = q.ColumnDouble(first + 2);
  a->timeout_s = q.ColumnDouble(first + 3);
  a->steps = static_cast<int>(q.ColumnInt(first + 4));
  a->date = q.ColumnText(first + 5);
  a->git_revision = q.ColumnText(first + 6);
  a->machine = q.ColumnText(first + 7);
}

// The step numbered `number` among steps (sorted by number); null if none.
StepRecord* FindStep(std::vector<StepRecord>& steps, std::int64_t number) {
  auto s = std::lower_bound(steps.begin(), steps.end(), number,
                            [](const StepRecord& a, std::int64_t n) { return a.step < n; });
  return s != steps.end() && s->step == number ? &*s : nullptr;
}

// Every run, in insertion order, with one query per table.
// A version-1 store (read-only) has no estimate column and no properties.
std::vector<RunRecord> ReadRuns(sqlite3* db, const std::string& path, int version,
                                bool with_steps) {
  std::vector<RunRecord> runs;
  std::unordered_map<std::int64_t, std::size_t> index_of;  // runs.id -> index in runs
  {
    Statement q(db, path, std::string("SELECT id, ") + kRunColumns + " FROM runs ORDER BY id");
    while (q.Step()) {
      RunRecord r;
      RunMetrics& m = r.metrics;
      Provenance& p = r.provenance;
      int i = 0;
      const std::int64_t id = q.ColumnInt(i++);
      const std::string key = q.ColumnText(i++);
      r.spec_file = q.ColumnText(i++);
      r.spec.algorithm = q.ColumnText(i++);
      r.spec.algorithm_params = ParamsFromJson(q.ColumnText(i++), path);
      r.spec.problem = q.ColumnText(i++);
      r.spec.problem_params = ParamsFromJson(q.ColumnText(i++), path);
      r.spec.seed = static_cast<std::uint64_t>(q.ColumnInt(i++));
      r.spec.timeout_s = q.ColumnDouble(i++);
      r.status = ParseStoredStatus(q.ColumnText(i++), path, key);
      r.reason = q.ColumnText(i++);
      r.wall_time_s = q.ColumnDouble(i++);
      m.steps = static_cast<int>(q.ColumnInt(i++));
      m.mean_area = q.ColumnDouble(i++);
      m.consistency_rate = q.ColumnDouble(i++);
      m.centre_rmse = q.ColumnDouble(i++);
      m.time_mean_s = q.ColumnDouble(i++);
      m.time_median_s = q.ColumnDouble(i++);
      m.time_p90_s = q.ColumnDouble(i++);
      m.time_mean_ci_lo_s = q.ColumnDouble(i++);
      m.time_mean_ci_hi_s = q.ColumnDouble(i++);
      m.corridors = CorridorsFromJson(q.ColumnText(i++), path);
      p.git_revision = q.ColumnText(i++);
      p.machine = q.ColumnText(i++);
      p.compiler = q.ColumnText(i++);
      p.flags = q.ColumnText(i++);
      p.date = q.ColumnText(i++);
      index_of[id] = runs.size();
      runs.push_back(std::move(r));
    }
  }
  if (!with_steps || runs.empty()) return runs;

  {
    Statement q(db, path,
                std::string("SELECT run_id, step, status, contained, area, centre_error, "
                            "solve_time_s, ") +
                    (version >= 2 ? "estimate" : "NULL") + " FROM steps ORDER BY run_id, step");
    RunRecord* run = nullptr;
    std::int64_t run_id = 0;
    while (q.Step()) {
      const std::int64_t id = q.ColumnInt(0);
      if (run == nullptr || id != run_id) {
        auto it = index_of.find(id);
        if (it == index_of.end()) continue;  // no such run: ignored
        run = &runs[it->second];
        run_id = id;
      }
      StepRecord s;
      s.step = static_cast<int>(q.ColumnInt(1));
      s.status = q.ColumnText(2);
      s.contained = q.IsNull(3) ? -1 : static_cast<int>(q.ColumnInt(3));
      s.area = q.ColumnDouble(4);
      s.centre_error = q.ColumnDouble(5);
      s.solve_time_s = q.ColumnDouble(6);
      s.estimate = q.IsNull(7) ? "box" : q.ColumnText(7);  // version 1 stored boxes only
      run->steps.push_back(std::move(s));
    }
  }
  {
    Statement q(db, path,
                "SELECT run_id, step, var, lo, hi, truth FROM step_values "
                "ORDER BY run_id, step, pos");
    std::int64_t last_run = 0;
    std::int64_t last_step = 0;
    StepRecord* step = nullptr;
    while (q.Step()) {
      const std::int64_t id = q.ColumnInt(0);
      const std::int64_t number = q.ColumnInt(1);
      if (step == nullptr || id != last_run || number != last_step) {
        step = nullptr;
        last_run = id;
        last_step = number;
        auto it = index_of.find(id);
        if (it != index_of.end()) step = FindStep(runs[it->second].steps, number);
        if (step == nullptr) continue;  // no such step: ignored
      }
      VariableRecord v;
      v.name = q.ColumnText(2);
      v.lo = q.ColumnDouble(3);
      v.hi = q.ColumnDouble(4);
      v.truth = q.ColumnDouble(5);
      step->vars.push_back(std::move(v));
    }
  }
  if (version < 2) return runs;
  {
    Statement q(db, path,
                "SELECT run_id, name, type, value FROM run_properties ORDER BY run_id, name");
    while (q.Step()) {
      auto it = index_of.find(q.ColumnInt(0));
      if (it != index_of.end()) runs[it->second].properties.push_back(ReadProperty(q, 1));
    }
  }
  {
    Statement q(db, path,
                "SELECT run_id, step, name, type, value FROM step_properties "
                "ORDER BY run_id, step, name");
    while (q.Step()) {
      auto it = index_of.find(q.ColumnInt(0));
      if (it == index_of.end()) continue;
      StepRecord* step = FindStep(runs[it->second].steps, q.ColumnInt(1));
      if (step != nullptr) step->properties.push_back(ReadProperty(q, 2));
    }
  }
  return runs;
}

// The attempts table, by key then attempt (none before version 3).
std::vector<Attempt> ReadAttempts(sqlite3* db, const std::string& path, int version) {
  std::vector<Attempt> attempts;
  if (version < 3) return attempts;
  Statement q(db, path,
              "SELECT run_key, attempt, status, reason, wall_time_s, timeout_s, steps, date, "
              "git_revision, machine FROM attempts ORDER BY run_key, attempt");
  while (q.Step()) {
    Attempt a;
    a.run_key = q.ColumnText(0);
    a.attempt = static_cast<int>(q.ColumnInt(1));
    ReadAttemptFields(q, 2, path, &a);
    attempts.push_back(std::move(a));
  }
  return attempts;
}

}  // namespace

std::optional<std::pair<std::int64_t, Attempt>> StoredSummary(sqlite3* db,
                                                              const std::string& path,
                                                              const std::string& key) {
  Statement find(db, path,
                 "SELECT id, status, reason, wall_time_s, timeout_s, steps, date, git_revision, "
                 "machine FROM runs WHERE key = ?");
  find.Text(1, key);
  if (!find.Step()) return std::nullopt;
  Attempt a;
  a.run_key = key;
  ReadAttemptFields(find, 1, path, &a);
  return std::make_pair(find.ColumnInt(0), a);
}

}  // namespace detail

std::vector<std::string> ResultsStore::RunKeys() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> keys;
  detail::Statement q(db_, path_, "SELECT key FROM runs ORDER BY id");
  while (q.Step()) keys.push_back(q.ColumnText(0));
  return keys;
}

bool ResultsStore::HasRun(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  detail::Statement q(db_, path_, "SELECT 1 FROM runs WHERE key = ?");
  q.Text(1, key);
  return q.Step();
}

std::vector<StoredRun> ResultsStore::StoredRuns() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<StoredRun> runs;
  detail::Statement q(db_, path_, "SELECT key, status, spec_file FROM runs ORDER BY id");
  while (q.Step()) {
    StoredRun r{q.ColumnText(0), RunStatus::kOk, q.ColumnText(2)};
    r.status = detail::ParseStoredStatus(q.ColumnText(1), path_, r.key);
    runs.push_back(std::move(r));
  }
  return runs;
}

std::vector<Attempt> ResultsStore::Attempts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return detail::ReadAttempts(db_, path_, version_);
}

std::vector<RunRecord> ResultsStore::LoadRuns(bool with_steps) const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<RunRecord> runs;
  detail::InReadTransaction(db_, path_,
                            [&] { runs = detail::ReadRuns(db_, path_, version_, with_steps); });
  return runs;
}

}  // namespace icp
