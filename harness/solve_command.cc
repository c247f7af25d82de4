#include "harness/solve_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "algorithms/registry.h"
#include "core/minibex_parser.h"

namespace icp {

namespace {
ParamMap ParseKeyValues(const std::vector<std::string>& items) {
  ParamMap map;
  for (const std::string& item : items) {
    auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw std::invalid_argument("--param '" + item + "': expected key=value");
    map[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return map;
}

// %.17g reads back to the same double, so the printed box still encloses.
std::string Bound(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
}  // namespace

SolveResult Solve(const SolveOptions& options) {
  if (options.repeat < 1)
    throw std::invalid_argument("--repeat " + std::to_string(options.repeat) + ": must be >= 1");
  if (options.format != "text" && options.format != "json")
    throw std::invalid_argument("--format " + options.format + ": must be text or json");
  const AlgorithmInfo& info = FindAlgorithm(options.algorithm);
  SolveResult result;
  result.algorithm = info.name;
  result.csp = ParseMinibexFile(options.file);
  if (info.contractor == nullptr)
    throw std::invalid_argument("solve: '" + info.name + "' is not a CSP contractor (it runs through `icpbench run`)");
  const ParamMap params = ParseKeyValues(options.params);
  info.resolve(info.name, params);  // every key checked, `carry` included
  std::unique_ptr<Contractor> contractor = info.contractor(ContractorParams(params), result.csp);
  std::vector<double> times;
  for (int r = 0; r < options.repeat; ++r) {
    Box box = result.csp.domains();
    ContractContext context;
    auto start = std::chrono::steady_clock::now();
    ContractSummary summary = contractor->Contract(box, context);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    result.box = box;
    result.summary = summary;
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  result.time_s = times[times.size() / 2];
  if (times.size() % 2 == 0) {
    double lower = *std::max_element(times.begin(), times.begin() + times.size() / 2);
    result.time_s = (result.time_s + lower) / 2;
  }
  return result;
}

std::string SolveResultToJson(const SolveResult& r) {
  nlohmann::ordered_json out;
  const bool empty = r.box.IsEmpty();
  out["algorithm"] = r.algorithm;
  out["status"] = empty ? "empty" : "nonempty";
  out["box"] = nlohmann::ordered_json::object();
  if (!empty) {
    for (int i = 0; i < r.csp.num_variables(); ++i) {
      auto bound = [](double v) -> nlohmann::ordered_json {
        if (std::isinf(v)) return nullptr;
        return v;
      };
      out["box"][r.csp.names()[i]] = {bound(r.box[i].lo()), bound(r.box[i].hi())};
    }
  }
  out["time_s"] = r.time_s;
  return out.dump();
}

std::string SolveResultToText(const SolveResult& r) {
  std::string text = "algorithm: " + r.algorithm + "\n";
  text += "status: " + std::string(r.box.IsEmpty() ? "empty" : "nonempty") + " (" +
          std::string(ToString(r.summary.status)) +
          (r.summary.message.empty() ? "" : ": " + r.summary.message) + ")\n";
  if (!r.box.IsEmpty()) {
    std::size_t width = 0;
    for (const auto& name : r.csp.names()) width = std::max(width, name.size());
    for (int i = 0; i < r.csp.num_variables(); ++i) {
      std::string name = r.csp.names()[i];
      name.resize(width, ' ');
      text += "  " + name + " in [" + Bound(r.box[i].lo()) + ", " + Bound(r.box[i].hi()) + "]\n";
    }
  }
  text += "revise_calls: " + std::to_string(r.summary.work.revise_calls) + "\n";
  text += "time_s: " + Bound(r.time_s) + "\n";
  return text;
}

}  // namespace icp
