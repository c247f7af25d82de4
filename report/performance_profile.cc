// Performance profiles: the ratios to each instance's best, rho(tau), and the
// report's table of them.
#include "report/performance_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <utility>

namespace icp {

namespace {

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

double Ratio(double value, double best) {
  if (best > 0) return value / best;
  return value == best ? 1 : std::numeric_limits<double>::infinity();
}

}  // namespace

PerformanceProfile ComputeProfile(const std::vector<ProfileEntry>& entries) {
  std::vector<std::string> solvers;
  std::map<std::string, std::map<std::string, std::vector<double>>> values;  // solver, instance
  std::map<std::string, double> best;                                        // by instance
  for (const ProfileEntry& e : entries) {
    if (values.count(e.solver) == 0) solvers.push_back(e.solver);
    std::vector<double>& v = values[e.solver][e.instance];
    if (std::isfinite(e.value)) v.push_back(e.value);
    best.emplace(e.instance, std::numeric_limits<double>::infinity());
  }
  // The solvers' medians, then the best of each instance.
  std::map<std::string, std::map<std::string, double>> medians;
  for (const auto& [solver, by_instance] : values) {
    for (const auto& [instance, v] : by_instance) {
      if (v.empty()) continue;
      const double m = Median(v);
      medians[solver][instance] = m;
      best[instance] = std::min(best[instance], m);
    }
  }
  PerformanceProfile profile;
  profile.instances = static_cast<int>(best.size());
  for (const std::string& solver : solvers) {
    SolverProfile s{solver, static_cast<int>(medians[solver].size()), {}};
    for (const auto& [instance, m] : medians[solver]) {
      const double r = Ratio(m, best[instance]);
      if (std::isfinite(r)) s.ratios.push_back(r);
    }
    std::sort(s.ratios.begin(), s.ratios.end());
    profile.solvers.push_back(std::move(s));
  }
  return profile;
}

double Rho(const PerformanceProfile& profile, const SolverProfile& solver, double tau) {
  if (profile.instances == 0) return 0;
  // A ratio equal to tau up to rounding (v / b computed, tau typed) counts.
  const auto within = std::upper_bound(solver.ratios.begin(), solver.ratios.end(),
                                       tau * (1 + 1e-12));
  return static_cast<double>(within - solver.ratios.begin()) / profile.instances;
}

std::string FormatShare(double rho) {
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", rho);
  return text;
}

std::string ProfileSolver(const RunRecord& run) {
  return WithParams(DisplayOf(run.spec.algorithm).label, run.spec.algorithm_params);
}

std::string ProfileMetricName(ProfileMetric metric) {
  return metric == ProfileMetric::kTime ? "time per CSP" : "mean x-y area";
}

PerformanceProfile RunsProfile(const std::vector<RunRecord>& runs, ProfileMetric metric) {
  std::vector<const RunRecord*> ordered;
  for (const RunRecord& r : runs) ordered.push_back(&r);
  std::stable_sort(ordered.begin(), ordered.end(), [](const RunRecord* a, const RunRecord* b) {
    if (a->spec.algorithm != b->spec.algorithm)
      return AlgorithmLess(a->spec.algorithm, b->spec.algorithm);
    return CompactParams(a->spec.algorithm_params) < CompactParams(b->spec.algorithm_params);
  });
  std::vector<ProfileEntry> entries;
  for (const RunRecord* r : ordered) {
    const double value = metric == ProfileMetric::kTime ? r->metrics.time_mean_s
                                                        : r->metrics.mean_area;
    entries.push_back({ProfileSolver(*r),
                       r->spec.problem + " " + CompactParams(r->spec.problem_params) + " seed " +
                           std::to_string(r->spec.seed),
                       r->status == RunStatus::kOk ? value
                                                   : std::numeric_limits<double>::quiet_NaN()});
  }
  return ComputeProfile(entries);
}

TextTable ProfileTable(const std::vector<RunRecord>& runs, ProfileMetric metric) {
  const bool time = metric == ProfileMetric::kTime;
  const PerformanceProfile profile = RunsProfile(runs, metric);
  TextTable t;
  t.title = "Performance profile, " + ProfileMetricName(metric) +
            ": share ρ(τ) of the " + std::to_string(profile.instances) +
            " instances within a factor τ of the best";
  t.headers = {"configuration", "solved"};
  t.numeric = {false, true};
  for (double tau : kProfileTaus) {
    t.headers.push_back("τ = " + FormatNumber(tau));
    t.numeric.push_back(true);
  }
  for (const SolverProfile& s : profile.solvers) {
    std::vector<std::string> row = {s.solver, std::to_string(s.solved)};
    for (double tau : kProfileTaus) row.push_back(FormatShare(Rho(profile, s, tau)));
    t.rows.push_back(std::move(row));
  }
  t.omit_if_empty = true;
  t.notes.push_back(
      "Dolan and Moré's performance profile over every problem instance of the store (a problem "
      "with its parameters and seed): ρ(τ) is the share of the instances on which the "
      "configuration's " +
      std::string(time ? "mean solve time per CSP" : "mean x-y area") +
      " is at most τ times the least of any configuration there (the median over its runs "
      "there when it has several). solved counts the instances where it has an ok run with a "
      "defined " +
      std::string(time ? "time" : "area (not every box empty)") +
      "; a failed, timed-out or skipped run, or an instance it never ran, counts as not solved, "
      "so ρ tends to solved / instances, not to 1." +
      (time ? std::string()
            : " The area says how tight an estimate is, not whether it holds the truth (the "
              "consistency column of the runs table does), and a particle filter's is the box "
              "of 95 % of its weight, not an enclosure."));
  if (t.rows.empty()) t.notes.push_back("No run in the store.");
  return t;
}

}  // namespace icp
