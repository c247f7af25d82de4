// The generic figure fig_timing: a box plot of the solve times per CSP, one
// box per group, and the choice of the groups it shows.
#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "plots/figures.h"
#include "plots/figures_internal.h"
#include "report/report.h"

namespace icp {

void PlotTimingFigure(const FigureText& text, const std::vector<const GroupSummary*>& groups,
                      const std::string& out_dir, PlotOutput* out) {
  Panel panel;
  std::string xtics;
  std::vector<const RunRecord*> ok_runs;
  for (const GroupSummary* g : groups)
    ok_runs.insert(ok_runs.end(), g->ok_runs.begin(), g->ok_runs.end());
  for (const GroupSummary* g : groups) {
    const double x = static_cast<double>(panel.series.size() + 1);
    Series s{"using (" + std::to_string(x) + "):1 with boxplot lw 1.2 lc rgb " +
                 Quote(Colour(g->algorithm)) + " notitle",
             {}, ""};
    for (const RunRecord* r : g->ok_runs) {
      for (const StepRecord& step : r->steps) s.rows.push_back({Positive(step.solve_time_s * 1e6)});
    }
    if (!HasPoint(s)) continue;
    xtics += std::string(xtics.empty() ? "" : ", ") +
             Quote(WithParams(g->algorithm, g->algorithm_params)) + " " + std::to_string(x);
    panel.series.push_back(std::move(s));
  }
  if (panel.series.empty()) return Skip(text, out, ok_runs);
  NoteRunsOnly(text, ok_runs, out);
  panel.setup = "set title " + Quote(text.title) +
                " noenhanced\nset ylabel 'time per CSP (µs)'\nset logscale y\n"
                "set format y '10^{%L}'\nset style boxplot outliers pointtype 7\n"
                "set pointsize 0.3\nset boxwidth 0.5\n"
                "set xtics (" + xtics + ") noenhanced" +
                // Beyond six boxes the names would run into each other.
                (panel.series.size() > 6 ? " rotate by 30 right" : "") + "\nset xrange [0.4:" +
                std::to_string(panel.series.size() + 0.6) + "]\nset grid noxtics\n";
  RenderPanel(
      text.name,
      std::min(kPrintWidthIn, std::max(3.5, 0.9 * static_cast<double>(panel.series.size()) + 1.2)),
      3.4, panel, out_dir, out);
}

std::vector<const GroupSummary*> TimingGroups(const std::vector<GroupSummary>& groups,
                                              std::string* setting) {
  // (problem, problem params) -> (algorithms ok at default params, CSPs),
  // over the step rows stored: a merged store's configuration recorded with
  // `record: runs` has none to draw, and must not win over one that has.
  // With no step rows anywhere, the choice is made over the runs' counts, so
  // that the figure's skip can name the runs recorded without them.
  std::map<std::pair<std::string, ParamMap>, std::pair<int, std::size_t>> score;
  for (const bool stored_only : {true, false}) {
    for (const GroupSummary& g : groups) {
      if (!g.algorithm_params.empty() || g.ok == 0) continue;
      std::size_t stored = 0;
      for (const RunRecord* r : g.ok_runs) stored += r->steps.size();
      if (stored_only && stored == 0) continue;
      auto& [algorithms, steps] = score[{g.problem, g.problem_params}];
      ++algorithms;
      steps += stored_only ? stored : static_cast<std::size_t>(g.metrics.steps);
    }
    if (!score.empty()) break;
  }
  const auto best = std::max_element(score.begin(), score.end(), [](const auto& a, const auto& b) {
    return a.second < b.second;
  });
  std::vector<const GroupSummary*> chosen;
  if (best == score.end()) return chosen;
  const auto& [problem, problem_params] = best->first;
  *setting = problem + (problem_params.empty() ? "" : ", " + CompactParams(problem_params));
  for (const GroupSummary& g : groups) {  // groups are in algorithm order
    if (g.algorithm_params.empty() && g.ok > 0 && g.problem == problem &&
        g.problem_params == problem_params)
      chosen.push_back(&g);
  }
  return chosen;
}

}  // namespace icp
