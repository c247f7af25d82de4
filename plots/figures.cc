#include "plots/figures.h"

#include <gnuplot-iostream.h>
#include <signal.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "harness/metrics.h"
#include "report/report.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPixelsPerInch = 110;  // PNG size from the PDF size in inches

// One plotted item: inline data sent after the plot command ('-'), or a
// function when rows is empty and function is set (e.g. the zero line).
struct Series {
  std::string spec;  // what follows '-' (or the function): "using 1:2 with lines ..."
  std::vector<std::vector<double>> rows;
  std::string function;
};

struct Panel {
  std::string setup;  // gnuplot commands before the plot command
  std::vector<Series> series;
};

// A figure: panels in a rows x cols multiplot (one panel: no multiplot).
struct Figure {
  std::string name;  // file name without extension
  std::string title;
  double width_in = 8;
  double height_in = 5;
  int rows = 1;
  int cols = 1;
  std::vector<Panel> panels;
};

enum class Terminal { kPng, kPdf };

// Colours by algorithm, the same in every figure.
std::string Colour(const std::string& algorithm) { return DisplayOf(algorithm).colour; }

// A gnuplot single-quoted string.
std::string Quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') out += '\'';
    if (c != '\n') out += c;
  }
  return out + "'";
}

// A gnuplot double-quoted string, so that a '\n' in text breaks the line.
std::string MultiLine(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

double Finite(double v) { return std::isfinite(v) ? v : kNaN; }
double Positive(double v) { return std::isfinite(v) && v > 0 ? v : kNaN; }

bool HasPoint(const Series& s) {
  if (!s.function.empty()) return true;
  for (const auto& row : s.rows) {
    if (!row.empty() && std::all_of(row.begin(), row.end(), [](double v) { return !std::isnan(v); }))
      return true;
  }
  return false;
}

bool GnuplotAvailable() {
  static const bool available = std::system("gnuplot --version >/dev/null 2>&1") == 0;
  return available;
}

// The shared terminal setup: cairo PNG or PDF of the figure's size, UTF-8,
// output to path.
void SetTerminal(Gnuplot& gp, Terminal terminal, const Figure& f, const std::string& path) {
  gp << "set encoding utf8\n";
  if (terminal == Terminal::kPng) {
    gp << "set terminal pngcairo enhanced size " << static_cast<int>(f.width_in * kPixelsPerInch)
       << "," << static_cast<int>(f.height_in * kPixelsPerInch) << " font 'Sans,10'\n";
  } else {
    gp << "set terminal pdfcairo enhanced size " << f.width_in << "in," << f.height_in
       << "in font 'Sans,8'\n";
  }
  gp << "set output " << Quote(path) << "\n";
}

void DrawPanel(Gnuplot& gp, const Panel& panel) {
  gp << "reset\nset encoding utf8\nset grid\n" << panel.setup << "\n";
  std::vector<const Series*> drawn;
  for (const Series& s : panel.series) {
    if (HasPoint(s)) drawn.push_back(&s);
  }
  if (drawn.empty()) {  // keep the multiplot's place
    gp << "unset key\nset xrange [0:1]\nset yrange [0:1]\n"
          "set label 99 'no data' at graph 0.5, graph 0.5 center\nplot 2 notitle\n";
    return;
  }
  gp << "plot ";
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    gp << (i ? ", " : "") << (drawn[i]->function.empty() ? "'-'" : drawn[i]->function) << " "
       << drawn[i]->spec;
  }
  gp << "\n";
  for (const Series* s : drawn) {
    if (s->function.empty()) gp.send1d(s->rows);
  }
}

// Writes f as out_dir/NAME.png and .pdf in one gnuplot session and records
// the files that came out non-empty.
void Render(const Figure& f, const std::string& out_dir, PlotOutput* out) {
  if (!GnuplotAvailable()) {
    out->messages.push_back(f.name + ": skipped: gnuplot not found");
    return;
  }
  const std::vector<std::pair<Terminal, std::string>> outputs = {
      {Terminal::kPng, (std::filesystem::path(out_dir) / (f.name + ".png")).string()},
      {Terminal::kPdf, (std::filesystem::path(out_dir) / (f.name + ".pdf")).string()}};
  for (const auto& [terminal, path] : outputs) std::filesystem::remove(path);
  // gnuplot reads on after an error, but should it die, a write must fail
  // rather than kill the process.
  struct sigaction ignore = {}, previous = {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &previous);
  {
    Gnuplot gp("gnuplot");
    for (const auto& [terminal, path] : outputs) {
      SetTerminal(gp, terminal, f, path);
      const bool multiplot = f.panels.size() > 1;
      if (multiplot) {
        gp << "set multiplot layout " << f.rows << "," << f.cols;
        if (!f.title.empty()) gp << " title " << Quote(f.title) << " noenhanced";
        gp << "\n";
      }
      for (const Panel& p : f.panels) DrawPanel(gp, p);
      if (multiplot) gp << "unset multiplot\n";
      gp << "unset output\n";
    }
  }  // closing the pipe waits for gnuplot to finish
  sigaction(SIGPIPE, &previous, nullptr);
  for (const auto& [terminal, path] : outputs) {
    std::error_code ec;
    if (std::filesystem::file_size(path, ec) > 0 && !ec) {
      out->files.push_back(path);
    } else {
      out->messages.push_back(path + ": gnuplot wrote nothing (see its messages above)");
    }
  }
}

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

int CountRunsOnly(const std::vector<const RunRecord*>& runs) {
  return static_cast<int>(std::count_if(runs.begin(), runs.end(),
                                        [](const RunRecord* r) { return RecordedRunsOnly(*r); }));
}

std::string RunsOnlyText(int n) {
  return std::to_string(n) + (n == 1 ? " run was" : " runs were") +
         " recorded with `record: runs` (run metrics only, no step rows; rerun with record: steps "
         "to draw them)";
}

// A figure over steps whose runs were stored without them says so, not
// the generic reason.
void Skip(const FigureText& text, PlotOutput* out, const std::vector<const RunRecord*>& runs = {}) {
  const int runs_only = CountRunsOnly(runs);
  out->messages.push_back(
      text.name + ": skipped: " +
      (runs_only > 0 ? "it needs step rows, and " + RunsOnlyText(runs_only) : text.skip_reason));
}

// Drawn, but without the runs that have no step rows.
void NoteRunsOnly(const FigureText& text, const std::vector<const RunRecord*>& runs,
                  PlotOutput* out) {
  if (const int n = CountRunsOnly(runs); n > 0)
    out->messages.push_back(text.name + ": left out " + RunsOnlyText(n));
}

}  // namespace

std::string RunLabel(const RunRecord& r) {
  std::string label = WithParams(r.spec.algorithm, r.spec.algorithm_params) + " (seed " +
                      std::to_string(r.spec.seed);
  if (!r.spec.problem_params.empty()) label += ", " + CompactParams(r.spec.problem_params);
  return label + ")";
}


void PlotSweepFigure(const FigureText& text, const std::string& x_label,
                     const std::vector<SweepPoint>& points, const std::string& out_dir,
                     PlotOutput* out) {
  if (points.empty()) return Skip(text, out);
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
  std::vector<std::vector<std::vector<double>>> corridors[2];
  std::vector<std::vector<double>> all[2];
  for (std::size_t n = 0; n < runs.size(); ++n) {
    const RunRecord* r = runs[n];
    std::vector<std::vector<double>> rows[2] = {CorridorRows(*r, kVars[0]),
                                                CorridorRows(*r, kVars[1])};
    const Series probe[2] = {{"", rows[0], ""}, {"", rows[1], ""}};
    if (!HasPoint(probe[0]) && !HasPoint(probe[1])) continue;
    shown.push_back(r);
    shown_labels.push_back(labels.at(n));
    for (int k = 0; k < 2; ++k) {
      all[k].insert(all[k].end(), rows[k].begin(), rows[k].end());
      corridors[k].push_back(std::move(rows[k]));
    }
  }
  if (shown.empty()) return Skip(text, out, runs);
  NoteRunsOnly(text, runs, out);
  // One step axis for all, so a shorter run shows as shorter.
  double last_step = 0;
  for (const RunRecord* r : shown) {
    for (const StepRecord& st : r->steps) last_step = std::max(last_step, static_cast<double>(st.step));
  }
  const std::string x_range = "set xrange [0:" + std::to_string(std::max(1.0, last_step)) + "]\n";
  Figure f;
  f.name = text.name;
  bool gps = false;
  for (const RunRecord* r : shown)
    for (const char* var : kVars) gps = gps || HasPoint({"", GpsCorridorRows(*r, var), ""});
  f.title = text.title + ": solid lo - truth, dashed hi - truth" + (gps ? "; grey: the GPS box" : "");
  f.width_in = 10;
  f.cols = 2;
  f.rows = static_cast<int>(shown.size());
  f.height_in = 0.6 + 2.2 * f.rows;
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const RunRecord& r = *shown[i];
    const std::string colour = Quote(Colour(r.spec.algorithm));
    for (int k = 0; k < 2; ++k) {
      Panel p;
      p.setup = "set title " + Quote(shown_labels[i] + ": " + kVars[k]) + " noenhanced\n" +
                "set ylabel 'error in " + kVars[k] + " (m)'\n" + CorridorRange(all[k]) +
                (i + 1 == shown.size() ? "set xlabel 'step'\n" : "") +
                "unset key\n" + x_range;
      const auto& rows = corridors[k][i];
      p.series = {
          {"using 1:2:3 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.35 notitle",
           GpsCorridorRows(r, kVars[k]), ""},
          {"using 1:2:3 with filledcurves fc rgb " + colour + " fs transparent solid 0.25 notitle",
           rows, ""},
          {"using 1:2 with lines lw 1.2 lc rgb " + colour + " notitle", rows, ""},
          {"using 1:3 with lines lw 1.2 dt 2 lc rgb " + colour + " notitle", rows, ""},
          {"with lines lw 1 lc rgb 'black' notitle", {}, "0"}};
      f.panels.push_back(std::move(p));
    }
  }
  Render(f, out_dir, out);
}

namespace {
// One line per run of a per-step value against the step, log scale, each
// line titled by its run and what title_extra says of it.
void PlotStepValueFigure(const FigureText& text, const std::string& y_label,
                         const std::vector<const RunRecord*>& runs,
                         const std::function<double(const StepRecord&)>& value,
                         const std::function<std::string(const RunRecord&)>& title_extra,
                         const std::string& out_dir, PlotOutput* out) {
  Panel panel;
  panel.setup = "set title " + Quote(text.title) + " noenhanced\nset xlabel 'step'\nset ylabel " +
                Quote(y_label) + "\nset logscale y\nset key top right noenhanced\n";
  for (const RunRecord* r : runs) {
    Series s{"using 1:2 with lines lw 1.5 lc rgb " + Quote(Colour(r->spec.algorithm)) +
                 " title " + Quote(RunLabel(*r) + title_extra(*r)),
             {}, ""};
    for (const StepRecord& step : r->steps)
      s.rows.push_back({static_cast<double>(step.step), Positive(value(step))});
    if (HasPoint(s)) panel.series.push_back(std::move(s));
  }
  if (panel.series.empty()) return Skip(text, out, runs);
  NoteRunsOnly(text, runs, out);
  Figure f;
  f.name = text.name;
  f.width_in = 9;
  f.height_in = 4.5;
  f.panels = {panel};
  Render(f, out_dir, out);
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

void PlotTrackFigure(const FigureText& text, const std::vector<std::pair<double, double>>& wall_points,
                     const std::vector<const RunRecord*>& runs, int boxes_every,
                     const std::string& out_dir, PlotOutput* out) {
  if (runs.empty() || runs[0]->steps.empty()) return Skip(text, out, runs);
  NoteRunsOnly(text, runs, out);
  Panel panel;
  panel.setup = "set title " + MultiLine(text.title) +
                " noenhanced\nset xlabel 'x (m)'\nset ylabel 'y (m)'\nset size ratio -1\n"
                "set key outside bottom center horizontal noenhanced\n";
  Series walls{"using 1:2 with dots lc rgb '#9a9a9a' title 'map'", {}, ""};
  for (const auto& [x, y] : wall_points) walls.rows.push_back({x, y});
  if (HasPoint(walls)) panel.series.push_back(std::move(walls));
  Series truth{"using 1:2 with lines lw 2 lc rgb 'black' title 'truth'", {}, ""};
  for (const StepRecord& s : runs[0]->steps)
    if (s.vars.size() >= 2) truth.rows.push_back({s.vars[0].truth, s.vars[1].truth});
  if (HasPoint(truth)) panel.series.push_back(std::move(truth));
  for (const RunRecord* r : runs) {
    const std::string colour = Quote(Colour(r->spec.algorithm));
    const bool particles = !r->steps.empty() && r->steps[0].estimate == "particles";
    if (boxes_every > 0 && !particles) {
      Series boxes{"using 1:2:3:4 with boxxyerror fs empty lw 0.6 lc rgb " + colour + " notitle",
                   {}, ""};
      for (std::size_t i = 0; i < r->steps.size(); i += boxes_every) {
        const StepRecord& s = r->steps[i];
        if (s.vars.size() < 2 || IsEmptyEstimate(s)) continue;
        const VariableRecord &x = s.vars[0], &y = s.vars[1];
        boxes.rows.push_back({Finite((x.lo + x.hi) / 2), Finite((y.lo + y.hi) / 2),
                              Finite((x.hi - x.lo) / 2), Finite((y.hi - y.lo) / 2)});
      }
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
  Figure f;
  f.name = text.name;
  f.width_in = 8;
  f.height_in = 8;
  f.panels = {panel};
  Render(f, out_dir, out);
}

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
                " noenhanced\nset ylabel 'time per CSP (µs)'\nset logscale y\nset format y '10^{%L}'\n"
                "set style boxplot outliers pointtype 7\nset pointsize 0.3\nset boxwidth 0.5\n"
                "set xtics (" + xtics + ") noenhanced\nset xrange [0.4:" +
                std::to_string(panel.series.size() + 0.6) + "]\nset grid noxtics\n";
  Figure f;
  f.name = text.name;
  f.width_in = std::max(4.0, 1.4 * static_cast<double>(panel.series.size()) + 1.5);
  f.height_in = 4.5;
  f.panels = {panel};
  Render(f, out_dir, out);
}

namespace {
constexpr char kBigMarker[] = "#ff1a1a";
constexpr char kSmallMarker[] = "#ff9f1c";

// The side of BlockMax's blocks.
int BlockSide(const cv::Mat& counts, int max_side) {
  return std::max(
      {1, (counts.rows + max_side - 1) / max_side, (counts.cols + max_side - 1) / max_side});
}
}  // namespace

cv::Mat BlockMax(const cv::Mat& counts, int max_side) {
  if (counts.type() != CV_32S) throw std::invalid_argument("BlockMax: counts must be CV_32S");
  if (max_side < 1) throw std::invalid_argument("BlockMax: max_side must be >= 1");
  const int block = BlockSide(counts, max_side);
  if (block == 1) return counts;
  const int rows = (counts.rows + block - 1) / block, cols = (counts.cols + block - 1) / block;
  cv::Mat out(rows, cols, CV_32S, cv::Scalar(std::numeric_limits<int>::min()));
  for (int r = 0; r < counts.rows; ++r) {
    const int* in = counts.ptr<int>(r);
    int* o = out.ptr<int>(r / block);
    for (int c = 0; c < counts.cols; ++c) o[c / block] = std::max(o[c / block], in[c]);
  }
  return out;
}

void PlotAccumulatorFigure(const FigureText& text, const cv::Mat& counts, const Interval& x,
                           const Interval& y, const std::vector<MarkerSet>& markers,
                           const std::string& out_dir, PlotOutput* out) {
  if (counts.empty() || x.IsEmpty() || y.IsEmpty()) return Skip(text, out);
  // Each pixel of the drawn matrix stands for a block of block x block
  // cells (the last of a row or column may hold fewer and overhang the
  // range, which clips it).
  const cv::Mat drawn = BlockMax(counts, kAccumulatorPlotCells);
  const int block = BlockSide(counts, kAccumulatorPlotCells);
  const double cell_x = x.Width() / counts.cols * block, cell_y = y.Width() / counts.rows * block;
  double max_count = 0;
  cv::minMaxLoc(counts, nullptr, &max_count);
  std::ostringstream data;
  data << "$counts << EOD\n";
  for (int r = 0; r < drawn.rows; ++r) {
    const int* row = drawn.ptr<int>(r);
    for (int c = 0; c < drawn.cols; ++c) data << (c ? " " : "") << row[c];
    data << "\n";
  }
  data << "EOD\n";
  auto num = [](double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
  };
  // The truth's cross is drawn as four arms around an open centre, so it
  // does not hide the maximum it marks; small crosses are plain points.
  const double arm_out = 0.045 * std::max(x.Width(), y.Width()),
               arm_in = 0.012 * std::max(x.Width(), y.Width());
  std::string arrows;
  int arrow = 0;
  for (const MarkerSet& m : markers) {
    if (!m.big) continue;
    for (const auto& [px, py] : m.points) {
      for (const double dx : {-1.0, 1.0}) {
        for (const double dy : {-1.0, 1.0}) {
          arrows += "set arrow " + std::to_string(++arrow) + " from " + num(px + dx * arm_in) +
                    "," + num(py + dy * arm_in) + " to " + num(px + dx * arm_out) + "," +
                    num(py + dy * arm_out) + " nohead front lw 3.5 lc rgb '" + kBigMarker + "'\n";
        }
      }
    }
  }
  Panel panel;
  panel.setup = data.str() + "set title " + MultiLine(text.title) + " noenhanced\nunset grid\n" +
                "set xlabel 'x'\nset ylabel 'y'\nset size ratio -1\n" +
                "set xrange [" + num(x.lo()) + ":" + num(x.hi()) + "]\nset yrange [" +
                num(y.lo()) + ":" + num(y.hi()) + "]\n" +
                "set cbrange [0:" + num(std::max(1.0, max_count)) + "]\nset cblabel 'count'\n" +
                "set cbtics " + num(std::max(1.0, std::ceil(max_count / 10))) + "\n" +
                // viridis: light enough at low counts that single bands show
                "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', "
                "1 '#fde725')\n" +
                "set bmargin 5.5\nset tics out\n"
                "set key at screen 0.45, screen 0.015 center bottom horizontal noenhanced\n" +
                arrows;
  panel.series.push_back({"", {},
                          "$counts matrix using (" + num(x.lo()) + " + ($1 + 0.5) * " +
                              num(cell_x) + "):(" + num(y.lo()) + " + ($2 + 0.5) * " +
                              num(cell_y) + "):3 with image notitle"});
  for (const MarkerSet& m : markers) {
    const std::string title = m.title.empty() ? " notitle" : " title " + Quote(m.title);
    if (m.big) {  // the arrows above; a legend entry only
      if (!m.title.empty() && !m.points.empty())
        panel.series.push_back(
            {"with points pt 2 ps 2.5 lw 3.5 lc rgb '" + std::string(kBigMarker) + "'" + title,
             {}, "keyentry"});
      continue;
    }
    Series s{std::string("using 1:2 with points pt 2 ps 1.8 lw 2.5 lc rgb '") + kSmallMarker + "'" +
                 title,
             {}, ""};
    for (const auto& [px, py] : m.points) s.rows.push_back({px, py});
    if (HasPoint(s)) panel.series.push_back(std::move(s));
  }
  Figure f;
  f.name = text.name;
  f.width_in = 7;
  f.height_in = 6;
  f.panels = {panel};
  Render(f, out_dir, out);
}

std::vector<const GroupSummary*> TimingGroups(const std::vector<GroupSummary>& groups,
                                              std::string* setting) {
  // (problem, problem params) -> (algorithms ok at default params, CSPs)
  std::map<std::pair<std::string, ParamMap>, std::pair<int, int>> score;
  for (const GroupSummary& g : groups) {
    if (!g.algorithm_params.empty() || g.ok == 0) continue;
    auto& [algorithms, steps] = score[{g.problem, g.problem_params}];
    ++algorithms;
    steps += g.metrics.steps;
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
