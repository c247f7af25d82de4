// Runs side by side on their map, each panel one run's boxes at every step
// over the truth: how wide a set estimate grows along a route (thesis 003
// Fig. 4.17: dead reckoning, then the same with the road map).
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "plots/figures.h"
#include "plots/figures_internal.h"

namespace icp {

void PlotBoxTrackFigure(const FigureText& text,
                        const std::vector<std::pair<double, double>>& map_points,
                        const std::vector<std::pair<std::string, const RunRecord*>>& panels,
                        const Interval& x, const Interval& y, const std::string& out_dir,
                        PlotOutput* out) {
  std::vector<const RunRecord*> runs;
  for (const auto& [title, run] : panels) runs.push_back(run);
  for (const RunRecord* r : runs)
    if (r->steps.empty()) return Skip(text, out, runs);
  if (runs.empty()) return Skip(text, out);
  Figure f;
  f.name = text.name;
  f.title = text.title;
  f.cols = static_cast<int>(panels.size());
  f.footer_in = FooterHeight({"map", "box of every step", "truth"});
  f.height_in = std::min(kPrintMaxHeightIn, 1.2 + kPrintWidthIn / f.cols);
  for (const auto& [title, run] : panels) {
    Panel panel;
    const bool last = run == panels.back().second;
    panel.setup = "set title " + MultiLine(Wrapped(title, kPrintWidthIn / f.cols)) +
                  " noenhanced\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset size ratio -1\n"
                  "set xrange [" +
                  std::to_string(x.lo()) + ":" + std::to_string(x.hi()) + "]\nset yrange [" +
                  std::to_string(y.lo()) + ":" + std::to_string(y.hi()) + "]\n" +
                  (last ? kFooterKey : "unset key\n");
    Series map = MapSeries(map_points);
    if (HasPoint(map)) panel.series.push_back(std::move(map));
    Series boxes = BoxesSeries(*run, 1, "box of every step");
    if (HasPoint(boxes)) panel.series.push_back(std::move(boxes));
    Series truth = TruthSeries(*run);
    if (HasPoint(truth)) panel.series.push_back(std::move(truth));
    f.panels.push_back(std::move(panel));
  }
  Render(f, out_dir, out);
}

}  // namespace icp
