// The sweep figure: mean areas and mean time per CSP against the value of a
// swept problem parameter, one line per configuration at the median of its
// seeds' means with the 95 % interval of that median as error bars;
// configurations whose line coincides drawn once under a joined label.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "plots/figures.h"
#include "plots/figures_internal.h"
#include "report/report.h"

namespace icp {

namespace {

// One quantity against the swept value: a panel of one line per group of
// configurations with equal values; log axes where the values span decades.
struct Quantity {
  std::string title, y_label, key;
  // per configuration {value, median, lo, hi}; lo = hi = median where the
  // seeds are too few for an interval (MedianWithInterval)
  std::vector<std::vector<std::vector<double>>> rows;
};

// The row of one swept value: the median over the runs of value(run), with
// its 95 % interval.
std::vector<double> MedianRow(const SweepPoint& p,
                              const std::function<double(const RunRecord&)>& value) {
  std::vector<double> values;
  for (const RunRecord* run : p.ok_runs)
    if (const double v = value(*run); std::isfinite(v)) values.push_back(v);
  const MedianInterval m = MedianWithInterval(values);
  const double median = Finite(m.median);
  return {p.value, median, std::isnan(m.lo) ? median : m.lo, std::isnan(m.hi) ? median : m.hi};
}

Panel QuantityPanel(const Quantity& q, const std::string& x_label,
                    const std::vector<std::string>& labels, const std::vector<std::string>& styles,
                    const std::vector<std::vector<std::size_t>>& groups) {
  std::vector<double> xs, ys;
  for (const auto& rows : q.rows)
    for (const auto& row : rows) {
      xs.push_back(row[0]);
      ys.insert(ys.end(), row.begin() + 1, row.end());
    }
  double y_lo = INFINITY, y_hi = -INFINITY;
  for (double y : ys)
    if (std::isfinite(y)) y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
  // The x range a little wider than the values, so that the end points'
  // error bars are drawn whole.
  const bool log_x = SpansDecades(xs);
  const double x_lo = *std::min_element(xs.begin(), xs.end());
  const double x_hi = *std::max_element(xs.begin(), xs.end());
  const double pad = log_x ? 0 : 0.03 * std::max(x_hi - x_lo, 1e-9);
  const double lo = log_x ? x_lo / 1.15 : x_lo - pad, hi = log_x ? x_hi * 1.15 : x_hi + pad;
  Panel p;
  p.setup = "set title " + Quote(q.title) + "\nset xlabel " + Quote(x_label) + "\nset ylabel " +
            Quote(q.y_label) + "\nset key " + q.key + " maxcols 1 samplen 2 noenhanced\nset xrange [" +
            FormatNumber(lo) + ":" + FormatNumber(hi) + "]\n" +
            (log_x ? "set logscale x\n" : "") +
            (SpansDecades(ys) ? "set logscale y\n" : TicsFor("y", y_lo, y_hi, 5));
  for (const auto& g : groups) {
    Series s{"using 1:2:3:4 " + styles[g.front()] + " title " + Quote(JoinedLabel(labels, g)),
             q.rows[g.front()], ""};
    if (HasPoint(s)) p.series.push_back(std::move(s));
  }
  return p;
}

// The " [...]" that ends every label (the problem parameters every line
// shares), "" when they do not share one.
std::string SharedSuffix(const std::vector<std::string>& labels) {
  if (labels.empty()) return "";
  const std::size_t open = labels.front().rfind(" [");
  if (open == std::string::npos || labels.front().back() != ']') return "";
  const std::string suffix = labels.front().substr(open);
  for (const std::string& l : labels)
    if (!l.ends_with(suffix)) return "";
  return suffix;
}

}  // namespace

void PlotSweepFigure(const FigureText& text, const std::string& x_label,
                     const std::vector<SweepPoint>& points, const std::string& out_dir,
                     PlotOutput* out) {
  // The window states' area is a step property, which runs stored with
  // `record: runs` lack: said, and its panel left out when no run has it.
  std::vector<const RunRecord*> runs;
  for (const SweepPoint& p : points) runs.insert(runs.end(), p.ok_runs.begin(), p.ok_runs.end());
  if (const std::vector<const RunRecord*> runs_only = RunsOnlyOf(runs); !runs_only.empty())
    out->messages.push_back(text.name +
                            ": drawn from the run metrics; the mean area of the window states (a "
                            "step property) lacks " +
                            RunCount(runs_only.size()) + " " + RecordedWithRunsOnly(runs_only));
  PlotSweepFigure(
      text, x_label, points,
      {{"Mean x-y area of the newest state", "area (m^2)",
        [](const RunRecord& r) { return r.metrics.mean_area; }},
       {"Mean x-y area of the window states", "area (m^2)", RunMeanWindowArea},
       {"Mean time per CSP", "time (ms)",
        [](const RunRecord& r) { return r.metrics.time_mean_s * 1e3; }}},
      out_dir, out);
}

void PlotSweepFigure(const FigureText& text, const std::string& x_label,
                     const std::vector<SweepPoint>& points,
                     const std::vector<SweepQuantity>& quantities, const std::string& out_dir,
                     PlotOutput* out) {
  if (points.empty()) return Skip(text, out);
  // Keys below the panels: the lines span the whole frame.
  std::vector<Quantity> rows;
  for (const SweepQuantity& q : quantities) rows.push_back({q.title, q.y_label, "below", {}});
  const bool bars = std::any_of(points.begin(), points.end(),
                                [](const SweepPoint& p) { return p.ok_runs.size() >= 6; });
  if (bars)
    for (Quantity& q : rows) q.title += " (median of seeds, 95 % CI)";
  // An algorithm's colour for all its configurations; its second, third ...
  // configuration dashed and marked differently, so they stay apart.
  std::vector<std::string> labels, styles;
  std::map<std::string, int> configurations;
  for (std::size_t i = 0; i < points.size();) {
    const std::string& label = points[i].label;
    const int nth = configurations[points[i].algorithm]++;
    labels.push_back(label);
    styles.push_back("with yerrorlines lw 2 dt " + std::to_string(1 + nth % 5) + " pt " +
                     std::to_string(7 + 2 * (nth % 3)) + " ps 0.7 lc rgb " +
                     Quote(Colour(points[i].algorithm)));
    for (Quantity& q : rows) q.rows.emplace_back();
    for (; i < points.size() && points[i].label == label; ++i)
      for (std::size_t k = 0; k < rows.size(); ++k)
        rows[k].rows.back().push_back(MedianRow(points[i], quantities[k].value));
  }
  // Parameters every line shares said once, in the title.
  const std::string shared = SharedSuffix(labels);
  for (std::string& l : labels) l.resize(l.size() - shared.size());
  // One panel a row, each as wide as the page prints it.
  Figure f;
  f.name = text.name;
  f.title = text.title + shared;
  std::vector<const Quantity*> shown;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    bool finite = false;
    for (const SweepPoint& p : points)
      for (const RunRecord* r : p.ok_runs) finite = finite || std::isfinite(quantities[k].value(*r));
    if (finite) shown.push_back(&rows[k]);
  }
  if (shown.empty()) return Skip(text, out);
  // Each group of equal lines noted once, with the panels it is equal in.
  std::vector<std::pair<std::vector<std::size_t>, std::string>> equal;
  for (const Quantity* q : shown) {
    const std::vector<std::vector<std::size_t>> groups = EqualGroups(q->rows);
    for (const auto& g : groups) {
      if (g.size() < 2) continue;
      auto same =
          std::find_if(equal.begin(), equal.end(), [&](const auto& e) { return e.first == g; });
      if (same == equal.end())
        equal.push_back({g, "in '" + q->title + "'"});
      else
        same->second += ", '" + q->title + "'";
    }
    f.panels.push_back(QuantityPanel(*q, x_label, labels, styles, groups));
  }
  for (const auto& [group, where] : equal) NoteEqualSeries(text.name, labels, {group}, where, out);
  f.rows = static_cast<int>(f.panels.size());
  f.height_in = 0.3 + 2.3 * f.rows;
  Render(f, out_dir, out);
}

}  // namespace icp
