// What the results browser's handlers share: errors that become a 4xx, the
// read-only store a request opens, run filters from query parameters, and
// JSON numbers. Handlers: api_runs.cc (runs, one run), api_estimate.cc (a
// step's estimate, re-run), api_compare.cc
// (aggregates, performance profiles), files.cc (page assets, figures, claims).
#ifndef ICPBENCH_WEB_API_H_
#define ICPBENCH_WEB_API_H_

#include <httplib.h>
#include <sqlite3.h>

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace icp::web {

// A request the server will not answer: 400 (bad filter, option or path) or
// 404 (unknown run, file); the message goes back as {"error": ...}.
class HttpError : public std::runtime_error {
 public:
  HttpError(int status, const std::string& message) : std::runtime_error(message), status(status) {}
  int status;
};

// The store of DIR, opened read-only for one request (immutable when no
// sweep is writing, else sharing its WAL: the rule of ResultsStore::
// OpenReadOnly). A connection per request sees a sweep's newest runs.
class StoreReader {
 public:
  explicit StoreReader(const std::string& dir);
  ~StoreReader();
  StoreReader(const StoreReader&) = delete;
  StoreReader& operator=(const StoreReader&) = delete;
  sqlite3* db() const { return db_; }
  const std::string& path() const { return path_; }
  int version() const { return version_; }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
  int version_ = 0;
};

// A WHERE clause over `runs r` and its bound values, from the query
// parameters algorithm, problem, status, experiment (comma-separated lists)
// and param.NAME (a parameter's effective value). Any other parameter not in
// `also_allowed` is a 400.
struct RunFilter {
  std::string where;  // "1" or "... AND ..."
  std::vector<std::string> values;
};
RunFilter ParseRunFilter(const httplib::Request& req, const std::vector<std::string>& also_allowed);

// The JSON path of parameter NAME ($."NAME"); a 400 unless NAME is letters,
// digits, '_' or '-'.
std::string ParamPath(const std::string& name);
// SQL of a parameter's value: the problem's, else the algorithm's. Its path
// is bound as `?`.
inline constexpr const char* kParamValueSql =
    "coalesce(json_extract(r.problem_params, ?), json_extract(r.algorithm_params, ?))";

// An integer query parameter in [lo, hi], or fallback when absent; a 400 if
// malformed or out of range.
long long IntParam(const httplib::Request& req, const std::string& name, long long fallback,
                   long long lo, long long hi);

// A number as JSON: NaN (SQL NULL) is null, +-inf the strings "inf"/"-inf"
// (the store's corridors convention).
nlohmann::json Number(double v);
// Column i of a row as JSON: null, an integer, a Number or text.
nlohmann::json Column(sqlite3_stmt* stmt, int i);

// A prepared statement with its values bound in order; finalised on scope exit.
class Query {
 public:
  Query(const StoreReader& store, const std::string& sql, const std::vector<std::string>& values);
  ~Query();
  Query(const Query&) = delete;
  Query& operator=(const Query&) = delete;
  bool Step();  // true while there is a row
  sqlite3_stmt* stmt() const { return stmt_; }

 private:
  const StoreReader& store_;
  sqlite3_stmt* stmt_ = nullptr;
};

// The run id of a /api/runs/ID/... path (match 1); a 400 unless a number.
std::string RunId(const httplib::Request& req);
// Throws a 400 if req has a query: PATH takes no query parameters.
void RequireNoQuery(const httplib::Request& req);
// A 404 unless run id is stored.
void RequireRun(const StoreReader& store, const std::string& id);

// Sends value as JSON (200).
void SendJson(httplib::Response& res, const nlohmann::json& value);

// The handlers.
void RegisterRunsApi(httplib::Server& server, const std::string& dir);
void RegisterEstimateApi(httplib::Server& server, const std::string& dir);
void RegisterCompareApi(httplib::Server& server, const std::string& dir);
void RegisterFiles(httplib::Server& server, const std::string& dir, const std::string& assets,
                   const std::string& chart_js);

}  // namespace icp::web

#endif  // ICPBENCH_WEB_API_H_
