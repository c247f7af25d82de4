#include "paper/claim_measures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "harness/metrics.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

RunSpec ConfigOf(const GroupSummary& g) {
  RunSpec spec;
  spec.algorithm = g.algorithm;
  spec.algorithm_params = g.algorithm_params;
  spec.problem = g.problem;
  spec.problem_params = g.problem_params;
  return spec;
}

std::string Metric(const YAML::Node& measure) {
  if (!measure["metric"]) throw ClaimsError("the measure needs 'metric'");
  return measure["metric"].as<std::string>();
}

// The selectors under key; the measure needs at least one.
std::vector<RunSelector> Selectors(const YAML::Node& measure, const char* key) {
  std::vector<RunSelector> out = SelectorsUnder(measure, key);
  if (out.empty()) throw ClaimsError(std::string("the measure needs '") + key + "'");
  return out;
}

RunSelector OneSelector(const YAML::Node& measure, const char* key) {
  const std::vector<RunSelector> s = Selectors(measure, key);
  if (s.size() != 1) throw ClaimsError(std::string("'") + key + "' takes one selector");
  return s.front();
}

Measurement Missing(const ClaimContext& context, const RunSelector& s) {
  Measurement m;
  m.missing = MissingRuns(context, s);
  return m;
}

std::function<double(const RunRecord&)> ValueOf(const std::string& metric) {
  return [metric](const RunRecord& run) { return RunMetric(run, metric); };
}

std::string SeedsText(int n) { return std::to_string(n) + (n == 1 ? " seed" : " seeds"); }

// "0.0177 [0.0171, 0.0183] ms, median of 6 seeds".
std::string IntervalText(const MedianInterval& m, const std::string& unit, double scale = 1) {
  return FormatWithInterval(m, scale) + unit + ", median of " + SeedsText(m.n);
}

Measurement MeasureMetric(const YAML::Node& measure, const ClaimContext& context) {
  const RunSelector s = OneSelector(measure, "runs");
  const GroupSummary* g = OnlyMatch(context, s);
  if (!g) return Missing(context, s);
  const std::string metric = Metric(measure);
  const MedianInterval m = RunMedian(*g, ValueOf(metric));
  return {m.median, "", IntervalText(m, UnitOf(metric)), ""};
}

Measurement MeasureRatio(const YAML::Node& measure, const ClaimContext& context) {
  const RunSelector a = OneSelector(measure, "runs"), b = OneSelector(measure, "of");
  const GroupSummary* ga = OnlyMatch(context, a);
  if (!ga) return Missing(context, a);
  const GroupSummary* gb = OnlyMatch(context, b);
  if (!gb) return Missing(context, b);
  const MedianInterval m = PairedRatio(*ga, *gb, ValueOf(Metric(measure)));
  if (m.n == 0) return Missing(context, b);
  return {m.median, "", IntervalText(m, "") + " (paired by seed)", ""};
}

Measurement MeasureFall(const YAML::Node& measure, const ClaimContext& context) {
  const RunSelector from = OneSelector(measure, "from"), to = OneSelector(measure, "to");
  const GroupSummary* gf = OnlyMatch(context, from);
  if (!gf) return Missing(context, from);
  const GroupSummary* gt = OnlyMatch(context, to);
  if (!gt) return Missing(context, to);
  const std::string metric = Metric(measure);
  MedianInterval ratio = PairedRatio(*gt, *gf, ValueOf(metric));
  if (ratio.n == 0) return Missing(context, to);
  MedianInterval fall = ratio;
  fall.median = 1 - ratio.median, fall.lo = 1 - ratio.hi, fall.hi = 1 - ratio.lo;
  const std::string unit = UnitOf(metric);
  const std::string text = IntervalText(fall, " %", 100) + " (" +
                           FormatNumber(RunMedian(*gf, ValueOf(metric)).median) + " to " +
                           FormatNumber(RunMedian(*gt, ValueOf(metric)).median) + unit + ")";
  return {fall.median, "", text, ""};
}

// The medians of each configuration a list of selectors picks, with labels.
struct Labelled {
  std::string label;
  double value;
};
std::optional<std::vector<Labelled>> Medians(const YAML::Node& measure,
                                             const ClaimContext& context, Measurement* missing) {
  std::vector<Labelled> out;
  const std::string metric = Metric(measure);
  for (const RunSelector& s : Selectors(measure, "runs")) {
    const GroupSummary* g = OnlyMatch(context, s);
    if (!g) {
      *missing = Missing(context, s);
      return std::nullopt;
    }
    out.push_back({LabelOf(s, g), RunMedian(*g, ValueOf(metric)).median});
  }
  return out;
}

std::string ListText(const std::vector<Labelled>& values, const std::string& unit) {
  std::string out;
  for (const Labelled& v : values)
    out += (out.empty() ? "" : ", ") + v.label + " " + FormatNumber(v.value);
  return out + unit + " (medians over seeds)";
}

Measurement MeasureSpread(const YAML::Node& measure, const ClaimContext& context) {
  Measurement missing;
  const auto values = Medians(measure, context, &missing);
  if (!values) return missing;
  const auto [lo, hi] = std::minmax_element(
      values->begin(), values->end(),
      [](const Labelled& a, const Labelled& b) { return a.value < b.value; });
  const double spread = hi->value / lo->value;
  return {spread, "", FormatNumber(spread) + ": " + ListText(*values, UnitOf(Metric(measure))),
          ""};
}

Measurement MeasureFastest(const YAML::Node& measure, const ClaimContext& context) {
  Measurement missing;
  const auto values = Medians(measure, context, &missing);
  if (!values) return missing;
  const Labelled& best = *std::min_element(
      values->begin(), values->end(),
      [](const Labelled& a, const Labelled& b) { return a.value < b.value; });
  return {best.value, best.label,
          best.label + ": " + ListText(*values, UnitOf(Metric(measure))), ""};
}

Measurement MeasureLowest(const YAML::Node& measure, const ClaimContext& context) {
  const std::string metric = Metric(measure);
  double lowest = kNaN;
  std::string which;
  int configurations = 0, steps = 0;
  for (const RunSelector& s : Selectors(measure, "runs")) {
    for (const GroupSummary* g : Matching(context, s)) {
      const double v = PooledMetric(*g, metric);
      ++configurations, steps += g->metrics.steps;
      if (std::isnan(lowest) || v < lowest) lowest = v, which = LabelOf(s, g);
    }
  }
  // Over what the store has; no data only when no selector picks a run.
  if (configurations == 0) return Missing(context, Selectors(measure, "runs").front());
  return {lowest, "",
          "lowest " + FormatNumber(lowest) + UnitOf(metric) + " (" + which + ") over " +
              std::to_string(configurations) + " configurations, " + std::to_string(steps) +
              " steps",
          ""};
}

// R² of the least-squares line through (x, y); NaN when either is constant.
double LinearR2(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = x.size();
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / n, my += y[i] / n;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0 && syy > 0 ? sxy * sxy / (sxx * syy) : kNaN;
}

Measurement MeasureLinearR2(const YAML::Node& measure, const ClaimContext& context) {
  const std::string metric = Metric(measure);
  if (!measure["over"]) throw ClaimsError("linear_r2 needs 'over', a problem parameter");
  const std::string over = measure["over"].as<std::string>();
  double worst = kNaN;
  std::string which;
  for (const RunSelector& s : Selectors(measure, "runs")) {
    std::vector<double> x, y;
    const std::vector<const GroupSummary*> groups = Matching(context, s);
    for (const GroupSummary* g : groups) {
      const auto it = g->problem_params.find(over);
      const std::string value =
          it != g->problem_params.end() ? it->second : ProblemDefaults(g->problem)[over];
      x.push_back(std::stod(value));
      y.push_back(RunMedian(*g, ValueOf(metric)).median);
    }
    if (x.size() < 3) return Missing(context, s);
    const double r2 = LinearR2(x, y);
    if (std::isnan(worst) || r2 < worst) worst = r2, which = LabelOf(s, groups.front());
  }
  return {worst, "", "lowest R² " + FormatNumber(worst) + " (" + which + ")", ""};
}

}  // namespace

std::vector<const GroupSummary*> Matching(const ClaimContext& context, const RunSelector& s) {
  std::vector<const GroupSummary*> out;
  for (const GroupSummary& g : context.groups) {
    const RunSpec config = ConfigOf(g);
    if (std::any_of(g.ok_runs.begin(), g.ok_runs.end(), [&](const RunRecord* run) {
          return Selects(s, config, ExperimentOf(*run));
        }))
      out.push_back(&g);
  }
  return out;
}

const GroupSummary* OnlyMatch(const ClaimContext& context, const RunSelector& s) {
  const std::vector<const GroupSummary*> groups = Matching(context, s);
  if (groups.size() > 1)
    throw ClaimsError(SelectorText(s) + " picks " + std::to_string(groups.size()) +
                      " configurations; the measure needs one");
  return groups.empty() ? nullptr : groups.front();
}

double RunMetric(const RunRecord& run, const std::string& metric) {
  if (metric == "time_ms") return RunMeanTime(run) * 1e3;
  if (metric == "time_us") return RunMeanTime(run) * 1e6;
  if (metric == "area") return RunMeanArea(run);
  if (metric == "consistency") return run.metrics.consistency_rate;
  if (metric == "centre_rmse") return run.metrics.centre_rmse;
  if (metric == "run_time_s") return run.metrics.time_mean_s * run.metrics.steps;
  if (metric == "median_centre_error") {
    std::vector<double> errors;
    for (const StepRecord& s : run.steps)
      if (std::isfinite(s.centre_error)) errors.push_back(s.centre_error);
    return errors.empty() ? kNaN : Quantile(errors, 0.5);
  }
  if (metric.rfind("property:", 0) == 0)
    return NumberProperty(run.properties, metric.substr(9)).value_or(kNaN);
  throw ClaimsError("unknown metric '" + metric + "'");
}

double PooledMetric(const GroupSummary& group, const std::string& metric) {
  if (metric == "time_ms") return group.metrics.time_mean_s * 1e3;
  if (metric == "time_us") return group.metrics.time_mean_s * 1e6;
  if (metric == "area") return group.metrics.mean_area;
  if (metric == "consistency") return group.metrics.consistency_rate;
  if (metric == "centre_rmse") return group.metrics.centre_rmse;
  double total = 0;
  int steps = 0;
  for (const RunRecord* run : group.ok_runs) {
    const double v = RunMetric(*run, metric);
    if (std::isnan(v)) return kNaN;
    total += v * run->metrics.steps, steps += run->metrics.steps;
  }
  return steps > 0 ? total / steps : kNaN;
}

std::string UnitOf(const std::string& metric) {
  if (metric == "time_ms") return " ms";
  if (metric == "time_us") return " µs";
  if (metric == "area") return " m²";
  if (metric == "centre_rmse" || metric == "median_centre_error") return " m";
  if (metric == "run_time_s") return " s";
  return "";
}

std::string LabelOf(const RunSelector& s, const GroupSummary* group) {
  if (!s.label.empty()) return s.label;
  if (!group) return s.algorithm;
  return WithParams(DisplayOf(group->algorithm).label, group->algorithm_params);
}

RunSelector ExplainedSelector(const Claim& claim, const char* key) {
  const YAML::Node node = claim.if_differs[key] ? claim.if_differs[key] : claim.measure[key];
  if (!node) throw ClaimsError(std::string("the explainer needs '") + key + "'");
  return ParseSelector(node);
}

std::string UnexplainedBecause(const Claim& claim, const ClaimContext& context) {
  if (!claim.if_differs["runs"] && !claim.measure["runs"]) return "";
  bool any = false;
  for (const GroupSummary* g : Matching(context, ExplainedSelector(claim, "runs")))
    for (const RunRecord* run : g->ok_runs) {
      if (!RecordedRunsOnly(*run)) return "";
      any = true;
    }
  return any ? "its explanation reads the runs' steps, and these runs were stored without them "
               "(record: runs)"
             : "";
}

std::string MissingRuns(const ClaimContext& context, const RunSelector& s) {
  return "no ok run matches " + SelectorText(s) + ": icpbench run " + context.spec +
         " produces them";
}

const ClaimFunctions& ClaimFunctionsRegistry() {
  static const ClaimFunctions functions = [] {
    ClaimFunctions f;
    f.measures = {{"metric", MeasureMetric},   {"ratio", MeasureRatio},
                  {"fall", MeasureFall},       {"spread", MeasureSpread},
                  {"fastest", MeasureFastest}, {"lowest", MeasureLowest},
                  {"linear_r2", MeasureLinearR2}};
    AddPaper000ClaimFunctions(&f);
    AddPaper002ClaimFunctions(&f);
    AddThesis003ClaimFunctions(&f);
    AddPaper004ClaimFunctions(&f);
    return f;
  }();
  return functions;
}

}  // namespace icp
