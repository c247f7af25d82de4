// The read-only store of a request, run filters from query parameters, JSON
// numbers and statements: what every handler of web/ uses.
#include <cmath>
#include <cstdlib>
#include <set>

#include "harness/results_store.h"
#include "harness/results_store_internal.h"
#include "harness/run_record.h"
#include "web/api.h"

namespace icp::web {

namespace {

// SQL experiment_of(spec_file): ExperimentOf (harness/run_record.h) (after the last '#'; a
// spec path may hold '#' too), so the browser groups runs as the report does.
void ExperimentOfSql(sqlite3_context* context, int, sqlite3_value** argv) {
  const unsigned char* text = sqlite3_value_text(argv[0]);
  const std::string experiment = ExperimentOf(std::string(text ? reinterpret_cast<const char*>(text) : ""));
  sqlite3_result_text(context, experiment.c_str(), static_cast<int>(experiment.size()), SQLITE_TRANSIENT);
}

}  // namespace

StoreReader::StoreReader(const std::string& dir) : path_(StorePath(dir)) {
  db_ = detail::OpenExistingReadOnly(path_);
  try {
    version_ = detail::CheckOrCreateSchema(db_, path_, /*may_create=*/false);
    if (sqlite3_create_function(db_, "experiment_of", 1, SQLITE_UTF8 | SQLITE_DETERMINISTIC, nullptr,
                                &ExperimentOfSql, nullptr, nullptr) != SQLITE_OK)
      detail::Fail(path_, "defining experiment_of", db_);
  } catch (...) {
    sqlite3_close_v2(db_);
    throw;
  }
}

StoreReader::~StoreReader() { sqlite3_close_v2(db_); }

Query::Query(const StoreReader& store, const std::string& sql, const std::vector<std::string>& values)
    : store_(store) {
  if (sqlite3_prepare_v2(store.db(), sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK)
    detail::Fail(store.path(), "preparing '" + sql + "'", store.db());
  for (std::size_t i = 0; i < values.size(); ++i)
    sqlite3_bind_text(stmt_, static_cast<int>(i + 1), values[i].c_str(), -1, SQLITE_TRANSIENT);
}

Query::~Query() { sqlite3_finalize(stmt_); }

bool Query::Step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  detail::Fail(store_.path(), std::string("running '") + sqlite3_sql(stmt_) + "'", store_.db());
}

nlohmann::json Number(double v) {
  if (std::isnan(v)) return nullptr;
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

nlohmann::json Column(sqlite3_stmt* stmt, int i) {
  switch (sqlite3_column_type(stmt, i)) {
    case SQLITE_NULL: return nullptr;
    case SQLITE_INTEGER: return sqlite3_column_int64(stmt, i);
    case SQLITE_FLOAT: return Number(sqlite3_column_double(stmt, i));
    default: return reinterpret_cast<const char*>(sqlite3_column_text(stmt, i));
  }
}

void SendJson(httplib::Response& res, const nlohmann::json& value) {
  // Text from the store may hold invalid UTF-8 (a reason, a message): replaced, not thrown.
  res.set_content(value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  "application/json");
}

std::string ParamPath(const std::string& name) {
  // A nested algorithm's parameters are stored as "inner.ratio": the dot is
  // part of the name, which the path quotes.
  const bool ok = !name.empty() && name.size() <= 64 &&
                  name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-.") == std::string::npos;
  if (!ok)
    throw HttpError(400, "bad parameter name '" + name + "' (letters, digits, _, - and ., at most 64)");
  return "$.\"" + name + "\"";
}

long long IntParam(const httplib::Request& req, const std::string& name, long long fallback,
                   long long lo, long long hi) {
  if (!req.has_param(name.c_str())) return fallback;
  const std::string text = req.get_param_value(name.c_str());
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  // Digits only: strtoll would also take leading blanks and a '+'.
  if (text.empty() || text.find_first_not_of("-0123456789") != std::string::npos ||
      *end != '\0' || errno != 0 || v < lo || v > hi)
    throw HttpError(400, name + "='" + text + "' must be an integer in [" + std::to_string(lo) +
                             ", " + std::to_string(hi) + "]");
  return v;
}

namespace {

// "a,b" -> {"a", "b"}; a 400 on an empty item.
std::vector<std::string> SplitList(const std::string& name, const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (items.back().empty()) throw HttpError(400, "empty value in " + name + "='" + text + "'");
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

}  // namespace

RunFilter ParseRunFilter(const httplib::Request& req, const std::vector<std::string>& also_allowed) {
  static const std::set<std::string> kStatuses = {"ok", "failed", "timeout", "skipped"};
  RunFilter f;
  f.where = "1";
  for (const auto& [name, text] : req.params) {
    std::string column;
    if (name == "algorithm") column = "r.algorithm";
    else if (name == "problem") column = "r.problem";
    else if (name == "status") column = "r.status";
    else if (name == "experiment") column = "experiment_of(r.spec_file)";
    if (!column.empty()) {
      const std::vector<std::string> items = SplitList(name, text);
      f.where += " AND " + column + " IN (";
      for (std::size_t i = 0; i < items.size(); ++i) {
        if (name == "status" && kStatuses.count(items[i]) == 0)
          throw HttpError(400, "unknown status '" + items[i] + "' (ok, failed, timeout, skipped)");
        f.where += i == 0 ? "?" : ", ?";
        f.values.push_back(items[i]);
      }
      f.where += ")";
    } else if (name == "key") {  // one run's identity (it holds commas: not a list)
      f.where += " AND r.key = ?";
      f.values.push_back(text);
    } else if (name.rfind("param.", 0) == 0) {
      const std::string path = ParamPath(name.substr(6));
      f.where += std::string(" AND ") + kParamValueSql + " = ?";
      f.values.insert(f.values.end(), {path, path, text});
    } else if (std::find(also_allowed.begin(), also_allowed.end(), name) == also_allowed.end()) {
      throw HttpError(400, "unknown query parameter '" + name +
                               "' (filters: algorithm, problem, status, experiment, key, param.NAME)");
    }
  }
  return f;
}

void RequireNoQuery(const httplib::Request& req) {
  if (!req.params.empty()) throw HttpError(400, req.path + " takes no query parameters");
}

std::string RunId(const httplib::Request& req) {
  RequireNoQuery(req);  // a run's own answers are not filtered
  const std::string id = req.matches[1];
  if (id.empty() || id.size() > 18 || id.find_first_not_of("0123456789") != std::string::npos)
    throw HttpError(400, "bad run id '" + id + "' (a number)");
  return id;
}

void RequireRun(const StoreReader& store, const std::string& id) {
  Query q(store, "SELECT 1 FROM runs WHERE id = ?", {id});
  if (!q.Step()) throw HttpError(404, "no run with id " + id);
}

}  // namespace icp::web
