#include "experiments/paper000/own_experiments.h"

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>

#include "harness/spec.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string Label(const GroupSummary& g) {
  return WithParams(DisplayOf(g.algorithm).label, g.algorithm_params);
}

// The width of variable `name` of the step's newest state; NaN when absent
// or empty.
double Width(const StepRecord& s, const std::string& name) {
  for (const auto& v : s.vars)
    if (v.name == name && v.hi >= v.lo) return v.hi - v.lo;
  return kNaN;
}

// The heading width at step index `at` (from the end when negative).
std::function<double(const RunRecord&)> HeadingAt(int at) {
  return [at](const RunRecord& r) {
    const int n = static_cast<int>(r.steps.size());
    const int i = at >= 0 ? at : n + at;
    return i >= 0 && i < n ? Width(r.steps[i], "theta") : kNaN;
  };
}

double Consistency(const RunRecord& r) { return r.metrics.consistency_rate; }

// A numeric problem parameter of the run, its default when not given.
std::optional<double> ProblemParam(const RunRecord& r, const std::string& name) {
  auto it = r.spec.problem_params.find(name);
  std::string text;
  if (it != r.spec.problem_params.end()) {
    text = it->second;
  } else {
    const ParamMap defaults = ProblemDefaults(r.spec.problem);
    auto d = defaults.find(name);
    if (d == defaults.end()) return std::nullopt;
    text = d->second;
  }
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Over the steps in [from, to) of the run: the mean x-y area (`area`) or
// the share holding the truth; NaN when none is there.
double OverSteps(const RunRecord& r, double from, double to, bool area) {
  double total = 0;
  int n = 0;
  for (const StepRecord& s : r.steps) {
    if (s.step < from || s.step >= to) continue;
    if (area && std::isfinite(s.area)) total += s.area, ++n;
    if (!area && s.contained >= 0) total += s.contained, ++n;
  }
  return n > 0 ? total / n : kNaN;
}

// Relative to the run's outage: `offset` outage lengths after its start.
std::function<double(const RunRecord&)> OutageWindow(double offset, bool area) {
  return [offset, area](const RunRecord& r) {
    const std::optional<double> start = ProblemParam(r, "outage_start");
    const std::optional<double> length = ProblemParam(r, "outage_length");
    if (!start || !length || *length <= 0) return kNaN;
    const double from = *start + offset * *length;
    return OverSteps(r, from, from + *length, area);
  };
}

using RunValue = std::function<double(const RunRecord&)>;

// A table of one experiment: per configuration with ok runs, its label,
// problem parameters and ok runs, then the median over the runs (seeds) of
// each value with its 95 % interval; omitted, with a note naming the spec,
// when the store has no run of it.
TextTable ExperimentTable(const std::vector<GroupSummary>& groups, const std::string& experiment,
                          const std::string& title, const std::vector<std::string>& headers,
                          const std::vector<RunValue>& values, const std::string& note) {
  TextTable t;
  t.title = title;
  t.headers = {"configuration", "problem params", "runs"};
  t.headers.insert(t.headers.end(), headers.begin(), headers.end());
  t.numeric = {false, false, true};
  t.numeric.resize(t.headers.size(), true);
  for (const GroupSummary& g : groups) {
    if (!HasExperiment(g, experiment) || g.ok_runs.empty()) continue;
    t.rows.push_back({Label(g), ParamsCell(g.problem_params), std::to_string(g.ok)});
    for (const RunValue& value : values)
      t.rows.back().push_back(FormatWithInterval(RunMedian(g, value)));
  }
  t.notes.push_back(note);
  if (t.rows.empty())
    t.notes.push_back("No run of experiment " + experiment +
                      ": icpbench run specs/default.yaml makes them.");
  t.omit_if_empty = true;
  return t;
}

TextTable StartTable(const std::vector<GroupSummary>& groups) {
  return ExperimentTable(
      groups, "start", "Heading unknown at the start (experiment start, car-track)",
      {"heading width, step 1 (rad)", "step 20 (rad)", "last step (rad)", "truth held"},
      {HeadingAt(0), HeadingAt(19), HeadingAt(-1), Consistency},
      "Each window's first heading starts in [-pi, pi] (paper 000, \"[theta_k] is initialized "
      "to ]-pi, pi]\"), with no GPS heading. The newest state's heading width at each step, "
      "median over the runs (seeds) with its 95% interval; truth held: the share of steps "
      "whose box holds the true state.");
}

TextTable OutageTable(const std::vector<GroupSummary>& groups) {
  return ExperimentTable(
      groups, "outage", "GPS outage (experiment outage, car-track)",
      {"area before (m²)", "during (m²)", "after (m²)", "truth held during"},
      {OutageWindow(-1, true), OutageWindow(0, true), OutageWindow(1, true),
       OutageWindow(0, false)},
      "GPS lost for outage_length steps from outage_start: the speed and the gyro alone "
      "carry the box (dead reckoning) while the window still holds the last fixes. Mean x-y "
      "area of the newest state over the outage_length steps before the outage, during it and "
      "after it; truth held: the share of the outage's steps whose box holds the true state. "
      "Medians over the runs (seeds) with their 95% intervals.");
}

}  // namespace

std::vector<TextTable> Paper000OwnExperimentTables(const std::vector<RunRecord>& runs) {
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  return {StartTable(groups), OutageTable(groups)};
}

}  // namespace icp
