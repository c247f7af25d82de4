// Runs aggregated by configuration: the groups of the tables (counts,
// problems, pooled metrics) and the points of a parameter sweep.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "harness/metrics.h"
#include "harness/spec.h"
#include "report/report.h"
#include "report/report_internal.h"

namespace icp {

using detail::report::OneLine;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxSeedsListed = 8;

bool ParseNumber(const std::string& text, double* value) {
  if (text.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return false;
  *value = v;
  return true;
}

// Numbers compare as numbers ("5" < "20"), anything else as text; a number
// sorts before a text.
bool NaturalLess(const std::string& a, const std::string& b) {
  double x, y;
  const bool xa = ParseNumber(a, &x);
  const bool yb = ParseNumber(b, &y);
  if (xa && yb && x != y) return x < y;
  if (xa != yb) return xa;
  return a < b;
}

bool ParamsLess(const ParamMap& a, const ParamMap& b) {
  auto i = a.begin();
  auto j = b.begin();
  for (; i != a.end() && j != b.end(); ++i, ++j) {
    if (i->first != j->first) return i->first < j->first;
    if (i->second != j->second) return NaturalLess(i->second, j->second);
  }
  return i == a.end() && j != b.end();
}

// Mean of values weighted by weights, skipping NaN values; NaN when no weight.
double WeightedMean(const std::vector<std::pair<double, double>>& value_weight) {
  double sum = 0, total = 0;
  for (const auto& [v, w] : value_weight) {
    if (std::isnan(v) || !(w > 0)) continue;
    sum += v * w;
    total += w;
  }
  return total > 0 ? sum / total : kNaN;
}

RunMetrics NaNMetrics() {
  RunMetrics m;
  m.mean_area = m.consistency_rate = m.centre_rmse = kNaN;
  m.time_mean_s = m.time_median_s = m.time_p90_s = kNaN;
  m.time_mean_ci_lo_s = m.time_mean_ci_hi_s = kNaN;
  return m;
}

// Combines stored run metrics when steps are not at hand (see report.h).
RunMetrics CombineRunMetrics(const std::vector<const RunRecord*>& runs) {
  if (runs.size() == 1) return runs[0]->metrics;
  RunMetrics m = NaNMetrics();
  std::vector<std::pair<double, double>> area, rate, square, time;
  for (const RunRecord* r : runs) {
    const double w = r->metrics.steps;
    m.steps += r->metrics.steps;
    area.emplace_back(r->metrics.mean_area, w);
    rate.emplace_back(r->metrics.consistency_rate, w);
    square.emplace_back(r->metrics.centre_rmse * r->metrics.centre_rmse, w);
    time.emplace_back(r->metrics.time_mean_s, w);
  }
  m.mean_area = WeightedMean(area);
  m.consistency_rate = WeightedMean(rate);
  m.centre_rmse = std::sqrt(WeightedMean(square));
  m.time_mean_s = WeightedMean(time);
  return m;
}

std::string SeedList(std::vector<std::uint64_t> seeds) {
  std::sort(seeds.begin(), seeds.end());
  std::string out = seeds.size() == 1 ? "seed " : "seeds ";
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    if (i == kMaxSeedsListed) {
      out += ", … (" + std::to_string(seeds.size()) + " runs)";
      break;
    }
    if (i > 0) out += ", ";
    out += std::to_string(seeds[i]);
  }
  return out;
}

// The run's steps' window_mean_area (see SweepPoint).
void AppendWindowAreas(const RunRecord& run, std::vector<double>* areas) {
  for (const StepRecord& s : run.steps) {
    if (auto a = NumberProperty(s.properties, "window_mean_area")) areas->push_back(*a);
  }
}

}  // namespace

double RunMeanWindowArea(const RunRecord& run) {
  std::vector<double> areas;
  AppendWindowAreas(run, &areas);
  return Mean(areas);
}

bool RecordedRunsOnly(const RunRecord& run) {
  return run.status == RunStatus::kOk && run.steps.empty() && run.metrics.steps > 0;
}

bool HasExperiment(const GroupSummary& group, const std::string& experiment) {
  return std::any_of(group.runs.begin(), group.runs.end(),
                     [&](const RunRecord* r) { return ExperimentOf(*r) == experiment; });
}

GroupSummary Summarise(const std::vector<const RunRecord*>& runs) {
  GroupSummary g;
  if (!runs.empty()) {
    g.algorithm = runs[0]->spec.algorithm;
    g.algorithm_params = runs[0]->spec.algorithm_params;
    g.problem = runs[0]->spec.problem;
    g.problem_params = runs[0]->spec.problem_params;
  }
  std::map<std::pair<RunStatus, std::string>, std::vector<std::uint64_t>> problems;
  bool all_have_steps = true;
  g.runs = runs;
  for (const RunRecord* r : runs) {
    switch (r->status) {
      case RunStatus::kOk:
        ++g.ok;
        g.ok_runs.push_back(r);
        if (r->steps.empty() && r->metrics.steps > 0) all_have_steps = false;
        continue;
      case RunStatus::kFailed:
        ++g.failed;
        break;
      case RunStatus::kTimeout:
        ++g.timeout;
        break;
      case RunStatus::kSkipped:
        ++g.skipped;
        break;
    }
    problems[{r->status, OneLine(r->reason)}].push_back(r->spec.seed);
  }
  for (const auto& [what, seeds] : problems) {
    std::string line = std::string(ToString(what.first)) + " (" + SeedList(seeds) + ")";
    if (!what.second.empty()) line += ": " + what.second;
    g.problems.push_back(line);
  }
  if (g.ok_runs.empty()) {
    g.metrics = NaNMetrics();
  } else if (all_have_steps) {
    std::vector<StepRecord> pooled;
    for (const RunRecord* r : g.ok_runs)
      pooled.insert(pooled.end(), r->steps.begin(), r->steps.end());
    g.metrics = ComputeMetrics(pooled);
  } else {
    g.pooled = false;
    g.metrics = CombineRunMetrics(g.ok_runs);
  }
  return g;
}

std::vector<GroupSummary> SummariseGroups(const std::vector<RunRecord>& runs) {
  using Key = std::tuple<std::string, ParamMap, std::string, ParamMap>;
  std::map<Key, std::vector<const RunRecord*>> by_key;
  for (const RunRecord& r : runs) {
    by_key[{r.spec.algorithm, r.spec.algorithm_params, r.spec.problem, r.spec.problem_params}]
        .push_back(&r);
  }
  std::vector<GroupSummary> groups;
  for (const auto& [key, members] : by_key) groups.push_back(Summarise(members));
  std::sort(groups.begin(), groups.end(), [](const GroupSummary& a, const GroupSummary& b) {
    if (a.problem != b.problem) return a.problem < b.problem;
    if (a.problem_params != b.problem_params) return ParamsLess(a.problem_params, b.problem_params);
    if (a.algorithm != b.algorithm) return AlgorithmLess(a.algorithm, b.algorithm);
    return ParamsLess(a.algorithm_params, b.algorithm_params);
  });
  return groups;
}

std::vector<SweepPoint> ParamSweep(const std::vector<RunRecord>& runs, const std::string& problem,
                                   const std::string& param) {
  const ParamMap defaults = ProblemDefaults(problem);
  const auto default_value = defaults.find(param);
  // configuration (algorithm, its params, problem params but param) -> value -> runs
  using Config = std::tuple<std::string, ParamMap, ParamMap>;
  std::map<Config, std::map<double, std::vector<const RunRecord*>>> configs;
  for (const RunRecord& r : runs) {
    if (r.spec.problem != problem || r.status != RunStatus::kOk) continue;
    const auto given = r.spec.problem_params.find(param);
    const std::string* text = given != r.spec.problem_params.end() ? &given->second
                              : default_value != defaults.end()    ? &default_value->second
                                                                   : nullptr;
    double value;
    if (!text || !ParseNumber(*text, &value)) continue;
    ParamMap others = r.spec.problem_params;
    others.erase(param);
    configs[{r.spec.algorithm, r.spec.algorithm_params, others}][value].push_back(&r);
  }
  std::vector<SweepPoint> points;
  for (const auto& [config, by_value] : configs) {
    if (by_value.size() < 2) continue;
    const auto& [algorithm, algorithm_params, others] = config;
    std::string label = WithParams(algorithm, algorithm_params);
    if (!others.empty()) label += " [" + CompactParams(others) + "]";
    for (const auto& [value, members] : by_value) {
      const GroupSummary g = Summarise(members);
      std::vector<double> window_areas;
      for (const RunRecord* r : members) AppendWindowAreas(*r, &window_areas);
      points.push_back({label, algorithm, value, g.ok, g.metrics.steps, g.metrics.mean_area,
                        g.metrics.time_mean_s, Mean(window_areas), members});
    }
  }
  std::stable_sort(points.begin(), points.end(), [](const SweepPoint& a, const SweepPoint& b) {
    if (a.algorithm != b.algorithm) return AlgorithmLess(a.algorithm, b.algorithm);
    if (a.label != b.label) return a.label < b.label;
    return a.value < b.value;
  });
  return points;
}

}  // namespace icp
