// GET /api/aggregate (a metric's mean with a 95% confidence interval per
// group and x value: the sweep figure), aggregated in SQL over the ok runs
// that pass the filters, and /api/profile (performance profiles: each
// group's metric over the best of its instance, as
// report/performance_profile.h computes them for the report and the paper).
#include <cmath>
#include <limits>
#include <set>

#include "report/performance_profile.h"
#include "web/api.h"

namespace icp::web {

namespace {

// SQL with the values its `?` take, in order.
struct Expr {
  std::string sql;
  std::vector<std::string> values;
};

// The run columns a metric may name; else prop.NAME, a numeric run property.
const std::set<std::string> kMetricColumns = {"mean_area",   "consistency_rate", "centre_rmse",
                                              "time_mean_s", "time_median_s",    "time_p90_s",
                                              "wall_time_s", "steps"};

Expr Metric(const httplib::Request& req) {
  const std::string name = req.has_param("metric") ? req.get_param_value("metric") : "time_mean_s";
  if (kMetricColumns.count(name) != 0) return {"r." + name, {}};
  if (name.rfind("prop.", 0) == 0 && name.size() > 5)
    return {"(SELECT CASE WHEN p.type IN ('int', 'real') THEN p.value END FROM run_properties p "
            "WHERE p.run_id = r.id AND p.name = ?)",
            {name.substr(5)}};
  throw HttpError(400, "unknown metric '" + name + "' (a run column such as time_mean_s, or prop.NAME)");
}

// What runs are grouped or placed by: algorithm, problem, experiment,
// param.NAME, or (for x only) "none".
Expr Axis(const httplib::Request& req, const char* key, const std::string& fallback) {
  const std::string name = req.has_param(key) ? req.get_param_value(key) : fallback;
  if (name == "algorithm" || name == "problem") return {"r." + name, {}};
  if (name == "experiment") return {"experiment_of(r.spec_file)", {}};
  if (name == "none") return {"''", {}};
  if (name.rfind("param.", 0) == 0) {
    const std::string path = ParamPath(name.substr(6));
    return {kParamValueSql, {path, path}};
  }
  throw HttpError(400, std::string("bad ") + key + "='" + name +
                           "' (algorithm, problem, experiment, param.NAME or none)");
}

std::vector<std::string> Concat(std::initializer_list<const std::vector<std::string>*> lists) {
  std::vector<std::string> all;
  for (const auto* l : lists) all.insert(all.end(), l->begin(), l->end());
  return all;
}

void GetAggregate(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  const RunFilter f = ParseRunFilter(req, {"metric", "group", "x"});
  const Expr metric = Metric(req);
  const Expr group = Axis(req, "group", "algorithm");
  const Expr x = Axis(req, "x", "none");
  StoreReader store(dir);
  Query q(store,
          // The spread about each group's mean, in a second pass (avg(m * m) -
          // mean^2 lost every digit where the mean is large and the spread small).
          "SELECT g, x, count(m), avg(m), sum((m - mean) * (m - mean)), min(m), max(m) FROM "
          "(SELECT g, x, m, avg(m) OVER (PARTITION BY g, x) AS mean FROM (SELECT " + group.sql +
              " AS g, " + x.sql + " AS x, " + metric.sql + " AS m FROM runs r WHERE " + f.where +
              " AND r.status = 'ok') WHERE m IS NOT NULL) GROUP BY g, x ORDER BY g, x",
          Concat({&group.values, &x.values, &metric.values, &f.values}));
  nlohmann::json rows = nlohmann::json::array();
  while (q.Step()) {
    const double n = static_cast<double>(sqlite3_column_int64(q.stmt(), 2));
    // avg() is NULL where the sum is NaN (+inf and -inf): a null mean, not 0.
    const double mean = sqlite3_column_type(q.stmt(), 3) == SQLITE_NULL
                            ? std::numeric_limits<double>::quiet_NaN()
                            : sqlite3_column_double(q.stmt(), 3);
    nlohmann::json row = {{"group", Column(q.stmt(), 0)}, {"x", Column(q.stmt(), 1)},
                          {"n", static_cast<long long>(n)}, {"mean", Number(mean)},
                          {"min", Column(q.stmt(), 5)}, {"max", Column(q.stmt(), 6)},
                          {"ci_lo", nullptr}, {"ci_hi", nullptr}};
    if (n >= 2) {
      // Normal approximation of the mean's 95% interval, from the sample variance.
      const double var = sqlite3_column_double(q.stmt(), 4) / (n - 1);
      const double half = 1.96 * std::sqrt(var / n);
      row["ci_lo"] = Number(mean - half);
      row["ci_hi"] = Number(mean + half);
    }
    rows.push_back(row);
  }
  SendJson(res, rows);
}

void GetProfile(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  const RunFilter f = ParseRunFilter(req, {"metric", "group"});
  const Expr metric = Metric(req);
  if (req.has_param("metric") && req.get_param_value("metric") == "consistency_rate")
    throw HttpError(400, "a performance profile needs a metric where lower is better");
  const Expr group = Axis(req, "group", "algorithm");
  StoreReader store(dir);
  // Each filtered run as a profile entry: its group is the solver, an
  // instance one problem with its parameters and seed; a run that is not ok
  // leaves its instance unsolved. report/performance_profile.h computes.
  Query q(store,
          "SELECT " + group.sql + ", r.problem || ' ' || r.problem_params || ' ' || r.seed, " +
              "CASE WHEN r.status = 'ok' THEN " + metric.sql + " END FROM runs r WHERE " +
              f.where + " ORDER BY 1",
          Concat({&group.values, &metric.values, &f.values}));
  std::vector<ProfileEntry> entries;
  while (q.Step())
    entries.push_back({sqlite3_column_type(q.stmt(), 0) == SQLITE_NULL
                           ? std::string("(none)")
                           : reinterpret_cast<const char*>(sqlite3_column_text(q.stmt(), 0)),
                       reinterpret_cast<const char*>(sqlite3_column_text(q.stmt(), 1)),
                       sqlite3_column_type(q.stmt(), 2) == SQLITE_NULL
                           ? std::numeric_limits<double>::quiet_NaN()
                           : sqlite3_column_double(q.stmt(), 2)});
  const PerformanceProfile profile = ComputeProfile(entries);
  nlohmann::json out = {{"instances", profile.instances}, {"solvers", nlohmann::json::object()}};
  for (const SolverProfile& s : profile.solvers) out["solvers"][s.solver] = s.ratios;
  SendJson(res, out);
}

}  // namespace

void RegisterCompareApi(httplib::Server& server, const std::string& dir) {
  using namespace std::placeholders;
  server.Get("/api/aggregate", std::bind(GetAggregate, dir, _1, _2));
  server.Get("/api/profile", std::bind(GetProfile, dir, _1, _2));
}

}  // namespace icp::web
