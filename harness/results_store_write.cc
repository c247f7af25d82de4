// Writing runs to the results store: a run with its steps and properties in
// one transaction, the replaced run's summary kept in table attempts.
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>

#include "harness/results_store_internal.h"

namespace icp {

namespace detail {

void AddAttempt(sqlite3* db, const std::string& path, const Attempt& a) {
  Statement q(db, path,
              "INSERT INTO attempts (run_key, attempt, status, reason, wall_time_s, timeout_s, "
              "steps, date, git_revision, machine) VALUES (?1, (SELECT coalesce(max(attempt), 0) "
              "+ 1 FROM attempts WHERE run_key = ?1), ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)");
  q.Text(1, a.run_key);
  q.Text(2, ToString(a.status));
  q.Text(3, a.reason);
  q.Double(4, a.wall_time_s);
  q.Double(5, a.timeout_s);
  q.Int(6, a.steps);
  q.Text(7, a.date);
  q.Text(8, a.git_revision);
  q.Text(9, a.machine);
  q.Run();
}

void WriteRun(sqlite3* db, const std::string& path, const RunRecord& run,
              const StepSource& next_step) {
  const std::string key = run.spec.Key();
  {
    if (auto stored = StoredSummary(db, path, key)) {
      const std::int64_t old_id = stored->first;
      AddAttempt(db, path, stored->second);
      for (const char* sql : {"DELETE FROM step_values WHERE run_id = ?",
                              "DELETE FROM step_properties WHERE run_id = ?",
                              "DELETE FROM run_properties WHERE run_id = ?",
                              "DELETE FROM steps WHERE run_id = ?",
                              "DELETE FROM runs WHERE id = ?"}) {
        Statement del(db, path, sql);
        del.Int(1, old_id);
        del.Run();
      }
    }
  }

  Statement insert(db, path,
                   std::string("INSERT INTO runs (") + kRunColumns +
                       ") VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
  const RunMetrics& m = run.metrics;
  const Provenance& p = run.provenance;
  int i = 0;
  insert.Text(++i, key);
  insert.Text(++i, run.spec_file);
  insert.Text(++i, run.spec.algorithm);
  insert.Text(++i, ParamsToJson(run.spec.algorithm_params, path));
  insert.Text(++i, run.spec.problem);
  insert.Text(++i, ParamsToJson(run.spec.problem_params, path));
  insert.Int(++i, static_cast<std::int64_t>(run.spec.seed));
  insert.Double(++i, run.spec.timeout_s);
  insert.Text(++i, ToString(run.status));
  insert.Text(++i, run.reason);
  insert.Double(++i, run.wall_time_s);
  insert.Int(++i, m.steps);
  insert.Double(++i, m.mean_area);
  insert.Double(++i, m.consistency_rate);
  insert.Double(++i, m.centre_rmse);
  insert.Double(++i, m.time_mean_s);
  insert.Double(++i, m.time_median_s);
  insert.Double(++i, m.time_p90_s);
  insert.Double(++i, m.time_mean_ci_lo_s);
  insert.Double(++i, m.time_mean_ci_hi_s);
  insert.Text(++i, CorridorsToJson(m.corridors));
  insert.Text(++i, p.git_revision);
  insert.Text(++i, p.machine);
  insert.Text(++i, p.compiler);
  insert.Text(++i, p.flags);
  insert.Text(++i, p.date);
  insert.Run();
  const std::int64_t run_id = sqlite3_last_insert_rowid(db);
  {
    Statement run_property(db, path,
                           "INSERT OR REPLACE INTO run_properties (run_id, name, type, value) "
                           "VALUES (?,?,?,?)");
    for (const Property& p : run.properties) {
      run_property.Int(1, run_id);
      BindProperty(run_property, 2, p);
      run_property.Run();
      run_property.Reset();
    }
  }

  Statement step_insert(db, path,
                        "INSERT INTO steps (run_id, step, status, contained, area, centre_error, "
                        "solve_time_s, estimate) VALUES (?,?,?,?,?,?,?,?)");
  Statement property_insert(
      db, path,
      "INSERT OR REPLACE INTO step_properties (run_id, step, name, type, value) "
      "VALUES (?,?,?,?,?)");
  Statement value_insert(db, path,
                         "INSERT INTO step_values (run_id, step, var, pos, lo, hi, truth) "
                         "VALUES (?,?,?,?,?,?,?)");
  StepRecord s;
  while (next_step(&s)) {
    step_insert.Int(1, run_id);
    step_insert.Int(2, s.step);
    step_insert.Text(3, s.status);
    if (s.contained == -1) {
      step_insert.Null(4);
    } else {
      step_insert.Int(4, s.contained);
    }
    step_insert.Double(5, s.area);
    step_insert.Double(6, s.centre_error);
    step_insert.Double(7, s.solve_time_s);
    step_insert.Text(8, s.estimate);
    step_insert.Run();
    step_insert.Reset();
    for (const Property& p : s.properties) {
      property_insert.Int(1, run_id);
      property_insert.Int(2, s.step);
      BindProperty(property_insert, 3, p);
      property_insert.Run();
      property_insert.Reset();
    }
    for (std::size_t pos = 0; pos < s.vars.size(); ++pos) {
      const VariableRecord& v = s.vars[pos];
      value_insert.Int(1, run_id);
      value_insert.Int(2, s.step);
      value_insert.Text(3, v.name);
      value_insert.Int(4, static_cast<std::int64_t>(pos));
      value_insert.Double(5, v.lo);
      value_insert.Double(6, v.hi);
      value_insert.Double(7, v.truth);
      value_insert.Run();
      value_insert.Reset();
    }
  }
}

}  // namespace detail

void ResultsStore::Insert(const RunRecord& run) { Insert(run, StepsOf(run)); }

void ResultsStore::Insert(const RunRecord& run, const StepSource& steps) {
  if (read_only_) throw StoreError("results store '" + path_ + "': opened read-only");
  std::lock_guard<std::mutex> lock(mutex_);
  detail::InTransaction(db_, path_, [&] { detail::WriteRun(db_, path_, run, steps); });
}

StepSource StepsOf(const RunRecord& run) {
  return [&run, next = std::size_t{0}](StepRecord* step) mutable {
    if (next == run.steps.size()) return false;
    *step = run.steps[next++];
    return true;
  };
}

}  // namespace icp
