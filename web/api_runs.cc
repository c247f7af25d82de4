// GET /api/runs (a page of runs, filtered), /api/summary (counts by status,
// failure reasons), /api/options (what the filters can choose), /api/runs/ID
// (one run with its steps), /api/runs/ID/values (its step values, for the
// corridors) and /api/runs/ID/steps/N (one step's values and properties).
// Paging, counting and filtering are done in SQL over runs' primary key.
#include <set>

#include "web/api.h"

namespace icp::web {

namespace {

// The list's columns (after r.id), as JSON keys.
constexpr const char* kListColumns[] = {
    "key", "experiment", "algorithm", "problem", "status", "reason", "seed", "steps",
    "wall_time_s", "mean_area", "consistency_rate", "centre_rmse", "time_mean_s", "time_median_s"};
constexpr const char* kListSql =
    "SELECT r.id, r.key, experiment_of(r.spec_file), r.algorithm, r.problem, "
    "r.status, r.reason, r.seed, r.steps, r.wall_time_s, r.mean_area, r.consistency_rate, "
    "r.centre_rmse, r.time_mean_s, r.time_median_s, r.algorithm_params, r.problem_params FROM runs r";
constexpr int kListParamsColumn = 15;

// The columns a list may be sorted by.
const std::set<std::string> kSortable = {"id", "algorithm", "problem", "status", "seed", "steps",
                                         "wall_time_s", "mean_area", "consistency_rate",
                                         "centre_rmse", "time_mean_s", "time_median_s"};

nlohmann::json ParamsObject(sqlite3_stmt* stmt, int i) {
  const unsigned char* text = sqlite3_column_text(stmt, i);
  if (text == nullptr) return nlohmann::json::object();
  nlohmann::json value =
      nlohmann::json::parse(reinterpret_cast<const char*>(text), nullptr, /*exceptions=*/false);
  // Sent as is, a malformed column would make the whole answer not JSON.
  if (value.is_discarded())
    throw HttpError(500, std::string("the store's column runs.") + sqlite3_column_name(stmt, i) +
                             " is not JSON (a damaged store)");
  return value;
}

// One row of kListSql as JSON.
nlohmann::json ListRow(sqlite3_stmt* stmt) {
  nlohmann::json run = {{"id", sqlite3_column_int64(stmt, 0)}};
  int i = 1;
  for (const char* name : kListColumns) run[name] = Column(stmt, i++);
  run["parameters"] = {{"algorithm", ParamsObject(stmt, kListParamsColumn)},
                       {"problem", ParamsObject(stmt, kListParamsColumn + 1)}};
  return run;
}

void GetRuns(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  RunFilter f = ParseRunFilter(req, {"limit", "offset", "sort", "desc"});
  const long long limit = IntParam(req, "limit", 100, 1, 10000);
  const long long offset = IntParam(req, "offset", 0, 0, 1LL << 40);
  const std::string sort = req.has_param("sort") ? req.get_param_value("sort") : "id";
  if (kSortable.count(sort) == 0) throw HttpError(400, "cannot sort by '" + sort + "'");
  const std::string order = IntParam(req, "desc", 0, 0, 1) ? " DESC" : "";
  StoreReader store(dir);
  Query q(store,
          std::string(kListSql) + " WHERE " + f.where + " ORDER BY r." + sort + order +
              (sort == "id" ? "" : ", r.id") + " LIMIT " + std::to_string(limit) + " OFFSET " +
              std::to_string(offset),
          f.values);
  nlohmann::json runs = nlohmann::json::array();
  while (q.Step()) runs.push_back(ListRow(q.stmt()));
  SendJson(res, runs);
}

void GetSummary(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  RunFilter f = ParseRunFilter(req, {});
  StoreReader store(dir);
  nlohmann::json summary = {{"total", 0}, {"status", nlohmann::json::object()}};
  {
    Query q(store, "SELECT r.status, count(*) FROM runs r WHERE " + f.where + " GROUP BY r.status",
            f.values);
    while (q.Step()) {
      const long long n = sqlite3_column_int64(q.stmt(), 1);
      summary["status"][reinterpret_cast<const char*>(sqlite3_column_text(q.stmt(), 0))] = n;
      summary["total"] = summary["total"].get<long long>() + n;
    }
  }
  nlohmann::json reasons = nlohmann::json::array();
  Query q(store,
          "SELECT r.status, r.reason, count(*) AS n FROM runs r WHERE " + f.where +
              " AND r.status <> 'ok' GROUP BY r.status, r.reason ORDER BY n DESC LIMIT 50",
          f.values);
  while (q.Step())
    reasons.push_back({{"status", Column(q.stmt(), 0)}, {"reason", Column(q.stmt(), 1)},
                       {"count", Column(q.stmt(), 2)}});
  summary["reasons"] = reasons;
  SendJson(res, summary);
}

// The distinct values of sql's one column, as a JSON array.
nlohmann::json Distinct(const StoreReader& store, const std::string& sql) {
  nlohmann::json values = nlohmann::json::array();
  Query q(store, sql, {});
  while (q.Step()) values.push_back(Column(q.stmt(), 0));
  return values;
}

void GetOptions(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  RequireNoQuery(req);
  StoreReader store(dir);
  nlohmann::json options;
  options["algorithms"] = Distinct(store, "SELECT DISTINCT algorithm FROM runs ORDER BY 1");
  options["problems"] = Distinct(store, "SELECT DISTINCT problem FROM runs ORDER BY 1");
  options["experiments"] = Distinct(
      store, "SELECT DISTINCT experiment_of(f) FROM (SELECT DISTINCT spec_file AS f "
             "FROM runs) ORDER BY 1");
  // Parameters with their values (a sweep's axes), in numeric order, at most
  // 200 each; `truncated_parameters` names those that have more.
  nlohmann::json params = nlohmann::json::object();
  std::set<std::string> truncated;
  // The distinct parameter objects first: a sweep has few, however many seeds and runs.
  Query q(store,
          "SELECT k, v FROM (SELECT p.key AS k, p.value AS v FROM (SELECT DISTINCT problem_params "
          "AS j FROM runs) d, json_each(d.j) p UNION SELECT p.key, p.value FROM (SELECT DISTINCT "
          "algorithm_params AS j FROM runs) d, json_each(d.j) p) ORDER BY k, CAST(v AS REAL), v",
          {});
  while (q.Step()) {
    const std::string name = reinterpret_cast<const char*>(sqlite3_column_text(q.stmt(), 0));
    nlohmann::json& values = params[name];
    if (values.size() < 200) values.push_back(Column(q.stmt(), 1));
    else truncated.insert(name);
  }
  options["parameters"] = params;
  options["truncated_parameters"] = truncated;
  options["properties"] =
      store.version() >= 2
          ? Distinct(store, "SELECT DISTINCT name FROM run_properties WHERE type IN ('int', 'real') "
                            "ORDER BY 1")
          : nlohmann::json::array();
  SendJson(res, options);
}

void GetRun(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  const std::string id = RunId(req);
  StoreReader store(dir);
  nlohmann::json run;
  {
    Query q(store,
            "SELECT id, key, spec_file, algorithm, algorithm_params, problem, problem_params, seed, "
            "timeout_s, status, reason, wall_time_s, steps, mean_area, consistency_rate, "
            "centre_rmse, time_mean_s, time_median_s, time_p90_s, time_mean_ci_lo_s, "
            "time_mean_ci_hi_s, corridors, git_revision, machine, compiler, flags, date FROM runs "
            "WHERE id = ?",
            {id});
    if (!q.Step()) throw HttpError(404, "no run with id " + id);
    const int n = sqlite3_column_count(q.stmt());
    for (int i = 0; i < n; ++i) {
      const std::string name = sqlite3_column_name(q.stmt(), i);
      if (name == "algorithm_params" || name == "problem_params" || name == "corridors")
        run[name] = ParamsObject(q.stmt(), i);
      else
        run[name] = Column(q.stmt(), i);
    }
  }
  nlohmann::json props = nlohmann::json::object();
  if (store.version() >= 2) {
    Query q(store, "SELECT name, value FROM run_properties WHERE run_id = ? ORDER BY name", {id});
    while (q.Step()) props[reinterpret_cast<const char*>(sqlite3_column_text(q.stmt(), 0))] = Column(q.stmt(), 1);
  }
  run["properties"] = props;
  nlohmann::json steps = nlohmann::json::array();
  Query q(store,
          std::string("SELECT step, status, contained, area, centre_error, solve_time_s, ") +
              (store.version() >= 2 ? "estimate" : "'box'") +
              " FROM steps WHERE run_id = ? ORDER BY step",
          {id});
  while (q.Step())
    steps.push_back({{"step", Column(q.stmt(), 0)}, {"status", Column(q.stmt(), 1)},
                     {"contained", Column(q.stmt(), 2)}, {"area", Column(q.stmt(), 3)},
                     {"centre_error", Column(q.stmt(), 4)}, {"solve_time_s", Column(q.stmt(), 5)},
                     {"estimate", Column(q.stmt(), 6)}});
  run["step_rows"] = steps;
  SendJson(res, run);
}

void GetValues(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  const std::string id = RunId(req);
  StoreReader store(dir);
  RequireRun(store, id);
  nlohmann::json values = nlohmann::json::array();
  Query q(store,
          "SELECT step, var, lo, hi, truth FROM step_values WHERE run_id = ? ORDER BY step, pos",
          {id});
  while (q.Step())
    values.push_back({Column(q.stmt(), 0), Column(q.stmt(), 1), Column(q.stmt(), 2),
                      Column(q.stmt(), 3), Column(q.stmt(), 4)});
  SendJson(res, {{"columns", {"step", "var", "lo", "hi", "truth"}}, {"rows", values}});
}

void GetStep(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  const std::string id = RunId(req);
  const std::string step = req.matches[2];
  StoreReader store(dir);
  RequireRun(store, id);
  nlohmann::json out = {{"run_id", std::stoll(id)}, {"step", std::stoll(step)}};
  {
    Query q(store, "SELECT 1 FROM steps WHERE run_id = ? AND step = ?", {id, step});
    if (!q.Step()) throw HttpError(404, "run " + id + " has no step " + step);
  }
  nlohmann::json values = nlohmann::json::array();
  {
    Query q(store,
            "SELECT var, lo, hi, truth FROM step_values WHERE run_id = ? AND step = ? ORDER BY pos",
            {id, step});
    while (q.Step())
      values.push_back({{"var", Column(q.stmt(), 0)}, {"lo", Column(q.stmt(), 1)},
                        {"hi", Column(q.stmt(), 2)}, {"truth", Column(q.stmt(), 3)}});
  }
  out["values"] = values;
  nlohmann::json props = nlohmann::json::object();
  if (store.version() >= 2) {
    Query q(store, "SELECT name, value FROM step_properties WHERE run_id = ? AND step = ? ORDER BY name",
            {id, step});
    while (q.Step()) props[reinterpret_cast<const char*>(sqlite3_column_text(q.stmt(), 0))] = Column(q.stmt(), 1);
  }
  out["properties"] = props;
  SendJson(res, out);
}

}  // namespace

void RegisterRunsApi(httplib::Server& server, const std::string& dir) {
  using namespace std::placeholders;
  server.Get("/api/runs", std::bind(GetRuns, dir, _1, _2));
  server.Get("/api/summary", std::bind(GetSummary, dir, _1, _2));
  server.Get("/api/options", std::bind(GetOptions, dir, _1, _2));
  server.Get(R"(/api/runs/([^/]*))", std::bind(GetRun, dir, _1, _2));
  server.Get(R"(/api/runs/([^/]*)/values)", std::bind(GetValues, dir, _1, _2));
  server.Get(R"(/api/runs/([^/]*)/steps/(\d{1,9}))", std::bind(GetStep, dir, _1, _2));
}

}  // namespace icp::web
