// How runs show in tables and figures: numbers, parameters, run counts and
// problem items, and an algorithm's display data and order.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

namespace {

// v rounded to a multiple of step (a power of ten) toward floor, nearest or
// ceil; a quotient within rounding error of an integer counts as one.
double RoundTo(double v, double step, double (*mode)(double)) {
  double q = v / step;
  if (std::fabs(q - std::round(q)) < 1e-9 * std::max(1.0, std::fabs(q))) q = std::round(q);
  const double r = mode(q) * step;
  return r == 0 ? 0 : r;  // no "-0"
}

std::string Fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

}  // namespace

std::string FormatWithInterval(const MedianInterval& m, double scale) {
  const double v = m.median * scale, lo = m.lo * scale, hi = m.hi * scale;
  if (std::isnan(v) || std::isnan(lo) || std::isnan(hi) || !std::isfinite(v) || !(hi > lo))
    return FormatNumber(v);
  const double half = (hi - lo) / 2;
  int exponent = static_cast<int>(std::floor(std::log10(half)));
  if (half < 2 * std::pow(10.0, exponent)) --exponent;  // leading digit 1: one more
  // At most 6 significant digits, whatever the interval.
  if (v != 0) exponent = std::max(exponent, static_cast<int>(std::floor(std::log10(std::fabs(v)))) - 5);
  const double step = std::pow(10.0, exponent);
  const int decimals = std::max(0, -exponent);
  // The bounds rounded outward, so the printed interval still holds the computed one.
  return Fixed(RoundTo(v, step, std::round), decimals) + " [" +
         Fixed(RoundTo(lo, step, std::floor), decimals) + ", " +
         Fixed(RoundTo(hi, step, std::ceil), decimals) + "]";
}

Unit TimeUnit(const std::vector<double>& seconds) {
  std::vector<double> magnitudes;
  for (double s : seconds)
    if (std::isfinite(s) && s != 0) magnitudes.push_back(std::fabs(s));
  if (magnitudes.empty()) return {"µs", 1e6};
  std::nth_element(magnitudes.begin(), magnitudes.begin() + magnitudes.size() / 2, magnitudes.end());
  const double median = magnitudes[magnitudes.size() / 2];
  for (const Unit& u : {Unit{"s", 1}, Unit{"ms", 1e3}, Unit{"µs", 1e6}})
    if (median * u.scale >= 1) return u;
  return {"ns", 1e9};
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
