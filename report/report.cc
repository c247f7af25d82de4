// The report of `icpbench report`: an overview line and the tables, in
// Markdown, LaTeX or CSV, from runs or a store's directory.
#include "report/report.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "harness/results_store.h"
#include "harness/spec.h"
#include "report/performance_profile.h"
#include "report/report_internal.h"

namespace icp {

using detail::report::GroupCsv;
using detail::report::GroupTable;
using detail::report::OneLine;
using detail::report::WriteMarkdown;

namespace {

// Distinct values of one provenance field over the runs, for the header.
std::string Distinct(const std::vector<RunRecord>& runs, std::string Provenance::*field) {
  std::set<std::string> values;
  for (const RunRecord& r : runs) {
    if (!(r.provenance.*field).empty()) values.insert(r.provenance.*field);
  }
  std::string out;
  for (const std::string& v : values) out += (out.empty() ? "" : "; ") + v;
  return out.empty() ? "unknown" : out;
}

std::string Overview(const std::vector<RunRecord>& runs) {
  int counts[4] = {0, 0, 0, 0};
  for (const RunRecord& r : runs) ++counts[static_cast<int>(r.status)];
  std::ostringstream out;
  out << runs.size() << " runs: " << counts[0] << " ok, " << counts[1] << " failed, "
      << counts[2] << " timeout, " << counts[3] << " skipped. Machines: "
      << Distinct(runs, &Provenance::machine)
      << ". Revisions: " << Distinct(runs, &Provenance::git_revision) << ".";
  std::set<std::string> revisions;
  for (const RunRecord& r : runs)
    if (r.status == RunStatus::kOk) revisions.insert(r.provenance.git_revision);
  if (revisions.size() > 1)
    out << " Note: the tables mix runs of " << revisions.size()
        << " code revisions; rerun with --force to measure one.";
  const auto runs_only = std::count_if(runs.begin(), runs.end(), RecordedRunsOnly);
  if (runs_only > 0)
    out << " Note: " << runs_only << (runs_only == 1 ? " ok run was" : " ok runs were")
        << " recorded with `record: runs` (run metrics only, no step rows): the runs per "
           "configuration table combines their stored metrics (median, p90 and CI only for a "
           "single run); tables over steps leave them out (rerun with record: steps to include "
           "them).";
  return out.str();
}

}  // namespace

std::string Report(const std::vector<RunRecord>& runs, const std::string& format,
                   const TableMaker& more) {
  if (format != "md" && format != "tex" && format != "csv") {
    throw std::invalid_argument("report format '" + format + "': must be one of md|tex|csv");
  }
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  if (format == "csv") return GroupCsv(groups);

  std::vector<TextTable> tables = {GroupTable(groups)};
  if (more) {
    for (TextTable& t : more(runs)) tables.push_back(std::move(t));
  }
  // Last, over every configuration of the store: the performance profiles.
  tables.push_back(ProfileTable(runs, ProfileMetric::kTime));
  tables.push_back(ProfileTable(runs, ProfileMetric::kArea));
  std::ostringstream out;
  if (format == "md") {
    out << "# icpbench report\n\n" << Overview(runs) << "\n\n";
    for (const TextTable& t : tables) WriteMarkdown(t, out);
  } else {
    out << "% icpbench report; needs \\usepackage{booktabs,graphicx,array}\n% " << OneLine(Overview(runs))
        << "\n\n";
    for (const TextTable& t : tables) out << TexTable(t);
  }
  return out.str();
}

std::vector<RunRecord> LoadRunsFromDirectory(const std::string& dir) {
  const std::string path = StorePath(dir);
  if (!std::filesystem::is_regular_file(path)) {
    throw std::runtime_error("no results store in '" + dir + "' (expected " + path + ")");
  }
  // Read-only: archived or another user's stores must be reportable.
  std::vector<RunRecord> runs = ResultsStore::OpenReadOnly(path)->LoadRuns(/*with_steps=*/true);
  for (RunRecord& r : runs) r.spec = WithoutDefaults(r.spec);
  return runs;
}

std::string ReportDirectory(const std::string& dir, const std::string& format,
                            const TableMaker& more) {
  if (format != "md" && format != "tex" && format != "csv") {
    throw std::invalid_argument("report format '" + format + "': must be one of md|tex|csv");
  }
  return Report(LoadRunsFromDirectory(dir), format, more);
}

}  // namespace icp
