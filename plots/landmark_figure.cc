// Paper 004 Fig. 8: a top view of how the landmarks' boxes shrink.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "harness/landmark_metrics.h"
#include "plots/figures.h"
#include "plots/figures_internal.h"
#include "report/report.h"

namespace icp {

void PlotLandmarkBoxesFigure(const FigureText& text, const RunRecord& run,
                             const std::vector<int>& steps, const std::string& out_dir,
                             PlotOutput* out) {
  using namespace detail::plots;
  // The true positions (run properties) and the car's true track.
  std::map<int, std::pair<double, double>> truth;
  for (const Property& p : run.properties) {
    int n = 0;
    char axis = 0;
    if (std::sscanf(p.name.c_str(), "L%d_truth_%c", &n, &axis) != 2) continue;
    if (const std::optional<double> v = NumberProperty({p}, p.name)) {
      if (axis == 'x') truth[n].first = *v;
      if (axis == 'y') truth[n].second = *v;
    }
  }
  std::vector<std::vector<double>> track;
  for (const StepRecord& s : run.steps) {
    double x = kNaN, y = kNaN;
    for (const VariableRecord& v : s.vars) {
      if (v.name == "x") x = v.truth;
      if (v.name == "y") y = v.truth;
    }
    track.push_back({x, y});
  }
  if (truth.empty() || run.steps.empty()) return Skip(text, out, {&run});
  // The view: the landmarks and the track, 2 m around; boxes clipped to it
  // (an infinite cone shows as a box to the edge).
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  auto extend = [&](double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x), y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
  };
  for (const auto& [n, xy] : truth) extend(xy.first, xy.second);
  for (const auto& row : track) extend(row[0], row[1]);
  x_lo -= 2, x_hi += 2, y_lo -= 2, y_hi += 2;
  Panel panel;
  panel.setup = "set size ratio -1\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset xrange [" +
                FormatNumber(x_lo) + ":" + FormatNumber(x_hi) + "]\nset yrange [" +
                FormatNumber(y_lo) + ":" + FormatNumber(y_hi) +
                "]\nset key below horizontal samplen 2 noenhanced\n" +
                TicsFor("x", x_lo, x_hi, 8) + TicsFor("y", y_lo, y_hi, 6);
  const char* const shades[] = {"#c6dbef", "#6baed6", "#2171b5", "#08306b"};
  int shade = 0;
  for (int k : steps) {
    const auto it = std::find_if(run.steps.begin(), run.steps.end(),
                                 [&](const StepRecord& s) { return s.step == k; });
    if (it == run.steps.end()) continue;
    Series boxes{"using (($1+$2)/2):(($3+$4)/2):1:2:3:4 with boxxyerror lw 1.5 lc rgb " +
                     Quote(shades[shade++ % 4]) + " title " + Quote("step " + std::to_string(k)),
                 {}, ""};
    for (const auto& [n, b] : LandmarkBoxesOf(it->properties))
      boxes.rows.push_back({std::clamp(b[0], x_lo, x_hi), std::clamp(b[1], x_lo, x_hi),
                            std::clamp(b[2], y_lo, y_hi), std::clamp(b[3], y_lo, y_hi)});
    if (!boxes.rows.empty()) panel.series.push_back(std::move(boxes));
  }
  Series points{"using 1:2 with points pt 7 ps 0.6 lc rgb 'black' title 'landmarks (truth)'", {}, ""};
  for (const auto& [n, xy] : truth) points.rows.push_back({xy.first, xy.second});
  panel.series.push_back(std::move(points));
  panel.series.push_back({"using 1:2 with lines lw 2 lc rgb '#d62728' title 'car (truth)'", track, ""});
  Figure f;
  f.name = text.name;
  f.title = text.title + " — " + RunLabel(run);
  f.height_in = 3.2;
  f.panels.push_back(std::move(panel));
  Render(f, out_dir, out);
}

}  // namespace icp
