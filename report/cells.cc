// How runs show in tables and figures: numbers, parameters, run counts and
// problem items, and an algorithm's display data and order.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "report/report.h"

namespace icp {

namespace {

constexpr const char* kDash = "—";

}  // namespace

std::string OkRunsCell(const GroupSummary& group) {
  std::string cell = std::to_string(group.ok);
  if (group.runs.size() != static_cast<std::size_t>(group.ok))
    cell += " of " + std::to_string(group.runs.size());
  return cell;
}

std::string ProblemItem(const GroupSummary& group, const std::string& problem) {
  return WithParams(group.algorithm, group.algorithm_params) + " on " +
         WithParams(group.problem, group.problem_params) + ": " + problem;
}

std::string FormatNumber(double v) {
  if (std::isnan(v)) return kDash;
  if (std::isinf(v)) return v > 0 ? "∞" : "-∞";
  if (v == 0) return "0";
  const double a = std::fabs(v);
  char buf[64];
  if (a >= 1e9 || a < 1e-3) {
    std::snprintf(buf, sizeof buf, "%.3e", v);
    return buf;
  }
  if (a >= 1e4) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  const int magnitude = static_cast<int>(std::floor(std::log10(a)));
  std::snprintf(buf, sizeof buf, "%.*f", std::max(0, 3 - magnitude), v);
  std::string out = buf;
  if (out.find('.') != std::string::npos) {
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
  }
  return out;
}

std::string WithParams(const std::string& name, const ParamMap& params) {
  return params.empty() ? name : name + " {" + CompactParams(params) + "}";
}

std::string ParamsCell(const ParamMap& params) {
  return params.empty() ? "default" : CompactParams(params);
}

std::string FormatRatio(double a, double b) {
  if (std::isnan(a) || std::isnan(b) || b == 0) return kDash;
  return FormatNumber(a / b);
}

std::string CompactParams(const ParamMap& params) {
  std::string out;
  for (const auto& [k, v] : params) out += (out.empty() ? "" : ",") + k + "=" + v;
  return out;
}

Display DisplayOf(const std::string& algorithm) {
  for (const AlgorithmInfo& a : Algorithms())
    if (a.name == algorithm) return a.display;
  return {algorithm, 1000, "#7f7f7f"};
}

bool AlgorithmLess(const std::string& a, const std::string& b) {
  const int oa = DisplayOf(a).order, ob = DisplayOf(b).order;
  return oa != ob ? oa < ob : a < b;
}

}  // namespace icp
