// The figures over the steps of runs: the error corridors of x and y (with
// the GPS box behind them), the x-y area and the centre error.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "harness/metrics.h"
#include "plots/figures.h"
#include "plots/figures_internal.h"
#include "report/report.h"

namespace icp {

namespace {

// The corridor [lo - truth, hi - truth] of variable var over the steps:
// rows {step, lower, upper}; NaN where the box is empty or the truth unknown.
std::vector<std::vector<double>> CorridorRows(const RunRecord& run, const std::string& var) {
  std::vector<std::vector<double>> rows;
  for (const StepRecord& s : run.steps) {
    double lower = kNaN, upper = kNaN;
    for (const VariableRecord& v : s.vars) {
      if (v.name != var || !(v.lo <= v.hi) || std::isnan(v.truth)) continue;
      lower = Finite(v.lo - v.truth);
      upper = Finite(v.hi - v.truth);
    }
    rows.push_back({static_cast<double>(s.step), lower, upper});
  }
  return rows;
}

// A y range holding 98 % of the corridor's bounds and zero, so a few wide
// boxes at the start (unknown heading) do not flatten the rest.
std::string CorridorRange(const std::vector<std::vector<double>>& rows) {
  std::vector<double> lower, upper;
  for (const auto& row : rows) {
    lower.push_back(row[1]);
    upper.push_back(row[2]);
  }
  const double lo = std::min(0.0, Quantile(lower, 0.01));
  const double hi = std::max(0.0, Quantile(upper, 0.99));
  if (std::isnan(lo) || std::isnan(hi) || !(hi > lo)) return "";
  const double margin = 0.1 * (hi - lo);
  return "set yrange [" + std::to_string(lo - margin) + ":" + std::to_string(hi + margin) + "]\n";
}

}  // namespace

// The GPS corridor of variable var (paper 000 Fig. 3): rows {step, gps lo -
// truth, gps hi - truth} from the step properties gps_<var>_lo/hi that
// car-track records; NaN where a step has none or the truth is unknown.
std::vector<std::vector<double>> GpsCorridorRows(const RunRecord& run, const std::string& var) {
  std::vector<std::vector<double>> rows;
  for (const StepRecord& s : run.steps) {
    double lower = kNaN, upper = kNaN;
    const std::optional<double> lo = NumberProperty(s.properties, "gps_" + var + "_lo");
    const std::optional<double> hi = NumberProperty(s.properties, "gps_" + var + "_hi");
    for (const VariableRecord& v : s.vars) {
      if (v.name != var || std::isnan(v.truth) || !lo || !hi) continue;
      lower = Finite(*lo - v.truth);
      upper = Finite(*hi - v.truth);
    }
    rows.push_back({static_cast<double>(s.step), lower, upper});
  }
  return rows;
}

void PlotCorridorFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                        const std::string& out_dir, PlotOutput* out) {
  std::vector<std::string> labels;
  for (const RunRecord* r : runs) labels.push_back(RunLabel(*r));
  PlotCorridorFigure(text, runs, labels, out_dir, out);
}

void PlotCorridorFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                        const std::vector<std::string>& labels, const std::string& out_dir,
                        PlotOutput* out) {
  const char* const kVars[2] = {"x", "y"};
  // Corridors of every shown run first: each column shares its y range so
  // the runs compare at a glance.
  std::vector<const RunRecord*> shown;
  std::vector<std::string> shown_labels;
  std::vector<std::vector<std::vector<double>>> corridors[2], both;
  std::vector<std::vector<double>> all[2];
  for (std::size_t n = 0; n < runs.size(); ++n) {
    const RunRecord* r = runs[n];
    std::vector<std::vector<double>> rows[2] = {CorridorRows(*r, kVars[0]),
                                                CorridorRows(*r, kVars[1])};
    const Series probe[2] = {{"", rows[0], ""}, {"", rows[1], ""}};
    if (!HasPoint(probe[0]) && !HasPoint(probe[1])) continue;
    shown.push_back(r);
    shown_labels.push_back(labels.at(n));
    both.push_back(rows[0]);
    both.back().insert(both.back().end(), rows[1].begin(), rows[1].end());
    for (int k = 0; k < 2; ++k) {
      all[k].insert(all[k].end(), rows[k].begin(), rows[k].end());
      const auto gps = GpsCorridorRows(*r, kVars[k]);
      all[k].insert(all[k].end(), gps.begin(), gps.end());
      corridors[k].push_back(std::move(rows[k]));
    }
  }
  if (shown.empty()) return Skip(text, out, runs);
  std::vector<std::vector<std::vector<double>>> per_variable = corridors[0];
  per_variable.insert(per_variable.end(), corridors[1].begin(), corridors[1].end());
  if (SkippedForOneStep(text, per_variable, out)) return;
  NoteRunsOnly(text, runs, out);
  // Runs whose corridors are equal at every step: one row of panels.
  const std::vector<std::vector<std::size_t>> groups = EqualGroups(both);
  NoteEqualSeries(text.name, shown_labels, groups, "equal corridors at every step", out);
  // One step axis for all, so a shorter run shows as shorter.
  double last_step = 0;
  for (const RunRecord* r : shown) {
    for (const StepRecord& st : r->steps)
      last_step = std::max(last_step, static_cast<double>(st.step));
  }
  const std::string x_range = "set xrange [0:" + std::to_string(std::max(1.0, last_step)) + "]\n";
  Figure f;
  f.name = text.name;
  bool gps = false;
  for (const RunRecord* r : shown)
    for (const char* var : kVars) gps = gps || HasPoint({"", GpsCorridorRows(*r, var), ""});
  // Over many steps the bounds are drawn as a filled band (lines would
  // merge at the printer's resolution), the GPS box underneath in grey.
  f.title = text.title + "\nband: the box's [lo - truth, hi - truth]; black: the truth (0)" +
            (gps ? "; grey: the GPS box" : "");
  f.cols = 2;
  f.rows = static_cast<int>(groups.size());
  f.height_in = std::min(kPrintMaxHeightIn, 0.5 + 2.4 * f.rows);  // room for wrapped titles
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const std::size_t first = groups[i].front();
    const RunRecord& r = *shown[first];
    const std::string colour = Quote(Colour(r.spec.algorithm));
    for (int k = 0; k < 2; ++k) {
      Panel p;
      // Wrapped to its panel: two panels a row share the page's width.
      p.setup = "set title " +
                MultiLine(Wrapped(JoinedLabel(shown_labels, groups[i]) + ": " + kVars[k],
                                  0.8 * kPrintWidthIn / f.cols)) +
                " noenhanced\n" + "set ylabel 'error in " + kVars[k] + " (m)'\n" +
                CorridorRange(all[k]) + (i + 1 == groups.size() ? "set xlabel 'step'\n" : "") +
                "unset key\n" + x_range + TicsFor("x", 0, std::max(1.0, last_step), 5);
      const auto& rows = corridors[k][first];
      p.series = {
          {"using 1:2:3 with filledcurves fc rgb '#b4b4b4' fs solid 1.0 notitle",
           GpsCorridorRows(r, kVars[k]), ""},
          {"using 1:2:3 with filledcurves fc rgb " + colour + " fs transparent solid 0.75 notitle",
           rows, ""},
          {"with lines lw 1.5 lc rgb 'black' notitle", {}, "0"}};
      f.panels.push_back(std::move(p));
    }
  }
  Render(f, out_dir, out);
}

namespace {

// Over more steps than this a line per step merges into a band at the
// printer's resolution: a running median is drawn instead.
constexpr std::size_t kLongRun = 400;

// The median of rows' values (column 1) over the window of steps centred on
// each row (NaN left out), window odd.
std::vector<std::vector<double>> RunningMedian(const std::vector<std::vector<double>>& rows,
                                               std::size_t window) {
  std::vector<std::vector<double>> out;
  const std::size_t half = window / 2;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::vector<double> values;
    for (std::size_t j = i >= half ? i - half : 0; j < std::min(rows.size(), i + half + 1); ++j)
      if (!std::isnan(rows[j][1])) values.push_back(rows[j][1]);
    out.push_back({rows[i][0], values.empty() ? kNaN : Quantile(values, 0.5)});
  }
  return out;
}

// Longer key labels make the key wider than the page (8-pt font, 6.5 in).
constexpr std::size_t kMaxKeyLabelChars = 50;

// One line per run of a per-step value against the step, log scale, each
// line titled by its run and what title_extra says of it; runs with equal
// values drawn once; over long runs the running median of a 40th of them.
void PlotStepValueFigure(const FigureText& text, const std::string& y_label,
                         const std::vector<const RunRecord*>& runs,
                         const std::function<double(const StepRecord&)>& value,
                         const std::function<std::string(const RunRecord&)>& title_extra,
                         const std::string& out_dir, PlotOutput* out) {
  std::vector<std::vector<std::vector<double>>> rows;
  std::vector<const RunRecord*> drawn;
  for (const RunRecord* r : runs) {
    Series s{"", {}, ""};
    for (const StepRecord& step : r->steps)
      s.rows.push_back({static_cast<double>(step.step), Positive(value(step))});
    if (!HasPoint(s)) continue;
    drawn.push_back(r);
    rows.push_back(std::move(s.rows));
  }
  if (drawn.empty()) return Skip(text, out, runs);
  if (SkippedForOneStep(text, rows, out)) return;
  NoteRunsOnly(text, runs, out);
  // Runs with the same values at every step and the same title extra: one
  // line under the joined label.
  std::vector<std::vector<std::size_t>> groups;
  for (const auto& equal : EqualGroups(rows)) {
    const std::size_t before = groups.size();
    for (std::size_t i : equal) {
      auto same = std::find_if(groups.begin() + before, groups.end(), [&](const auto& g) {
        return title_extra(*drawn[g.front()]) == title_extra(*drawn[i]);
      });
      if (same == groups.end())
        groups.push_back({i});
      else
        same->push_back(i);
    }
  }
  std::vector<std::string> names;
  for (const RunRecord* r : drawn) names.push_back(RunLabel(*r));
  NoteEqualSeries(text.name, names, groups, "at every step", out);
  // A key wider than the page is not drawn: when a configuration's label is
  // long and the algorithms tell the lines apart, the key names the
  // algorithm and the title the whole configurations.
  std::string configurations;
  std::set<std::string> algorithms;
  for (const RunRecord* r : drawn) algorithms.insert(r->spec.algorithm);
  const bool long_label = std::any_of(names.begin(), names.end(), [](const std::string& n) {
    return n.size() > kMaxKeyLabelChars;
  });
  if (long_label && algorithms.size() == drawn.size()) {
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      configurations += (i ? "; " : "") + names[i];
      names[i] = drawn[i]->spec.algorithm;
    }
  }
  std::size_t steps = 0;
  for (const auto& r : rows) steps = std::max(steps, r.size());
  const std::size_t window = steps > kLongRun ? (steps / 40) | 1 : 1;
  Panel panel;
  panel.setup =
      "set title " +
      MultiLine(Wrapped(text.title +
                            (window > 1 ? ": running median over " + std::to_string(window) +
                                              " steps"
                                        : "") +
                            (configurations.empty() ? "" : "\n" + configurations),
                        // centred on the plot, which the y labels narrow
                        0.8 * kPrintWidthIn)) +
      " noenhanced\nset xlabel 'step'\nset ylabel " + Quote(y_label) +
      // The key below: its labels name whole configurations, and the lines
      // span the frame.
      "\nset logscale y\nset key below noenhanced\nset autoscale xfix\n";
  // Each line its own dash, so that lines that nearly coincide stay apart.
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const auto& g = groups[k];
    const RunRecord& r = *drawn[g.front()];
    panel.series.push_back({"using 1:2 with lines lw 2 dt " + std::to_string(1 + k % 5) +
                                " lc rgb " + Quote(Colour(r.spec.algorithm)) + " title " +
                                Quote(JoinedLabel(names, g) + title_extra(r)),
                            window > 1 ? RunningMedian(rows[g.front()], window) : rows[g.front()],
                            ""});
  }
  RenderPanel(text.name, kPrintWidthIn, 3.6, panel, out_dir, out);
}
}  // namespace

void PlotAreaFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                    const std::string& out_dir, PlotOutput* out) {
  PlotStepValueFigure(
      text, "x-y area (m^2)", runs, [](const StepRecord& s) { return s.area; },
      [](const RunRecord&) { return std::string(); }, out_dir, out);
}

void PlotCentreErrorFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                           const std::string& out_dir, PlotOutput* out) {
  auto consistency = [](const RunRecord& r) {
    int known = 0, contained = 0;
    for (const StepRecord& s : r.steps)
      if (s.contained >= 0) ++known, contained += s.contained;
    return known ? ", truth held on " + FormatNumber(100.0 * contained / known) + "% of steps"
                 : std::string();
  };
  PlotStepValueFigure(
      text, "centre error (m)", runs, [](const StepRecord& s) { return s.centre_error; },
      consistency, out_dir, out);
}

}  // namespace icp
