#include "experiments/paper004/paper004.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "experiments/paper000/paper000.h"
#include "experiments/paper004/visual.h"
#include "harness/metrics.h"
#include "harness/spec.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPaperWindow = kPaper004.post_localization_window;  // Ξ of Fig. 13

std::string Percent(double share) { return FormatNumber(100 * share); }

// Whether a run's steps report post-localized states (what
// PostLocalizedStates selects on), without building them.
bool ReportsPostStates(const RunRecord& r) {
  return std::any_of(r.steps.begin(), r.steps.end(), [](const StepRecord& s) {
    return NumberProperty(s.properties, "post_contained").has_value();
  });
}

// Whether the run's parameters are HC4's defaults (the figure's algorithm).
bool DefaultHc4(const RunRecord& r) {
  return r.spec.algorithm_params.empty() || r.spec.algorithm_params == AlgorithmDefaults("hc4");
}

// The points of Fig. 2 whose runs report post-localized states.
std::vector<SweepPoint> PostLocalizationPoints(const std::vector<RunRecord>& runs) {
  std::vector<SweepPoint> out;
  for (const SweepPoint& p : Paper000Fig2Points(Paper000WindowSweep(runs))) {
    for (const RunRecord* r : p.ok_runs) {
      if (ReportsPostStates(*r)) {
        out.push_back(p);
        break;
      }
    }
  }
  return out;
}

TextTable PostLocalizationTable(const std::vector<RunRecord>& runs) {
  TextTable t;
  t.title = "Paper 004: real-time vs post-localization (car-track)";
  t.headers = {"configuration", "w", "runs", "states", "RTL consistent (%)", "PL consistent (%)",
               "RTL area (m²)", "PL area (m²)", "PL / RTL area", "RTL width x (m)",
               "PL width x (m)", "RTL width y (m)", "PL width y (m)"};
  t.numeric = {false, true, true, true, true, true, true, true, true, true, true, true, true};
  for (const PostLocalizationPoint& row : Paper004PostLocalization(runs)) {
    const SweepPoint& p = row.point;
    const RunMetrics &rtl = row.real_time, &pl = row.post;
    t.rows.push_back({p.label, FormatNumber(p.value), std::to_string(p.runs),
                      std::to_string(pl.steps), Percent(rtl.consistency_rate),
                      Percent(pl.consistency_rate), FormatNumber(rtl.mean_area),
                      FormatNumber(pl.mean_area), FormatRatio(pl.mean_area, rtl.mean_area),
                      FormatNumber(CorridorWidth(rtl, "x")), FormatNumber(CorridorWidth(pl, "x")),
                      FormatNumber(CorridorWidth(rtl, "y")), FormatNumber(CorridorWidth(pl, "y"))});
  }
  t.omit_if_empty = true;
  if (t.rows.empty()) {
    t.notes.push_back(
        "No ok car-track run of experiment window reports post-localized states: "
        "specs/default.yaml (experiment window) produces them.");
    return t;
  }
  t.notes.push_back(
      "RTL (real-time localization): the newest state's box at each step. PL "
      "(post-localization, paper 004 §4.2): each state's box as the last window that held it "
      "leaves it. With carried windows (carry=first) that box holds what the earlier windows "
      "knew and the later measurements add; with memoryless ones (carry=none) only that "
      "window's measurements, so it can be wider than the state's real-time box. States: "
      "how many left a window (the last w of a drive never do). Consistent: the box holds "
      "the true state (eq. 31, heading modulo 2π); width: the mean of hi − lo of the "
      "interval error (eq. 30). Pooled over the ok runs (every seed) of each configuration.");
  t.notes.push_back(
      "Published (paper 004 §5.2, Figs. 12-13, visual localization on the PAVIN track, "
      "Ξ = 50): both consistent all along; the post-localized corridor narrower; real-time "
      "corridor widths 11.7 cm (x) and 13.4 cm (y). Its data and sensors are not the car "
      "track's, so the widths compare in kind, not in value.");
  return t;
}

}  // namespace

double CorridorWidth(const RunMetrics& m, const std::string& var) {
  for (const Corridor& c : m.corridors)
    if (c.var == var) return c.mean_upper - c.mean_lower;
  return kNaN;
}

std::vector<PostLocalizationPoint> Paper004PostLocalization(const std::vector<RunRecord>& runs) {
  return PoolPostLocalization(PostLocalizationPoints(runs));
}

std::vector<PostLocalizationPoint> PoolPostLocalization(const std::vector<SweepPoint>& points) {
  std::vector<PostLocalizationPoint> out;
  for (const SweepPoint& p : points) {
    std::vector<StepRecord> real_time, post;
    for (const RunRecord* r : p.ok_runs) {
      real_time.insert(real_time.end(), r->steps.begin(), r->steps.end());
      const std::vector<StepRecord> states = PostLocalizedStates(r->steps);
      post.insert(post.end(), states.begin(), states.end());
    }
    out.push_back({p, ComputeMetrics(real_time), ComputeMetrics(post)});
  }
  return out;
}

const RunRecord* Paper004FigureRun(const std::vector<RunRecord>& runs) {
  const RunRecord* best = nullptr;
  double best_distance = 0;
  for (const SweepPoint& p : PostLocalizationPoints(runs)) {
    if (p.algorithm != "hc4") continue;
    for (const RunRecord* r : p.ok_runs) {
      if (!DefaultHc4(*r)) continue;
      if (!ReportsPostStates(*r)) continue;
      const double distance = std::abs(p.value - kPaperWindow);
      if (!best || distance < best_distance ||
          (distance == best_distance && r->spec.seed < best->spec.seed)) {
        best = r;
        best_distance = distance;
      }
    }
  }
  return best;
}

std::vector<TextTable> Paper004Tables(const std::vector<RunRecord>& runs) {
  std::vector<TextTable> out = {PostLocalizationTable(runs)};
  for (TextTable& t : Paper004VisualTables(runs)) out.push_back(std::move(t));
  return out;
}

void Paper004Figures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                     PlotOutput* out) {
  Paper004VisualFigures(runs, out_dir, out);
  const FigureText text{"fig13_post_localization",
                        "Interval error, real-time localization (top) and post-localization",
                        "no ok HC4 car-track run of experiment window with post-localized states "
                        "(specs/default.yaml produces them)"};
  const RunRecord* run = Paper004FigureRun(runs);
  if (!run) {
    // HC4's window runs stored with `record: runs` keep no post-localized
    // states: the message names them rather than saying there is no run.
    std::vector<const RunRecord*> runs_only;
    for (const SweepPoint& p : Paper000Fig2Points(Paper000WindowSweep(runs))) {
      if (p.algorithm != "hc4") continue;
      for (const RunRecord* r : p.ok_runs)
        if (RecordedRunsOnly(*r) && DefaultHc4(*r)) runs_only.push_back(r);
    }
    return SkipFigure(text, runs_only, out);
  }
  PlotPostLocalizationFigure(text, *run, out_dir, out);
}

void PlotPostLocalizationFigure(const FigureText& text, const RunRecord& run,
                                const std::string& out_dir, PlotOutput* out) {
  RunRecord post = run;
  post.steps = PostLocalizedStates(run.steps);
  const std::string label = RunLabel(run);
  PlotCorridorFigure(text, {&run, &post}, {label + ", real time", label + ", post-localized"},
                     out_dir, out);
}

}  // namespace icp
