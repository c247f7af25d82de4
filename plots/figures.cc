// The entry points of `icpbench plot`: the caller's figures then the generic
// ones (fig_timing, the performance profiles) from runs or a store's
// directory; a run's label in figures.
#include "plots/figures.h"

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "harness/environment_error.h"
#include "harness/output_directory.h"
#include "plots/figures_internal.h"
#include "report/report.h"

namespace icp {

std::string RunLabel(const RunRecord& r) {
  std::string label = WithParams(r.spec.algorithm, r.spec.algorithm_params) + " (seed " +
                      std::to_string(r.spec.seed);
  if (!r.spec.problem_params.empty()) label += ", " + CompactParams(r.spec.problem_params);
  return label + ")";
}

namespace {

// A figure skipped now but drawn by an earlier plot into the same
// directory: its old files would pass for this store's (the paper and
// `serve` pick figures up by name). Messages "NAME: skipped: ..." name it.
void RemoveSkippedFigures(const PlotOutput& out, const std::string& out_dir) {
  const std::set<std::string> written(out.files.begin(), out.files.end());
  for (const std::string& m : out.messages) {
    const std::size_t colon = m.find(": skipped: ");
    if (colon == std::string::npos) continue;
    for (const char* ext : {".png", ".pdf", ".svg"}) {
      const std::string file = (std::filesystem::path(out_dir) / (m.substr(0, colon) + ext)).string();
      std::error_code ignored;  // nothing there is the usual case
      if (!written.count(file)) std::filesystem::remove(file, ignored);
    }
  }
}

}  // namespace

PlotOutput PlotRuns(const std::vector<RunRecord>& runs, const std::string& out_dir,
                    const FigureMaker& more) {
  CreateOutputDirectory(out_dir, kChooseAnotherOut);
  PlotOutput out;
  if (more) more(runs, out_dir, &out);
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  std::string setting;
  const std::vector<const GroupSummary*> timing = TimingGroups(groups, &setting);
  PlotTimingFigure({"fig_timing", "Solve time per CSP (" + setting + ")",
                    "no ok run with per-step solve times"},
                   timing, out_dir, &out);
  PlotProfileFigure({"fig_profile_time", "Performance profile: time per CSP",
                     "no ok run with a solve time"},
                    runs, ProfileMetric::kTime, out_dir, &out);
  PlotProfileFigure({"fig_profile_area", "Performance profile: mean x-y area",
                     "no ok run with an area"},
                    runs, ProfileMetric::kArea, out_dir, &out);
  std::vector<const RunRecord*> all;
  for (const RunRecord& r : runs) all.push_back(&r);
  if (const int n = CountRunsOnly(all); n > 0)
    out.messages.push_back("of the store's runs, " + RunsOnlyText(n) +
                           ": figures over steps (corridors, area, centre error, track, timing) "
                           "leave them out");
  RemoveSkippedFigures(out, out_dir);
  return out;
}

std::vector<std::string> PlotDirectory(const std::string& dir, const std::string& out_dir,
                                       std::vector<std::string>* messages,
                                       const FigureMaker& more) {
  PlotOutput out = PlotRuns(LoadRunsFromDirectory(dir), out_dir, more);
  if (messages) *messages = std::move(out.messages);
  return out.files;
}

}  // namespace icp
