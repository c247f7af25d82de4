// The sweep figure: mean areas and mean time per CSP against the value of a
// swept problem parameter, one line per configuration.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "plots/figures.h"
#include "plots/figures_internal.h"
#include "report/report.h"

namespace icp {

void PlotSweepFigure(const FigureText& text, const std::string& x_label,
                     const std::vector<SweepPoint>& points, const std::string& out_dir,
                     PlotOutput* out) {
  if (points.empty()) return Skip(text, out);
  // The areas and times come from the run metrics, which every ok run has;
  // the window states' area is a step property, which runs stored with
  // `record: runs` lack.
  std::vector<const RunRecord*> runs;
  for (const SweepPoint& p : points) runs.insert(runs.end(), p.ok_runs.begin(), p.ok_runs.end());
  if (const std::vector<const RunRecord*> runs_only = RunsOnlyOf(runs); !runs_only.empty())
    out->messages.push_back(text.name +
                            ": drawn from the run metrics; the mean area of the window states (a "
                            "step property) lacks " +
                            RunCount(runs_only.size()) + " " + RecordedWithRunsOnly(runs_only));
  const bool window_area = std::any_of(points.begin(), points.end(), [](const SweepPoint& p) {
    return std::isfinite(p.mean_window_area);
  });
  Figure f;
  f.name = text.name;
  f.title = text.title;
  f.cols = window_area ? 3 : 2;
  f.width_in = 5 * f.cols;
  f.height_in = 4.2;
  Panel area, window, time;
  area.setup = "set title 'Mean x-y area of the newest state'\nset xlabel " + Quote(x_label) +
               "\nset ylabel 'area (m^2)'\nset key top right noenhanced\n";
  window.setup = "set title 'Mean x-y area of the window states'\nset xlabel " +
                 Quote(x_label) + "\nset ylabel 'area (m^2)'\nset key top right noenhanced\n";
  time.setup = "set title 'Mean time per CSP'\nset xlabel " + Quote(x_label) +
               "\nset ylabel 'time (ms)'\nset key top left noenhanced\n";
  // An algorithm's colour for all its configurations; its second, third ...
  // configuration dashed and marked differently, so they stay apart.
  std::map<std::string, int> configurations;
  for (std::size_t i = 0; i < points.size();) {
    const std::string& label = points[i].label;
    const int nth = configurations[points[i].algorithm]++;
    const std::string style = "with linespoints lw 2 dt " + std::to_string(1 + nth % 5) + " pt " +
                              std::to_string(7 + 2 * (nth % 3)) + " ps 0.7 lc rgb " +
                              Quote(Colour(points[i].algorithm)) + " title " + Quote(label);
    Series a{"using 1:2 " + style, {}, ""};
    Series w{"using 1:2 " + style, {}, ""};
    Series t{"using 1:2 " + style, {}, ""};
    for (; i < points.size() && points[i].label == label; ++i) {
      a.rows.push_back({points[i].value, Finite(points[i].mean_area)});
      w.rows.push_back({points[i].value, Finite(points[i].mean_window_area)});
      t.rows.push_back({points[i].value, Finite(points[i].mean_time_s * 1e3)});
    }
    area.series.push_back(std::move(a));
    if (HasPoint(w)) window.series.push_back(std::move(w));
    time.series.push_back(std::move(t));
  }
  f.panels = {area};
  if (window_area) f.panels.push_back(window);
  f.panels.push_back(time);
  Render(f, out_dir, out);
}

}  // namespace icp
