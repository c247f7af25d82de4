#include "harness/solve_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <variant>

#include "algorithms/contraction_check.h"
#include "algorithms/registry.h"
#include "core/minibex_parser.h"
#include "harness/environment_error.h"
#include "harness/metrics.h"
#include "problems/registry.h"

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

// With SolveOptions::kill_grace_s: ends the process if the work it watches
// (one contraction or solve) is still running that long past its limit.
class Watchdog {
 public:
  Watchdog(const SolveOptions& options, const std::string& algorithm) {
    if (options.kill_grace_s < 0 || !std::isfinite(options.timeout_s)) return;
    const auto after = std::chrono::duration<double>(options.timeout_s + options.kill_grace_s);
    const std::string message = "icpbench: algorithm '" + algorithm + "' did not stop within " +
                                FormatDouble(options.kill_grace_s) + " s past --timeout " +
                                FormatDouble(options.timeout_s) + "\n";
    thread_ = std::thread([this, after, message] {
      std::unique_lock<std::mutex> lock(mutex_);
      if (done_changed_.wait_for(lock, after, [this] { return done_; })) return;
      std::fputs(message.c_str(), stderr);
      std::_Exit(1);
    });
  }
  ~Watchdog() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    done_changed_.notify_all();
    thread_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable done_changed_;
  bool done_ = false;
  std::thread thread_;
};

// Work of `algorithm` (building it, a contraction, a solve): its own
// failures become AlgorithmFault; usage, memory and environment errors
// pass as they are.
template <class Work>
auto Guarded(const std::string& algorithm, Work&& work) {
  try {
    return work();
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const EnvironmentError&) {
    throw;
  } catch (const std::exception& e) {
    throw AlgorithmFault("algorithm '" + algorithm + "' failed: " + e.what());
  } catch (...) {
    throw AlgorithmFault("algorithm '" + algorithm + "' threw an exception of unknown type");
  }
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
  if (!(options.timeout_s > 0))
    throw std::invalid_argument("--timeout " + FormatDouble(options.timeout_s) +
                                ": must be a number of seconds > 0 (inf: no limit)");
  // Each repeat gets the whole limit.
  auto limit = [&] {
    return StopCondition::After(std::chrono::duration<double>(options.timeout_s))
        .WithCancelFlag(options.cancel);
  };
  auto cancelled = [&] { return options.cancel != nullptr && options.cancel->load(); };
  const AlgorithmInfo& info = FindAlgorithm(options.algorithm);
  SolveResult result;
  result.algorithm = info.name;
  result.csp = options.parsed ? *options.parsed : ParseMinibexFile(options.file);
  const ParamMap params = ParseKeyValues(options.params);
  info.resolve(info.name, params);  // every key checked, `carry` included
  std::vector<double> times;
  if (info.contractor != nullptr) {
    std::shared_ptr<Contractor> contractor =
        options.contractor && options.parsed ? options.contractor
                                             : Guarded(info.name, [&] {
                                                 return std::shared_ptr<Contractor>(
                                                     info.contractor(ContractorParams(params), result.csp));
                                               });
    if (!contractor) throw AlgorithmFault("algorithm '" + info.name + "' made no contractor");
    result.contractor = contractor;
    const Box domains = result.csp.domains();
    for (int r = 0; r < options.repeat && (r == 0 || !cancelled()); ++r) {
      Box box = domains;
      const StopCondition stop = limit();
      ContractContext context(stop);
      auto start = std::chrono::steady_clock::now();
      const Watchdog watchdog(options, info.name);
      ContractSummary summary = Guarded(info.name, [&] { return contractor->Contract(box, context); });
      times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if (std::string why = InvalidContractionReason(domains, box, result.csp.names()); !why.empty())
        throw AlgorithmFault("algorithm '" + info.name + "' returned an invalid box: " + why);
      result.box = box;
      result.summary = summary;
    }
  } else if (info.needs == View::kMeasurementSet) {
    // The file as the minibex-file problem offers it: one measurement per constraint.
    Step step;
    FindProblem("minibex-file").make({{"file", options.file}}, 0)->Next(&step);
    if (!step.views.Offers(info.needs))
      throw std::invalid_argument("solve: the minibex-file problem offers no measurement-set view");
    for (int r = 0; r < options.repeat && (r == 0 || !cancelled()); ++r) {
      std::unique_ptr<Estimator> estimator = Guarded(info.name, [&] { return info.make(params, 0); });
      auto start = std::chrono::steady_clock::now();
      const Watchdog watchdog(options, info.name);
      StepResult step_result = Guarded(info.name, [&] { return estimator->Step(step.views, limit()); });
      times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if (!step_result.estimate) throw AlgorithmFault("algorithm '" + info.name + "' returned no estimate");
      if (std::string why = InvalidEstimateReason(step.views, *step_result.estimate); !why.empty())
        throw AlgorithmFault("algorithm '" + info.name + "' returned an invalid estimate: " + why);
      result.box = step_result.estimate->Hull();
      result.summary = step_result.summary;
      result.relaxed = true;
      result.q = static_cast<int>(IntProperty(step_result.properties, "q").value_or(0));
      result.estimate_kind = std::string(step_result.estimate->Kind());
      result.estimate_extras = step_result.estimate->Extras();
      result.hulls_by_q = std::move(step_result.hulls_by_q);
    }
  } else {
    // A CSP-view algorithm without a contractor estimates over a problem's
    // steps (windows), which one Minibex CSP is not.
    const std::string why =
        info.needs == View::kCsp
            ? " has no contractor for one CSP: it estimates over a problem's steps"
            : " needs the " + std::string(ToString(info.needs)) + " view, which a Minibex file does not offer";
    throw std::invalid_argument("solve: '" + info.name + "'" + why +
                                (info.test_only ? " (a harness test plugin, not an algorithm)" : "") +
                                " (run it through `icpbench run`)");
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  result.time_s = times[times.size() / 2];
  if (times.size() % 2 == 0) {
    double lower = *std::max_element(times.begin(), times.begin() + times.size() / 2);
    result.time_s = (result.time_s + lower) / 2;
  }
  return result;
}

namespace {
// {name: [lo, hi]}, infinite bounds null; {} for an empty box.
nlohmann::ordered_json BoxToJson(const Box& box, const std::vector<std::string>& names) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  if (box.IsEmpty()) return out;
  auto bound = [](double v) -> nlohmann::ordered_json {
    if (std::isinf(v)) return nullptr;
    return v;
  };
  for (std::size_t i = 0; i < names.size(); ++i)
    out[names[i]] = {bound(box[i].lo()), bound(box[i].hi())};
  return out;
}

const char* StatusOf(const Box& box) { return box.IsEmpty() ? "empty" : "nonempty"; }
}  // namespace

std::string SolveResultToJson(const SolveResult& r) {
  nlohmann::ordered_json out;
  out["algorithm"] = r.algorithm;
  out["status"] = StatusOf(r.box);
  out["box"] = BoxToJson(r.box, r.csp.names());
  out["time_s"] = r.time_s;
  if (r.summary.status == ContractStatus::kStopped) out["stopped"] = r.summary.message;
  if (r.relaxed) {
    out["q"] = r.q;
    nlohmann::ordered_json estimate;
    estimate["kind"] = r.estimate_kind;
    for (const Property& p : r.estimate_extras)
      std::visit([&](const auto& v) { estimate[p.name] = v; }, p.value);
    out["estimate"] = estimate;
    if (!r.hulls_by_q.empty()) {
      out["by_q"] = nlohmann::ordered_json::array();
      for (std::size_t q = 0; q < r.hulls_by_q.size(); ++q)
        out["by_q"].push_back({{"q", q},
                               {"status", StatusOf(r.hulls_by_q[q])},
                               {"box", BoxToJson(r.hulls_by_q[q], r.csp.names())}});
    }
  }
  return out.dump();
}

std::string SolveResultToText(const SolveResult& r) {
  std::string text = "algorithm: " + r.algorithm + "\n";
  // A message that already names the status ("stopped (time limit)") is
  // not prefixed with it again.
  const std::string status(ToString(r.summary.status));
  const std::string detail = r.summary.message.empty()                  ? status
                             : r.summary.message.rfind(status, 0) == 0 ? r.summary.message
                                                                       : status + ": " + r.summary.message;
  text += "status: " + std::string(r.box.IsEmpty() ? "empty" : "nonempty") + " (" + detail + ")\n";
  if (!r.box.IsEmpty()) {
    std::size_t width = 0;
    for (const auto& name : r.csp.names()) width = std::max(width, name.size());
    for (int i = 0; i < r.csp.num_variables(); ++i) {
      std::string name = r.csp.names()[i];
      name.resize(width, ' ');
      text += "  " + name + " in [" + Bound(r.box[i].lo()) + ", " + Bound(r.box[i].hi()) + "]\n";
    }
  }
  if (r.relaxed) {
    text += "q: " + std::to_string(r.q) + " (outliers allowed)\n";
    text += "estimate: " + r.estimate_kind;
    for (const Property& p : r.estimate_extras)
      std::visit([&](const auto& v) {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) text += ", " + p.name + " " + v;
        else text += ", " + p.name + " " + FormatDouble(static_cast<double>(v));
      }, p.value);
    text += "\n";
  }
  text += "revise_calls: " + std::to_string(r.summary.work.revise_calls) + "\n";
  text += "time_s: " + Bound(r.time_s) + "\n";
  return text;
}

}  // namespace icp
