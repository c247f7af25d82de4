// The generic table of the report: runs per configuration (aggregated over
// seeds) with its failure list, and the same table as CSV.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "report/report.h"
#include "report/report_internal.h"

namespace icp::detail::report {

namespace {

constexpr int kMaxProblemLines = 20;  // failure list below table 1

std::string RunsCell(const GroupSummary& g) {
  if (g.failed == 0 && g.timeout == 0 && g.skipped == 0) return std::to_string(g.ok);
  std::string out = std::to_string(g.ok) + " ok";
  for (const auto& [count, name] : {std::pair<int, const char*>{g.failed, "failed"},
                                    {g.timeout, "timeout"},
                                    {g.skipped, "skipped"}}) {
    if (count > 0) out += ", " + std::to_string(count) + " " + name;
  }
  return out;
}

}  // namespace

// The runs-per-configuration table and its failure list.
TextTable GroupTable(const std::vector<GroupSummary>& groups) {
  TextTable t;
  t.title = "Runs per configuration (aggregated over seeds)";
  // One time unit for the three time columns, from their values.
  std::vector<double> times;
  for (const GroupSummary& g : groups)
    times.insert(times.end(), {g.metrics.time_median_s, g.metrics.time_p90_s, g.metrics.time_mean_s});
  const Unit unit = TimeUnit(times);
  t.headers = {"algorithm", "params", "problem", "params", "runs", "CSPs",
               "mean area (m²) [95% CI]", "consistency", "centre RMSE (m)",
               "time median (" + unit.name + ")", "time p90 (" + unit.name + ")",
               "time mean (" + unit.name + ") [95% CI]"};
  t.numeric = {false, false, false, false, true, true, true, true, true, true, true, true};
  int listed = 0, unlisted = 0;
  for (const GroupSummary& g : groups) {
    const RunMetrics& m = g.metrics;
    t.rows.push_back({g.algorithm, ParamsCell(g.algorithm_params), g.problem,
                      ParamsCell(g.problem_params), RunsCell(g), std::to_string(m.steps),
                      FormatWithInterval(RunMedian(g, RunMeanArea)),
                      FormatNumber(m.consistency_rate), FormatNumber(m.centre_rmse),
                      FormatNumber(m.time_median_s * unit.scale),
                      FormatNumber(m.time_p90_s * unit.scale),
                      FormatWithInterval(RunMedian(g, RunMeanTime), unit.scale)});
    for (const std::string& p : g.problems) {
      if (listed == kMaxProblemLines) {
        ++unlisted;
        continue;
      }
      ++listed;
      t.items.push_back(ProblemItem(g, p));
    }
  }
  if (unlisted > 0) t.items.push_back("… and " + std::to_string(unlisted) + " more");
  t.notes.push_back(
      "Mean area and time mean: the median over the ok runs (one per seed) of each run's mean, "
      "with the 95% confidence interval of that median from order statistics (from 6 runs "
      "on; fewer give the median alone), rounded to the interval's leading digit. "
      "Consistency (share of CSPs whose box holds the truth, paper 004 eq. 31), centre RMSE "
      "and the time median and p90: over the CSPs of the ok runs, pooled across seeds. Times "
      "per CSP.");
  if (std::any_of(groups.begin(), groups.end(), [](const GroupSummary& g) { return !g.pooled; })) {
    t.notes.push_back(
        "Groups whose runs have no step records combine the stored run metrics; their time "
        "median and p90 are shown only for a single run.");
  }
  if (!t.items.empty()) t.notes.push_back("Runs that did not finish ok:");
  return t;
}

std::string GroupCsv(const std::vector<GroupSummary>& groups) {
  std::ostringstream out;
  out << "algorithm,algorithm_params,problem,problem_params,runs_ok,runs_failed,runs_timeout,"
         "runs_skipped,steps,mean_area_m2,consistency_rate,centre_rmse_m,time_median_us,"
         "time_p90_us,time_mean_us,time_mean_ci_lo_us,time_mean_ci_hi_us\n";
  for (const GroupSummary& g : groups) {
    const RunMetrics& m = g.metrics;
    const std::vector<std::string> fields = {
        g.algorithm, CompactParams(g.algorithm_params), g.problem, CompactParams(g.problem_params),
        std::to_string(g.ok), std::to_string(g.failed), std::to_string(g.timeout),
        std::to_string(g.skipped), std::to_string(m.steps), FormatCsvNumber(m.mean_area),
        FormatCsvNumber(m.consistency_rate), FormatCsvNumber(m.centre_rmse),
        FormatCsvNumber(m.time_median_s * 1e6), FormatCsvNumber(m.time_p90_s * 1e6),
        FormatCsvNumber(m.time_mean_s * 1e6), FormatCsvNumber(m.time_mean_ci_lo_s * 1e6),
        FormatCsvNumber(m.time_mean_ci_hi_s * 1e6)};
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << CsvField(fields[i]);
    out << "\n";
  }
  return out.str();
}

}  // namespace icp::detail::report
