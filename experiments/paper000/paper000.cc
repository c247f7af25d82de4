#include "experiments/paper000/paper000.h"

#include <algorithm>
#include <limits>
#include <set>

#include "experiments/paper000/own_experiments.h"
#include "harness/spec.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kDash = "—";

// HC4 at default parameters on g's problem configuration, among the groups:
// what "measured / HC4" divides by.
const GroupSummary* Hc4Reference(const std::vector<const GroupSummary*>& groups,
                                 const GroupSummary& g) {
  for (const GroupSummary* h : groups) {
    if (h->algorithm == "hc4" && h->algorithm_params.empty() && h->problem == g.problem &&
        h->problem_params == g.problem_params)
      return h;
  }
  return nullptr;
}

TextTable PublishedTable(const std::vector<GroupSummary>& all_groups) {
  const std::vector<const GroupSummary*> groups = Paper000Table1Groups(all_groups);
  std::vector<double> times;
  for (const GroupSummary* g : groups) times.push_back(RunMedian(*g, RunMeanTime).median);
  const Unit unit = TimeUnit(times);
  TextTable t;
  t.title = "Paper 000 Table 1: time per CSP, published vs measured (car-track, w = 20)";
  t.headers = {"algorithm", "published (ms)", "measured (" + unit.name + ") [95% CI]",
               "speed-up (published / measured) [95% CI]", "published / HC4",
               "measured / HC4 [95% CI]", "runs", "CSPs", "problem params"};
  t.numeric = {false, true, true, true, true, true, true, true, false};
  // The published algorithms and any other that experiment table1 ran.
  std::vector<std::string> algorithms;
  for (const PublishedTime& p : Paper000PublishedTimes()) algorithms.push_back(p.algorithm);
  for (const GroupSummary* g : groups) {
    if (std::find(algorithms.begin(), algorithms.end(), g->algorithm) == algorithms.end())
      algorithms.push_back(g->algorithm);
  }
  std::stable_sort(algorithms.begin(), algorithms.end(), AlgorithmLess);
  const double hc4_published = Paper000PublishedTimes().front().ms;
  for (const std::string& algorithm : algorithms) {
    double published = kNaN;
    for (const PublishedTime& p : Paper000PublishedTimes())
      if (p.algorithm == algorithm) published = p.ms;
    std::vector<const GroupSummary*> rows;
    for (const GroupSummary* g : groups)
      if (g->algorithm == algorithm) rows.push_back(g);
    if (rows.empty()) rows.push_back(nullptr);  // a published algorithm not run: dashes
    for (const GroupSummary* g : rows) {
      MedianInterval measured, speed_up, to_hc4;
      if (g) {
        measured = RunMedian(*g, RunMeanTime);
        // published / measured falls as measured grows: the interval's ends swap.
        const double published_s = published * 1e-3;
        speed_up = measured;
        speed_up.median = published_s / measured.median;
        speed_up.lo = published_s / measured.hi;
        speed_up.hi = published_s / measured.lo;
        if (const GroupSummary* hc4 = Hc4Reference(groups, *g))
          to_hc4 = PairedRatio(*g, *hc4, RunMeanTime);
      }
      t.rows.push_back({WithParams(DisplayOf(algorithm).label, g ? g->algorithm_params : ParamMap{}),
                        FormatNumber(published), FormatWithInterval(measured, unit.scale),
                        FormatWithInterval(speed_up), FormatRatio(published, hc4_published),
                        FormatWithInterval(to_hc4), g ? OkRunsCell(*g) : kDash,
                        g ? std::to_string(g->metrics.steps) : kDash,
                        g ? ParamsCell(g->problem_params) : kDash});
    }
  }
  t.notes.push_back(
      "Measured: each run's mean solve time per CSP, then the median over the ok runs (one "
      "per seed) of each configuration with a run of experiment table1, with the 95% "
      "confidence interval of that median (order statistics, from 6 runs on), rounded to the "
      "interval's leading digit; the speed-up divides the published time by both. Measured / HC4: per "
      "seed, the run's time over HC4's on the same instance (HC4 at default parameters on the "
      "same problem configuration), then their median and interval. Non-default algorithm "
      "parameters follow the label; CSPs: over all the runs. Published: paper 000 Table 1 "
      "(one lap, 2000 CSPs, w = 20). — : no such runs in the store.");
  return t;
}

TextTable SweepTable(const std::vector<SweepPoint>& points) {
  std::vector<double> times;
  for (const SweepPoint& p : points) times.push_back(p.mean_time_s);
  const Unit unit = TimeUnit(times);
  TextTable t;
  t.title = "Window sweep on car-track (paper 000 Fig. 2)";
  t.headers = {"configuration", "w", "runs", "CSPs", "mean area (m²) [95% CI]",
               "mean area over the window (m²) [95% CI]",
               "mean time (" + unit.name + ") [95% CI]"};
  t.numeric = {false, true, true, true, true, true, true};
  for (const SweepPoint& p : points) {
    const GroupSummary g = Summarise(p.ok_runs);
    t.rows.push_back({p.label, FormatNumber(p.value), std::to_string(p.runs),
                      std::to_string(p.steps), FormatWithInterval(RunMedian(g, RunMeanArea)),
                      FormatWithInterval(RunMedian(g, RunMeanWindowArea)),
                      FormatWithInterval(RunMedian(g, RunMeanTime), unit.scale)});
  }
  t.notes.push_back(
      "Each run's mean over its CSPs, then the median over the runs (seeds) with its 95% "
      "confidence interval (order statistics, from 6 runs on). mean area: the newest state's "
      "box (the real-time localization); mean area over the window: the mean x-y area of all "
      "the window's states, averaged over the steps (the later states smoothed by the "
      "window's measurements; not the post-localized area of the paper 004 table, which "
      "counts each state once, as the last window holding it leaves it).");
  t.omit_if_empty = true;
  if (points.empty()) t.notes.push_back("No car-track configuration was run at several w.");
  return t;
}

// "car-track, w = 20" or "car-track, w = 5, steps=600": the paper's figures
// name the window; one entry per problem configuration of the runs.
std::string Setting(const std::vector<const RunRecord*>& runs) {
  std::set<std::string> settings;
  for (const RunRecord* r : runs) {
    ParamMap others = r->spec.problem_params;
    std::string w = ProblemDefaults(r->spec.problem)["w"];
    if (others.count("w")) w = others["w"];
    others.erase("w");
    std::string text = r->spec.problem;
    if (!w.empty()) text += ", w = " + w;
    if (!others.empty()) text += ", " + CompactParams(others);
    settings.insert(text);
  }
  std::string out;
  for (const std::string& s : settings) out += (out.empty() ? "" : "; ") + s;
  return out;
}

}  // namespace

const std::vector<PublishedTime>& Paper000PublishedTimes() {
  static const std::vector<PublishedTime> kTable = {
      {"hc4", 0.52}, {"bc3", 1.02}, {"bc4", 0.58}, {"3b-bc4", 1400}};
  return kTable;
}

std::vector<const GroupSummary*> Paper000Table1Groups(const std::vector<GroupSummary>& groups) {
  std::vector<const GroupSummary*> out;
  for (const GroupSummary& g : groups)
    if (g.ok > 0 && HasExperiment(g, kPaper000Table1)) out.push_back(&g);
  return out;
}

std::vector<const RunRecord*> Paper000LapRuns(const std::vector<GroupSummary>& all_groups) {
  std::vector<const GroupSummary*> groups = Paper000Table1Groups(all_groups);
  std::stable_sort(groups.begin(), groups.end(), [](const GroupSummary* a, const GroupSummary* b) {
    return AlgorithmLess(a->algorithm, b->algorithm);
  });
  std::vector<const RunRecord*> shown;
  for (const GroupSummary* g : groups) {
    const RunRecord* best = nullptr;
    for (const RunRecord* r : g->ok_runs) {
      if (!r->steps.empty() && (!best || r->spec.seed < best->spec.seed)) best = r;
    }
    if (best) shown.push_back(best);
  }
  return shown;
}

namespace {
// Of each table1 configuration that Paper000LapRuns leaves out because no ok
// run has steps, its smallest seed stored with `record: runs`, if any.
std::vector<const RunRecord*> LapRunsWithoutSteps(const std::vector<GroupSummary>& all_groups) {
  std::vector<const RunRecord*> out;
  for (const GroupSummary* g : Paper000Table1Groups(all_groups)) {
    const RunRecord* best = nullptr;
    for (const RunRecord* r : g->ok_runs) {
      if (!r->steps.empty()) {
        best = nullptr;
        break;
      }
      if (RecordedRunsOnly(*r) && (!best || r->spec.seed < best->spec.seed)) best = r;
    }
    if (best) out.push_back(best);
  }
  return out;
}
}  // namespace

std::vector<SweepPoint> Paper000WindowSweep(const std::vector<RunRecord>& runs) {
  return ParamSweep(runs, "car-track", "w");
}

std::vector<SweepPoint> Paper000Fig2Points(const std::vector<SweepPoint>& sweep) {
  std::set<std::string> labels;
  for (const SweepPoint& p : sweep) {
    for (const RunRecord* r : p.ok_runs)
      if (ExperimentOf(*r) == kPaper000Window) labels.insert(p.label);
  }
  std::vector<SweepPoint> out;
  for (const SweepPoint& p : sweep)
    if (labels.count(p.label)) out.push_back(p);
  return out;
}

std::vector<TextTable> Paper000Tables(const std::vector<RunRecord>& runs) {
  return {PublishedTable(SummariseGroups(runs)), SweepTable(Paper000WindowSweep(runs))};
}

std::vector<TextTable> Paper000ReportTables(const std::vector<RunRecord>& runs) {
  std::vector<TextTable> tables = Paper000Tables(runs);
  for (TextTable& t : Paper000OwnExperimentTables(runs)) tables.push_back(std::move(t));
  return tables;
}

void Paper000Figures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                     PlotOutput* out) {
  PlotSweepFigure({"fig2_window",
                   "Average localization area and computing time against the window w (car-track)",
                   "no car-track configuration of experiment window with ok runs at two or more w"},
                  "window w (steps)", Paper000Fig2Points(Paper000WindowSweep(runs)), out_dir, out);

  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  const std::vector<const RunRecord*> shown = Paper000LapRuns(groups);
  const std::string setting = Setting(shown);
  // The figures name what they lack: behind the runs drawn, those of the
  // configurations whose ok runs were all stored with `record: runs`.
  std::vector<const RunRecord*> given = shown;
  for (const RunRecord* r : LapRunsWithoutSteps(groups)) given.push_back(r);
  PlotCorridorFigure({"fig3_corridors", "Interval error over the lap (" + setting + ")",
                      "no ok run of experiment table1 with steps and truth"},
                     given, out_dir, out);
  PlotAreaFigure({"fig4_area", "Size of the localization area (" + setting + ")",
                  "no ok run of experiment table1 with areas"},
                 given, out_dir, out);
}

}  // namespace icp
