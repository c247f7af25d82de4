// The entry points of `icpbench plot`: the caller's figures then the generic
// ones (fig_timing, the performance profiles) from runs or a store's
// directory; a run's label in figures.
#include "plots/figures.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "plots/figures_internal.h"
#include "report/report.h"

namespace icp {

std::string RunLabel(const RunRecord& r) {
  std::string label = WithParams(r.spec.algorithm, r.spec.algorithm_params) + " (seed " +
                      std::to_string(r.spec.seed);
  if (!r.spec.problem_params.empty()) label += ", " + CompactParams(r.spec.problem_params);
  return label + ")";
}

PlotOutput PlotRuns(const std::vector<RunRecord>& runs, const std::string& out_dir,
                    const FigureMaker& more) {
  std::filesystem::create_directories(out_dir);
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
