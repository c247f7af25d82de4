// Performance profiles (Dolan and Moré, Math. Program. 91, 2002): for each
// solver, the share rho(tau) of the instances on which its value is within a
// factor tau of the best solver's there. One implementation for the report's
// tables, the figures (plots/), the paper and the results browser's
// /api/profile (web/), which each only choose what a solver and an instance
// are.
//
// The rules: a solver's value on an instance is the median of its values
// there (the repeats of a run, or the configurations a coarser grouping
// pools); it has none, and so does not solve the instance, when none of its
// runs there is ok with a finite value (failed, timed-out and skipped runs,
// and instances it never ran, count as not solved). The best is the least
// value on the instance; the ratio of a value v to the best b is v / b, 1
// when both are 0 and infinite (never within a factor) when only b is. The
// denominator is every instance of the entries, solved or not, so rho(tau)
// of a solver tends to the share of instances it solves, not to 1.
#ifndef ICPBENCH_REPORT_PERFORMANCE_PROFILE_H_
#define ICPBENCH_REPORT_PERFORMANCE_PROFILE_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "report/report.h"

namespace icp {

// One run's value: lower is better; NaN when the run did not solve its
// instance (not ok, or no value).
struct ProfileEntry {
  std::string solver;
  std::string instance;
  double value = 0;
};

struct SolverProfile {
  std::string solver;
  int solved = 0;  // instances where it has a value
  // One ratio to the best per instance the solver solves, ascending; only
  // finite ratios.
  std::vector<double> ratios;
};

struct PerformanceProfile {
  int instances = 0;                   // distinct instances of the entries
  std::vector<SolverProfile> solvers;  // in the order of their first entry
};

PerformanceProfile ComputeProfile(const std::vector<ProfileEntry>& entries);

// The share of the profile's instances on which the solver is within a
// factor tau of the best (0 without instances).
double Rho(const PerformanceProfile& profile, const SolverProfile& solver, double tau);

// rho as the tables show it: two decimals (1/32 of the default store's
// instances is 0.03).
std::string FormatShare(double rho);

// What the report's and the paper's profiles compare: the runs' mean solve
// time per CSP, or their mean x-y area.
enum class ProfileMetric { kTime, kArea };

// The profile over a store's runs: a solver is an algorithm configuration
// (algorithm and its parameters, "hc4 {carry=none}"), an instance a problem
// configuration with its seed; solvers in display order (AlgorithmLess,
// then parameters).
PerformanceProfile RunsProfile(const std::vector<RunRecord>& runs, ProfileMetric metric);
// A run's solver in RunsProfile: "HC4 {carry=none}".
std::string ProfileSolver(const RunRecord& run);
// The figure's and table's name of a metric: "time per CSP", "mean x-y area".
std::string ProfileMetricName(ProfileMetric metric);

// The factors the tables give rho at.
inline constexpr double kProfileTaus[] = {1, 1.5, 2, 5, 10};

// The table of rho(tau) at kProfileTaus, one row per solver, with the
// instances it solves; notes say what it counts.
TextTable ProfileTable(const std::vector<RunRecord>& runs, ProfileMetric metric);

}  // namespace icp

#endif  // ICPBENCH_REPORT_PERFORMANCE_PROFILE_H_
