#include "experiments/thesis003/thesis003.h"

#include "experiments/thesis003/city_roads.h"
#include "experiments/thesis003/fig5_2.h"
#include "experiments/thesis003/marina.h"
#include "experiments/thesis003/marina_figures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <stdexcept>
#include <variant>

#include "algorithms/accumulator/accumulator.h"
#include "core/contractor.h"
#include "core/grid.h"
#include "harness/metrics.h"
#include "problems/beacon_ranges/beacon_ranges.h"
#include "problems/registry.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kDash = "—";

TextTable RelaxedTable(const std::vector<RunRecord>& runs) {
  std::vector<const GroupSummary*> groups;
  const std::vector<GroupSummary> all = SummariseGroups(runs);
  std::vector<double> times;
  for (const GroupSummary& g : all) {
    if (!HasExperiment(g, kThesis003RelaxedLines) && !HasExperiment(g, kThesis003RelaxedBeacons))
      continue;
    groups.push_back(&g);
    times.push_back(RunMedian(g, RunMeanTime).median);
  }
  const Unit unit = TimeUnit(times);
  TextTable t;
  t.title = "Thesis 003: relaxed solvers";
  t.headers = {"configuration",
               "problem",
               "runs",
               "steps",
               "consistency",
               "mean area (m²) [95% CI]",
               "mean q",
               "mean true outliers",
               "q ≤ true outliers",
               "empty",
               "time per step (" + unit.name + ") [95% CI]"};
  t.numeric = {false, false, true, true, true, true, true, true, true, true, true};
  for (const GroupSummary* group : groups) {
    const GroupSummary& g = *group;
    int steps = 0, known = 0, contained = 0, empty = 0, compared = 0, q_within = 0;
    std::vector<double> qs, outliers;
    for (const RunRecord* r : g.ok_runs) {
      for (const StepRecord& s : r->steps) {
        ++steps;
        if (s.contained >= 0) {
          ++known;
          contained += s.contained;
        }
        empty += IsEmptyEstimate(s);
        const std::optional<double> q = NumberProperty(s.properties, "q");
        const std::optional<double> k = NumberProperty(s.properties, "true_outliers");
        if (q) qs.push_back(*q);
        if (k) outliers.push_back(*k);
        if (q && k) {
          ++compared;
          q_within += *q <= *k;
        }
      }
    }
    t.rows.push_back({WithParams(DisplayOf(g.algorithm).label, g.algorithm_params),
                      WithParams(g.problem, g.problem_params), OkRunsCell(g), std::to_string(steps),
                      FormatRatio(contained, known), FormatWithInterval(RunMedian(g, RunMeanArea)),
                      FormatNumber(Mean(qs)), FormatNumber(Mean(outliers)),
                      FormatRatio(q_within, compared), FormatRatio(empty, steps),
                      FormatWithInterval(RunMedian(g, RunMeanTime), unit.scale)});
    for (const std::string& p : g.problems) t.items.push_back(ProblemItem(g, p));
  }
  t.notes.push_back(
      "Every configuration with a run of experiment relaxed-lines or relaxed-beacons, over the "
      "steps of its ok runs (every seed); runs: ok runs (of all, when some failed). "
      "Consistency: share of the steps whose estimate holds the truth. Mean area (over the "
      "steps with a non-empty estimate) and time per step: each run's mean, then the median "
      "over the runs (seeds) with its 95% confidence interval (order statistics, from 6 runs "
      "on). q: the number of measurements the solver found it must "
      "drop (step property q); true outliers: how many were wrong; q ≤ true outliers: share of "
      "the steps where the solver dropped no more than the truth requires. Empty: share of the "
      "steps with an empty estimate (ICP once an outlier is in). — : no such value (HC4 "
      "reports no q).");
  if (t.rows.empty())
    t.notes.push_back("No run of experiment relaxed-lines or relaxed-beacons in the store.");
  return t;
}

// "(1.234, -0.5)".
std::string Point(double x, double y) {
  return "(" + FormatNumber(x) + ", " + FormatNumber(y) + ")";
}

// The centre of the maximum's hull in the grid's coordinates.
std::pair<double, double> MaximumCentre(const RecomputedAccumulator& a, const cv::Mat& counts,
                                        const AccumulatorMaximum& m) {
  const double cx = a.x.Width() / counts.cols, cy = a.y.Width() / counts.rows;
  return {a.x.lo() + 0.5 * (m.col0 + m.col1) * cx, a.y.lo() + 0.5 * (m.row0 + m.row1) * cy};
}

std::string Regions(int n) {
  return n == 1 ? "in one region" : "in " + std::to_string(n) + " separate regions";
}

std::string Plural(int n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

std::string RunSetting(const RunRecord& r, const cv::Mat& counts) {
  return r.spec.problem +
         (r.spec.problem_params.empty() ? "" : " " + CompactParams(r.spec.problem_params)) +
         ", seed " + std::to_string(r.spec.seed) + ", " + std::to_string(counts.cols) + "x" +
         std::to_string(counts.rows) + " cells";
}

std::vector<MarkerSet> Truth(const RecomputedAccumulator& a) {
  if (a.truth.size() < 2) return {};
  return {{"truth", {{a.truth[0], a.truth[1]}}, true}};
}

void SkipWith(const std::string& name, const std::string& reason, PlotOutput* out) {
  out->messages.push_back(name + ": skipped: " + reason);
}

// Draws nothing but the skip message of text.
void Missing(const FigureText& text, const std::string& out_dir, PlotOutput* out) {
  PlotAccumulatorFigure(text, cv::Mat(), Interval(0, 1), Interval(0, 1), {}, out_dir, out);
}

void LinesAccumulator(const std::vector<RunRecord>& runs, const std::string& out_dir, PlotOutput* out) {
  FigureText text{"fig_lines_accumulator", "",
                  std::string("no ok accumulator run of experiment ") +
                      kThesis003LinesAccumulator};
  const RunRecord* run = Thesis003FigureRun(runs, kThesis003LinesAccumulator);
  if (!run) return Missing(text, out_dir, out);
  RecomputedAccumulator a;
  try {
    a = RecomputeAccumulator(*run);
  } catch (const std::exception& e) {
    return SkipWith(text.name, e.what(), out);
  }
  const cv::Mat& sum = a.counts.back();
  const AccumulatorMaximum m = FindMaximum(sum);
  const auto [mx, my] = MaximumCentre(a, sum, m);
  int lines = 0, wrong = 0;
  for (int n : a.measurements) lines += n;
  for (int n : a.outliers) wrong += n;
  text.title = "Accumulator of " + Plural(lines, "line") + ", " + Plural(wrong, "outlier") +
               ": max count " + std::to_string(m.count) + " of " + std::to_string(lines) +
               " lines at " + Point(mx, my) + " " + Regions(m.regions) + "\n(" +
               RunSetting(*run, sum) + ")";
  PlotAccumulatorFigure(text, sum, a.x, a.y, Truth(a), out_dir, out);
}

void Fig55To57(const std::vector<RunRecord>& runs, const std::string& out_dir, PlotOutput* out) {
  const char* const kNames[3] = {"fig5_5_robot_a", "fig5_6_robot_b", "fig5_7_sum"};
  const std::string none = std::string("no ok accumulator run of experiment ") + kThesis003Fig55;
  const RunRecord* run = Thesis003FigureRun(runs, kThesis003Fig55);
  if (!run) {
    for (const char* name : kNames) Missing({name, "", none}, out_dir, out);
    return;
  }
  RecomputedAccumulator a;
  try {
    a = RecomputeAccumulator(*run);
  } catch (const std::exception& e) {
    for (const char* name : kNames) SkipWith(name, e.what(), out);
    return;
  }
  const int sources = static_cast<int>(a.counts.size()) - 1;
  const char* const kRobot[2] = {"A", "B"};
  for (int s = 0; s < 2; ++s) {
    if (s >= sources) {
      SkipWith(kNames[s], "the run of experiment fig5_5 has no source " + std::to_string(s), out);
      continue;
    }
    const AccumulatorMaximum m = FindMaximum(a.counts[s]);
    std::vector<MarkerSet> markers = Truth(a);
    if (s < static_cast<int>(a.beacons.size()))
      markers.push_back({std::string("beacons of robot ") + kRobot[s], a.beacons[s], false});
    const std::string title =
        std::string("Robot ") + kRobot[s] + " alone (source " + std::to_string(s) + ": " +
        Plural(a.measurements[s], "range") + ", " + Plural(a.outliers[s], "outlier") +
        "): max count " + std::to_string(m.count) + " of " + std::to_string(a.measurements[s]) +
        " " + Regions(m.regions) + "\n(" + RunSetting(*run, a.counts[s]) + ")";
    PlotAccumulatorFigure({kNames[s], title, none}, a.counts[s], a.x, a.y, markers, out_dir, out);
  }
  const cv::Mat& sum = a.counts.back();
  const AccumulatorMaximum m = FindMaximum(sum);
  const auto [mx, my] = MaximumCentre(a, sum, m);
  int ranges = 0, wrong = 0;
  for (int n : a.measurements) ranges += n;
  for (int n : a.outliers) wrong += n;
  std::vector<MarkerSet> markers = Truth(a);
  MarkerSet beacons{"beacons", {}, false};
  for (const auto& b : a.beacons) beacons.points.insert(beacons.points.end(), b.begin(), b.end());
  if (!beacons.points.empty()) markers.push_back(beacons);
  const std::string title = "Sum of both robots (" + Plural(ranges, "range") + ", " +
                            Plural(wrong, "outlier") + "): max count " + std::to_string(m.count) +
                            " of " + std::to_string(ranges) + " at " + Point(mx, my) + " " +
                            Regions(m.regions) + "\n(" + RunSetting(*run, sum) + ")";
  PlotAccumulatorFigure({kNames[2], title, none}, sum, a.x, a.y, markers, out_dir, out);
}

}  // namespace

const std::vector<AccumulatorPublished>& Thesis003PublishedAccumulators() {
  static const std::vector<AccumulatorPublished> kFigures = {
      {"fig5_5_robot_a", "Fig. 5.5", 0, 3, 0, 3},
      {"fig5_6_robot_b", "Fig. 5.6", 1, 0, 0, 4},
      {"fig5_7_sum", "Fig. 5.7", -1, 1, 4, 7},
  };
  return kFigures;
}

const RunRecord* Thesis003FigureRun(const std::vector<RunRecord>& runs,
                                    const std::string& experiment) {
  const RunRecord* best = nullptr;
  for (const RunRecord& r : runs) {
    if (r.status != RunStatus::kOk || r.spec.algorithm != "accumulator" ||
        ExperimentOf(r) != experiment)
      continue;
    if (!best || r.spec.seed < best->spec.seed) best = &r;
  }
  return best;
}

Step FirstMeasurementSetStep(const RunRecord& run) {
  std::unique_ptr<Problem> problem =
      FindProblem(run.spec.problem).make(run.spec.problem_params, run.spec.seed);
  Step step;
  if (!problem->Next(&step)) throw std::invalid_argument(run.spec.problem + ": no step");
  if (!step.views.measurement_set)
    throw std::invalid_argument(run.spec.problem + ": no measurement-set view to recompute from");
  return step;
}

RecomputedAccumulator RecomputeAccumulator(const RunRecord& run) {
  const AccumulatorParams params =
      ParseParams<AccumulatorParams>("accumulator", run.spec.algorithm_params);
  const Step step = FirstMeasurementSetStep(run);
  const MeasurementSetView& view = *step.views.measurement_set;
  const StateSpace& space = step.views.space;
  const Grid grid = AccumulatorGrid(view.prior, view.prior, space, params.cells);
  RecomputedAccumulator out;
  WorkCounters work;
  bool stopped = false;
  out.counts = SourceAccumulators(grid, view, StopCondition(), &work, &stopped);
  out.x = grid.search()[grid.x()];
  out.y = grid.search()[grid.y()];
  if (!step.truth.empty()) out.truth = {step.truth[grid.x()], step.truth[grid.y()]};
  const int sources = static_cast<int>(out.counts.size()) - 1;
  out.measurements.assign(sources, 0);
  out.outliers.assign(sources, 0);
  for (std::size_t i = 0; i < view.measurements.size(); ++i) {
    const int s = view.sources.empty() ? 0 : view.sources[i];
    ++out.measurements[s];
    if (i < view.outliers.size() && view.outliers[i]) ++out.outliers[s];
  }
  if (run.spec.problem == "beacon-ranges" &&
      ParseBeaconRanges("beacon-ranges", run.spec.problem_params).scenario == "two-robots") {
    out.beacons.assign(sources, {});
    for (const RangeMeasurement& r : ReadBeaconScene(TwoRobotsScenePath()).ranges)
      if (r.source < sources) out.beacons[r.source].push_back({r.beacon_x, r.beacon_y});
  }
  return out;
}

AccumulatorMaximum FindMaximum(const cv::Mat& counts) {
  AccumulatorMaximum m;
  if (counts.empty()) return m;
  double max_count = 0;
  cv::minMaxLoc(counts, nullptr, &max_count);
  m.count = static_cast<int>(max_count);
  cv::Mat at_maximum, labels, stats, centroids;
  cv::compare(counts, max_count, at_maximum, cv::CMP_EQ);
  const int labelled = cv::connectedComponentsWithStats(at_maximum, labels, stats, centroids, 8);
  m.regions = labelled - 1;  // label 0 is the background
  m.row0 = counts.rows, m.col0 = counts.cols;
  for (int i = 1; i < labelled; ++i) {
    CellHull h;
    h.col0 = stats.at<int>(i, cv::CC_STAT_LEFT);
    h.row0 = stats.at<int>(i, cv::CC_STAT_TOP);
    h.col1 = h.col0 + stats.at<int>(i, cv::CC_STAT_WIDTH);
    h.row1 = h.row0 + stats.at<int>(i, cv::CC_STAT_HEIGHT);
    m.hulls.push_back(h);
    m.row0 = std::min(m.row0, h.row0), m.row1 = std::max(m.row1, h.row1);
    m.col0 = std::min(m.col0, h.col0), m.col1 = std::max(m.col1, h.col1);
  }
  return m;
}

std::vector<TextTable> Thesis003Tables(const std::vector<RunRecord>& runs) {
  return {RelaxedTable(runs), MarinaTable(runs)};
}

void Thesis003Figures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                      PlotOutput* out) {
  Fig52Figure(runs, out_dir, out);
  LinesAccumulator(runs, out_dir, out);
  Fig55To57(runs, out_dir, out);
  MarinaFigures(runs, out_dir, out);
  CityRoadsFigure(runs, out_dir, out);
}

}  // namespace icp
