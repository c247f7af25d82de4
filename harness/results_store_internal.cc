// The results store's shared helpers: SQLite errors and statements, and how
// values are encoded (parameters and corridors as JSON, typed properties).
#include "harness/results_store_internal.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>

#include "harness/environment_error.h"

namespace icp::detail {

[[noreturn]] void Fail(const std::string& path, const std::string& what, sqlite3* db) {
  std::string message = "results store '" + path + "': " + what;
  if (db != nullptr) message += (what.empty() ? "" : ": ") + std::string(sqlite3_errmsg(db));
  // The environment's failures (exit 3), with what to do about them.
  switch (db != nullptr ? sqlite3_errcode(db) & 0xff : SQLITE_OK) {
    case SQLITE_FULL: throw EnvironmentError(message + " (free disk space and rerun)");
    case SQLITE_CANTOPEN:
      throw EnvironmentError(message +
                             " (check the permissions of the store's directory and files; or too many open "
                             "files: raise ulimit -n, or reduce run's --jobs)");
    case SQLITE_READONLY: throw EnvironmentError(message + " (check the permissions of the store)");
    case SQLITE_IOERR:
      throw EnvironmentError(message + " (check the disk, its free space and the file-size limit, ulimit -f)");
    case SQLITE_NOMEM: throw EnvironmentError(message + " (out of memory: reduce --jobs)");
    default: break;
  }
  throw StoreError(message);
}

void Exec(sqlite3* db, const std::string& path, const char* sql) {
  // A full disk is usually met here, at COMMIT: Fail says it is the environment's.
  if (sqlite3_exec(db, sql, nullptr, nullptr, nullptr) != SQLITE_OK) Fail(path, "", db);
}

RunStatus ParseStoredStatus(const std::string& text, const std::string& path,
                            const std::string& key) {
  try {
    return ParseRunStatus(text);
  } catch (const std::invalid_argument& e) {
    throw StoreError("results store '" + path + "': run '" + key + "': " + e.what());
  }
}

std::string ParamsToJson(const ParamMap& params, const std::string& path) {
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [key, value] : params) object[key] = value;
  try {
    return object.dump();
  } catch (const nlohmann::json::exception& e) {
    throw StoreError("results store '" + path + "': parameters are not UTF-8 text: " + e.what());
  }
}

ParamMap ParamsFromJson(const std::string& text, const std::string& path) {
  ParamMap params;
  if (text.empty()) return params;
  try {
    nlohmann::json object = nlohmann::json::parse(text);
    for (const auto& [key, value] : object.items()) params[key] = value.get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw StoreError("results store '" + path + "': bad parameter JSON '" + text +
                     "': " + e.what());
  }
  return params;
}

namespace {

nlohmann::ordered_json NumberToJson(double v) {
  if (std::isnan(v)) return nullptr;
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

double NumberFromJson(const nlohmann::ordered_json& j) {
  if (j.is_null()) return kStoreNaN;
  if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    throw nlohmann::json::other_error::create(501, "bad number '" + s + "'", &j);
  }
  return j.get<double>();
}

}  // namespace

std::string CorridorsToJson(const std::vector<Corridor>& corridors) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const Corridor& c : corridors) {
    array.push_back({{"var", c.var},
                     {"mean_lower", NumberToJson(c.mean_lower)},
                     {"mean_upper", NumberToJson(c.mean_upper)},
                     {"min_lower", NumberToJson(c.min_lower)},
                     {"max_upper", NumberToJson(c.max_upper)}});
  }
  return array.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::vector<Corridor> CorridorsFromJson(const std::string& text, const std::string& path) {
  std::vector<Corridor> corridors;
  if (text.empty()) return corridors;
  try {
    for (const auto& j : nlohmann::ordered_json::parse(text)) {
      Corridor c;
      c.var = j.at("var").get<std::string>();
      c.mean_lower = NumberFromJson(j.at("mean_lower"));
      c.mean_upper = NumberFromJson(j.at("mean_upper"));
      c.min_lower = NumberFromJson(j.at("min_lower"));
      c.max_upper = NumberFromJson(j.at("max_upper"));
      corridors.push_back(std::move(c));
    }
  } catch (const nlohmann::json::exception& e) {
    throw StoreError("results store '" + path + "': bad corridors JSON: " + e.what());
  }
  return corridors;
}

void BindProperty(Statement& q, int i, const Property& p) {
  q.Text(i, p.name);
  q.Text(i + 1, TypeName(p));
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::int64_t>) q.Int(i + 2, v);
        else if constexpr (std::is_same_v<T, double>) q.Double(i + 2, v);
        else q.Text(i + 2, v);
      },
      p.value);
}

Property ReadProperty(const Statement& q, int i) {
  Property p{q.ColumnText(i), std::int64_t{0}};
  const std::string type = q.ColumnText(i + 1);
  if (type == "int") p.value = q.ColumnInt(i + 2);
  else if (type == "real") p.value = q.ColumnDouble(i + 2);
  else p.value = q.ColumnText(i + 2);
  return p;
}

}  // namespace icp::detail
