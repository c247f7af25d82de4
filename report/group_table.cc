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

std::string Micro(double seconds) { return FormatNumber(seconds * 1e6); }

std::string MeanWithInterval(double mean, double lo, double hi, double scale) {
  std::string out = FormatNumber(mean * scale);
  if (!std::isnan(lo) && !std::isnan(hi)) {
    out += " [" + FormatNumber(lo * scale) + ", " + FormatNumber(hi * scale) + "]";
  }
  return out;
}

}  // namespace

// The runs-per-configuration table and its failure list.
TextTable GroupTable(const std::vector<GroupSummary>& groups) {
  TextTable t;
  t.title = "Runs per configuration (aggregated over seeds)";
  t.headers = {"algorithm", "params",       "problem",          "params",
               "runs",      "CSPs",         "mean area (m²)",   "consistency",
               "centre RMSE (m)", "time median (µs)", "time p90 (µs)",
               "time mean (µs) [95% CI]"};
  t.numeric = {false, false, false, false, true, true, true, true, true, true, true, true};
  int listed = 0, unlisted = 0;
  for (const GroupSummary& g : groups) {
    const RunMetrics& m = g.metrics;
    t.rows.push_back({g.algorithm, ParamsCell(g.algorithm_params), g.problem,
                      ParamsCell(g.problem_params), RunsCell(g), std::to_string(m.steps),
                      FormatNumber(m.mean_area), FormatNumber(m.consistency_rate),
                      FormatNumber(m.centre_rmse), Micro(m.time_median_s), Micro(m.time_p90_s),
                      MeanWithInterval(m.time_mean_s, m.time_mean_ci_lo_s, m.time_mean_ci_hi_s,
                                       1e6)});
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
      "Metrics over the CSPs of the ok runs, pooled across seeds; consistency: share of CSPs "
      "whose box holds the truth (paper 004 eq. 31); times per CSP, 95% CI by bootstrap of "
      "the mean.");
  if (std::any_of(groups.begin(), groups.end(), [](const GroupSummary& g) { return !g.pooled; })) {
    t.notes.push_back(
        "Groups whose runs have no step records combine the stored run metrics; their median, "
        "p90 and CI are shown only for a single run.");
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
