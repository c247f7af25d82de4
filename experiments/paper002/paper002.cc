#include "experiments/paper002/paper002.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "experiments/thesis003/guarantee_columns.h"
#include "harness/spec.h"
#include "problems/indoor_landmarks/indoor_map.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegrees = 180 / std::numbers::pi;
constexpr const char* kProblem = "indoor-landmarks";

std::string PathOf(const RunRecord& run) {
  const auto it = run.spec.problem_params.find("path");
  return it != run.spec.problem_params.end() ? it->second : ProblemDefaults(kProblem).at("path");
}

const VariableRecord* Var(const StepRecord& s, const std::string& name) {
  for (const VariableRecord& v : s.vars)
    if (v.name == name) return &v;
  return nullptr;
}

// Of experiment indoor or indoor-spurious.
bool IsIndoorRun(const RunRecord& run) {
  return run.spec.problem == kProblem && ExperimentOf(run).rfind(kPaper002Experiment, 0) == 0;
}

// The summed property over a group's ok runs; NaN when none has it.
double Total(const GroupSummary& g, const std::string& name) {
  double total = 0;
  bool any = false;
  for (const RunRecord* r : g.ok_runs)
    if (const auto v = NumberProperty(r->properties, name)) total += *v, any = true;
  return any ? total : kNaN;
}

// Each run's IndoorStats, computed once for the table's columns.
class StatsCache {
 public:
  const IndoorRunStats& Of(const RunRecord& run) {
    auto it = stats_.find(&run);
    if (it == stats_.end()) it = stats_.emplace(&run, IndoorStats(run)).first;
    return it->second;
  }

 private:
  std::map<const RunRecord*, IndoorRunStats> stats_;
};

std::string Median(const GroupSummary& g, StatsCache& cache, double (*of)(const IndoorRunStats&)) {
  return FormatWithInterval(RunMedian(g, [&](const RunRecord& r) { return of(cache.Of(r)); }));
}

// Consistency over the steps whose assumption held (for landmark tracking:
// every association so far right): "share (steps)".
std::string ConsistencyWhereHeld(const GroupSummary& g) {
  const GuaranteeSummary guarantee = SummariseGuarantee(g);
  if (guarantee.held == 0) return "—";
  return FormatNumber(100 * guarantee.ConsistencyWhereHeld()) + " (" +
         std::to_string(guarantee.held) + ")";
}

// The configurations with an ok run of the indoor experiments.
std::vector<GroupSummary> IndoorGroups(const std::vector<RunRecord>& runs) {
  std::vector<GroupSummary> groups;
  for (GroupSummary& g : SummariseGroups(runs))
    if (g.problem == kProblem && std::any_of(g.ok_runs.begin(), g.ok_runs.end(),
                                             [](const RunRecord* r) { return IsIndoorRun(*r); }))
      groups.push_back(std::move(g));
  return groups;
}

// A group's first two cells: the configuration (the problem parameters
// other than the path in brackets) and the path.
std::vector<std::string> Configuration(const GroupSummary& g) {
  ParamMap shown = g.problem_params;
  shown.erase("path");
  return {WithParams(DisplayOf(g.algorithm).label, g.algorithm_params) +
              (shown.empty() ? "" : " [" + CompactParams(shown) + "]"),
          PathOf(*g.ok_runs.front())};
}

constexpr double kConfigurationCm = 4.2;  // the LaTeX column that wraps

// The note of a table with no row.
std::string NoIndoorRuns() {
  return std::string("No ok indoor-landmarks runs of experiment ") + kPaper002Experiment +
         ": specs/default.yaml produces them.";
}

TextTable AccuracyTable(const std::vector<GroupSummary>& groups) {
  TextTable table;
  table.title = "Paper 002: a robot at a corridor's end tracking typed landmarks (indoor-landmarks)";
  table.headers = {"configuration", "path", "runs", "consistent (%)", "while assumption held (%)",
                   "widest x (m)", "widest y (m)", "widest θ (°)", "position error (m)",
                   "heading error (°)"};
  table.numeric = {false, false, true, true, true, true, true, true, true, true};
  table.wrap_cm = {kConfigurationCm};
  table.omit_if_empty = true;
  StatsCache stats;
  for (const GroupSummary& g : groups) {
    std::vector<std::string> row = Configuration(g);
    row.insert(row.end(),
               {OkRunsCell(g), FormatNumber(100 * g.metrics.consistency_rate),
                ConsistencyWhereHeld(g),
                Median(g, stats, [](const IndoorRunStats& s) { return s.widest_x; }),
                Median(g, stats, [](const IndoorRunStats& s) { return s.widest_y; }),
                Median(g, stats, [](const IndoorRunStats& s) { return s.widest_theta_deg; }),
                Median(g, stats, [](const IndoorRunStats& s) { return s.position_error; }),
                Median(g, stats, [](const IndoorRunStats& s) { return s.heading_error_deg; })});
    table.rows.push_back(std::move(row));
  }
  if (table.rows.empty()) {
    table.notes.push_back(NoIndoorRuns());
    return table;
  }
  const Paper002Published& p = kPaper002;
  table.rows.push_back({"odometry alone, paper (Fig. 9)", "2 paths", "", "", "", "grows", "grows",
                        "", "", ""});
  table.rows.push_back({"landmarks, paper (Fig. 11)", "2 paths", "", "", "",
                        "< " + FormatNumber(p.widest_xy), "< " + FormatNumber(p.widest_xy),
                        "< " + FormatNumber(p.widest_theta_deg), "≈ " + FormatNumber(p.position_error),
                        "≈ " + FormatNumber(p.heading_error_deg)});
  table.notes.push_back(
      "Per configuration and path over its seeds: consistent, the share of steps whose box holds "
      "the true pose; while assumption held, the same over the steps where the estimator's "
      "guarantee applies, with their number: for landmark tracking, those before the run's "
      "first wrong association (it assumes every association right); for the relaxed solvers, "
      "those with at most their bound of wrong returns since their last restart; widest, the "
      "median over seeds of the widest box of the run; errors, the median of the run's mean "
      "distance from the box's centre to the truth. The paper's corridor, robot and sensor are "
      "simulated from its description (problems/indoor_landmarks/indoor_drive.h), so its "
      "numbers compare in kind.");
  return table;
}

TextTable AssociationTable(const std::vector<GroupSummary>& groups) {
  TextTable table;
  table.title = "Paper 002: associations and time per step (indoor-landmarks)";
  table.headers = {"configuration", "path", "runs", "associations right / wrong / missed",
                   "wrong → lost", "time per step (ms)"};
  table.numeric = {false, false, true, false, false, true};
  table.wrap_cm = {kConfigurationCm};
  table.omit_if_empty = true;
  for (const GroupSummary& g : groups) {
    const double right = Total(g, "associations_right");
    const double wrong_steps = Total(g, "wrong_association_steps");
    std::vector<std::string> row = Configuration(g);
    row.insert(row.end(),
               {OkRunsCell(g),
                std::isnan(right) ? "—"
                                  : FormatNumber(right) + " / " +
                                        FormatNumber(Total(g, "associations_wrong")) + " / " +
                                        FormatNumber(Total(g, "associations_missed")),
                std::isnan(wrong_steps) ? "—"
                                        : FormatNumber(Total(g, "wrong_association_losses")) +
                                              " of " + FormatNumber(wrong_steps),
                FormatWithInterval(RunMedian(g, RunMeanTime), 1e3)});
    table.rows.push_back(std::move(row));
  }
  if (table.rows.empty()) {
    table.notes.push_back(NoIndoorRuns());
    return table;
  }
  table.notes.push_back(
      "Associations, summed over the seeds: right, a landmark's return given its landmark; "
      "wrong, given another, or a spurious return given any; missed, a landmark's return given "
      "none. Wrong → lost: the steps with a wrong association whose box missed the truth, of "
      "all steps with one. The relaxed solvers, the particle filter and odometry alone do not "
      "associate (—): a wrong association is an outlier to the relaxed solvers. Time: the "
      "median over seeds of the mean solve time per step.");
  return table;
}

// The wall segments as points every 5 cm, for the figures.
std::vector<std::pair<double, double>> WallPoints() {
  std::vector<std::pair<double, double>> points;
  for (const auto& w : ReadIndoorMap(ShippedCorridorMapPath()).walls) {
    const double length = std::hypot(w[2] - w[0], w[3] - w[1]);
    const int n = std::max(1, static_cast<int>(length / 0.05));
    for (int i = 0; i <= n; ++i)
      points.push_back({w[0] + (w[2] - w[0]) * i / n, w[1] + (w[3] - w[1]) * i / n});
  }
  return points;
}

// The ok run of the smallest seed of algorithm at default parameters on
// path at the problem's defaults otherwise.
const RunRecord* FigureRun(const std::vector<RunRecord>& runs, const std::string& algorithm,
                           const std::string& path) {
  const RunRecord* best = nullptr;
  for (const RunRecord& r : runs) {
    if (r.status != RunStatus::kOk || !IsIndoorRun(r) || r.spec.algorithm != algorithm ||
        !r.spec.algorithm_params.empty() || PathOf(r) != path || r.steps.empty())
      continue;
    if (std::any_of(r.spec.problem_params.begin(), r.spec.problem_params.end(),
                    [](const auto& kv) { return kv.first != "path"; }))
      continue;
    if (!best || r.spec.seed < best->spec.seed) best = &r;
  }
  return best;
}

// The runs of algorithm that the figures draw, paths a and b; nullptr
// when either is missing.
std::pair<const RunRecord*, const RunRecord*> BothPaths(const std::vector<RunRecord>& runs,
                                                        const std::string& algorithm) {
  const RunRecord* a = FigureRun(runs, algorithm, "a");
  const RunRecord* b = FigureRun(runs, algorithm, "b");
  if (!a || !b) return {nullptr, nullptr};
  return {a, b};
}

}  // namespace

IndoorRunStats IndoorStats(const RunRecord& run) {
  IndoorRunStats s;
  if (run.steps.empty()) {
    s.widest_x = s.widest_y = s.widest_theta_deg = s.position_error = s.heading_error_deg =
        s.growth_share = kNaN;
    return s;
  }
  double position = 0, heading = 0, previous_volume = kNaN;
  int judged = 0, grew = 0, compared = 0;
  for (const StepRecord& step : run.steps) {
    const VariableRecord* x = Var(step, "x");
    const VariableRecord* y = Var(step, "y");
    const VariableRecord* theta = Var(step, "theta");
    if (!x || !y || !theta) continue;
    s.widest_x = std::max(s.widest_x, x->hi - x->lo);
    s.widest_y = std::max(s.widest_y, y->hi - y->lo);
    s.widest_theta_deg = std::max(s.widest_theta_deg, (theta->hi - theta->lo) * kDegrees);
    if (std::isfinite(step.centre_error) && std::isfinite(theta->truth)) {
      position += step.centre_error;
      heading += std::abs(std::remainder(0.5 * (theta->lo + theta->hi) - theta->truth,
                                         2 * std::numbers::pi)) * kDegrees;
      ++judged;
    }
    const double volume = (x->hi - x->lo) * (y->hi - y->lo) * (theta->hi - theta->lo);
    if (!std::isnan(previous_volume)) ++compared, grew += volume > previous_volume;
    previous_volume = volume;
  }
  s.position_error = judged > 0 ? position / judged : kNaN;
  s.heading_error_deg = judged > 0 ? heading / judged : kNaN;
  s.growth_share = compared > 0 ? static_cast<double>(grew) / compared : kNaN;
  return s;
}

std::vector<TextTable> Paper002Tables(const std::vector<RunRecord>& runs) {
  const std::vector<GroupSummary> groups = IndoorGroups(runs);
  return {AccuracyTable(groups), AssociationTable(groups)};
}

void Paper002Figures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                     PlotOutput* out) {
  // What FigureRun picks, said when it finds nothing.
  auto skip = [](const std::string& algorithm) {
    return "no ok run of " + algorithm +
           " at its default parameters, with its steps stored, on both paths a and b of "
           "indoor-landmarks at the problem's defaults otherwise (specs/default.yaml, experiment " +
           std::string(kPaper002Experiment) + ")";
  };
  // Fig. 9: the boxes on the map. Fig. 11's boxes are a few cm wide, hidden
  // under the track on the map: drawn as their interval errors instead.
  FigureText fig9{"fig9_odometry", "Fig. 9: localization by odometry alone", skip("dead-reckoning")};
  if (const auto [a, b] = BothPaths(runs, "dead-reckoning"); a) {
    fig9.title += " (" + RunLabel(*a) + ")";
    PlotBoxTrackFigure(fig9, WallPoints(), {{"path a", a}, {"path b", b}}, Interval(-0.5, 16.8),
                       Interval(-2.5, 4.5), out_dir, out);
  } else {
    SkipFigure(fig9, {}, out);
  }
  FigureText fig11{"fig11_landmarks",
                   "Fig. 11: localization with the landmarks, the boxes around the truth",
                   skip("landmark-tracking")};
  if (const auto [a, b] = BothPaths(runs, "landmark-tracking"); a) {
    fig11.title += " (" + RunLabel(*a) + ")";
    PlotCorridorFigure(fig11, {a, b}, {"path a", "path b"}, out_dir, out);
  } else {
    SkipFigure(fig11, {}, out);
  }
}

}  // namespace icp
