#include "experiments/thesis003/marina.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "experiments/thesis003/guarantee_columns.h"
#include "harness/guarantee.h"
#include "harness/metrics.h"

namespace icp {

namespace {

constexpr const char* kDash = "—";

bool OfMarina(const RunRecord& r) { return IsMarinaExperiment(ExperimentOf(r)); }

bool HasMarinaRun(const GroupSummary& g) {
  return std::any_of(g.runs.begin(), g.runs.end(), [](const RunRecord* r) { return OfMarina(*r); });
}

std::string Cell(double v) { return std::isnan(v) ? kDash : FormatNumber(v); }

}  // namespace

bool IsMarinaExperiment(const std::string& e) {
  return e == kThesis003Marina || e.rfind(std::string(kThesis003Marina) + "-", 0) == 0;
}

// A run's solve time summed over its steps.
double RunSolveTime(const RunRecord& r) {
  double total = 0;
  for (const StepRecord& s : r.steps) total += s.solve_time_s;
  return r.steps.empty() ? std::numeric_limits<double>::quiet_NaN() : total;
}

TextTable MarinaTable(const std::vector<RunRecord>& runs) {
  std::vector<const GroupSummary*> groups;
  const std::vector<GroupSummary> all = SummariseGroups(runs);
  std::vector<double> step_times;
  for (const GroupSummary& g : all) {
    if (!HasMarinaRun(g)) continue;
    groups.push_back(&g);
    step_times.push_back(g.metrics.time_median_s);
  }
  const Unit unit = TimeUnit(step_times);
  TextTable t;
  t.title = "Thesis 003 ch. 6: marina, set membership vs particle filter";
  t.headers = {"configuration",     "problem",          "runs",
               "steps",             "consistency",      "centre RMSE (m) [95% CI]",
               "median error (m)",  "restarts per run",
               "median time per step (" + unit.name + ")", "time per run (s) [95% CI]"};
  t.numeric = {false, false, true, true, true, true, true, true, true, true};
  for (const std::string& h : GuaranteeHeaders()) t.headers.push_back(h);
  for (bool n : GuaranteeNumeric()) t.numeric.push_back(n);
  for (const GroupSummary* group : groups) {
    const GroupSummary& g = *group;
    int steps = 0, known = 0, contained = 0;
    std::vector<double> errors, times, restarts;
    for (const RunRecord* r : g.ok_runs) {
      for (const StepRecord& s : r->steps) {
        ++steps;
        if (s.contained >= 0) ++known, contained += s.contained;
        if (std::isfinite(s.centre_error)) errors.push_back(s.centre_error);
        times.push_back(s.solve_time_s);
      }
      if (const std::optional<double> n = RunRestarts(*r)) restarts.push_back(*n);
    }
    t.rows.push_back({WithParams(DisplayOf(g.algorithm).label, g.algorithm_params),
                      WithParams(g.problem, g.problem_params), OkRunsCell(g), std::to_string(steps),
                      FormatRatio(contained, known),
                      FormatWithInterval(RunMedian(g, [](const RunRecord& r) { return r.metrics.centre_rmse; })),
                      Cell(Quantile(errors, 0.5)), Cell(Mean(restarts)),
                      Cell(Quantile(times, 0.5) * unit.scale),
                      FormatWithInterval(RunMedian(g, RunSolveTime))});
    for (std::string& c : GuaranteeCells(g)) t.rows.back().push_back(std::move(c));
    for (const std::string& p : g.problems) t.items.push_back(ProblemItem(g, p));
  }
  // The thesis' own figures for its 600 m run (§6.7), for comparison.
  t.rows.push_back({"published: set membership, C/C++", "the Girona marina data set, 600 m", kDash,
                    kDash, kDash, kDash, kDash, kDash, kDash,
                    FormatNumber(kThesis003SetMembershipRunS)});
  t.rows.push_back({"published: particle filter, 600 particles, Matlab",
                    "the Girona marina data set, 600 m", kDash, kDash, kDash, kDash, kDash, kDash,
                    kDash, FormatNumber(kThesis003ParticleFilterRunS)});
  for (std::vector<std::string>& row : t.rows) row.resize(t.headers.size(), kDash);
  t.notes.push_back(
      "Every configuration with a run of experiment marina or marina-*, over the steps of its "
      "ok runs (every seed). Consistency: share of the steps whose estimate holds the truth (the "
      "particle filter's region, its weighted 95% box or hull, is not a guaranteed enclosure). "
      "Centre error: distance from the box centre (the filter: its weighted mean) to the truth; "
      "centre RMSE and time per run: each run's, then the median over the runs (seeds) with its "
      "95% confidence interval (order statistics, from 6 runs on). "
      "Restarts: the set-membership solver's global searches after a detected inconsistency "
      "(run property resets), the filter's reinitialisations after every particle lost all "
      "weight. Time per run: the estimator's solve time summed over the steps. Published: paper "
      "003 §6.7, one core of a Centrino Duo T2500 at 2 GHz (1 h 10 min) and Matlab on a Core2 at "
      "2.2 GHz (31 min), on the real data set, which is not available here: the rows above are "
      "the simulated marina of problems/marina_sonar.");
  t.notes.push_back(GuaranteeNote());
  if (t.rows.size() == 2)
    t.notes.push_back("No run of experiment marina or marina-* in the store (specs/marina.yaml).");
  return t;
}

}  // namespace icp
