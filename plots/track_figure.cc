// A run drawn on its map: the map's pixels, the true trajectory, each run's
// estimate centres and, every few steps, its x-y boxes (the marina tracks).
#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/metrics.h"
#include "plots/figures.h"
#include "plots/figures_internal.h"

namespace icp {

namespace {
// The centre of a step's estimate on (x, y) = vars 0, 1: the properties
// mean_<name> when present, else the middle of the hull; NaN when empty.
std::pair<double, double> StepCentre(const StepRecord& s) {
  if (s.vars.size() < 2) return {kNaN, kNaN};
  double c[2];
  for (int i = 0; i < 2; ++i) {
    const VariableRecord& v = s.vars[i];
    const std::optional<double> mean = NumberProperty(s.properties, "mean_" + v.name);
    c[i] = mean ? *mean : v.lo <= v.hi ? Finite((v.lo + v.hi) / 2) : kNaN;
  }
  return {c[0], c[1]};
}
}  // namespace

namespace detail::plots {

Series MapSeries(const std::vector<std::pair<double, double>>& points) {
  Series map{"using 1:2 with dots lc rgb '#9a9a9a' title 'map'", {}, ""};
  for (const auto& [x, y] : points) map.rows.push_back({x, y});
  return map;
}

Series TruthSeries(const RunRecord& run) {
  Series truth{"using 1:2 with lines lw 2 lc rgb 'black' title 'truth'", {}, ""};
  for (const StepRecord& s : run.steps)
    if (s.vars.size() >= 2) truth.rows.push_back({s.vars[0].truth, s.vars[1].truth});
  return truth;
}

Series BoxesSeries(const RunRecord& run, int every, const std::string& title) {
  Series boxes{"using 1:2:3:4 with boxxyerror fs empty lw 0.6 lc rgb " +
                   Quote(Colour(run.spec.algorithm)) +
                   (title.empty() ? " notitle" : " title " + Quote(title)),
               {}, ""};
  for (std::size_t i = 0; i < run.steps.size(); i += std::max(1, every)) {
    const StepRecord& s = run.steps[i];
    if (s.vars.size() < 2 || IsEmptyEstimate(s)) continue;
    const VariableRecord &x = s.vars[0], &y = s.vars[1];
    boxes.rows.push_back({Finite((x.lo + x.hi) / 2), Finite((y.lo + y.hi) / 2),
                          Finite((x.hi - x.lo) / 2), Finite((y.hi - y.lo) / 2)});
  }
  return boxes;
}

}  // namespace detail::plots

void PlotTrackFigure(const FigureText& text,
                     const std::vector<std::pair<double, double>>& wall_points,
                     const std::vector<const RunRecord*>& runs, int boxes_every,
                     const std::string& out_dir, PlotOutput* out) {
  // The truth is drawn from the first run with steps; runs stored without
  // them (record: runs) draw nothing and are named.
  const auto first = std::find_if(runs.begin(), runs.end(),
                                  [](const RunRecord* r) { return !r->steps.empty(); });
  if (first == runs.end()) return Skip(text, out, runs);
  NoteRunsOnly(text, runs, out);
  Panel panel;
  panel.setup = "set title " + MultiLine(text.title) +
                " noenhanced\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset size ratio -1\n"
                "set key outside bottom center horizontal noenhanced\n";
  Series walls = MapSeries(wall_points);
  if (HasPoint(walls)) panel.series.push_back(std::move(walls));
  Series truth = TruthSeries(**first);
  if (HasPoint(truth)) panel.series.push_back(std::move(truth));
  for (const RunRecord* r : runs) {
    const std::string colour = Quote(Colour(r->spec.algorithm));
    const bool particles = !r->steps.empty() && r->steps[0].estimate == "particles";
    if (boxes_every > 0 && !particles) {
      Series boxes = BoxesSeries(*r, boxes_every, "");
      if (HasPoint(boxes)) panel.series.push_back(std::move(boxes));
    }
    Series centres{"using 1:2 with lines lw 1.2 lc rgb " + colour + " title " +
                       Quote(RunLabel(*r) + (particles ? ": weighted mean" : ": box centre")),
                   {}, ""};
    for (const StepRecord& s : r->steps) {
      const auto [x, y] = StepCentre(s);
      centres.rows.push_back({x, y});
    }
    if (HasPoint(centres)) panel.series.push_back(std::move(centres));
  }
  RenderPanel(text.name, kPrintWidthIn, kPrintWidthIn, panel, out_dir, out);
}

}  // namespace icp
