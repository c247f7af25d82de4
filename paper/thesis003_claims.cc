// Thesis 003's own measures and explainers (experiments/thesis003/claims.yaml):
// the box polynomials of Fig. 5.2 and the accumulators of Figs 5.5-5.7,
// recomputed from their runs as the figures are, the set-membership
// guarantee judged on every step, and the measured reasons of chapter 6's
// differences (where the truth was lost, why the misses missed, the
// filter's coverage at each level).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>

#include "experiments/thesis003/fig5_2.h"
#include "experiments/thesis003/guarantee_columns.h"
#include "experiments/thesis003/thesis003.h"
#include "harness/guarantee.h"
#include "harness/metrics.h"
#include "paper/claim_measures.h"
#include "paper/paper_data.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string Quantity(const YAML::Node& measure, const std::vector<std::string>& known) {
  const std::string q = measure["quantity"] ? measure["quantity"].as<std::string>() : "";
  if (std::find(known.begin(), known.end(), q) == known.end()) {
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw ClaimsError("the measure needs 'quantity', one of " + list);
  }
  return q;
}

// The run a figure draws: of the one configuration the selector picks, the
// ok run with the smallest seed; nullptr when there is none.
const RunRecord* FigureRun(const ClaimContext& context, const RunSelector& s) {
  const GroupSummary* g = OnlyMatch(context, s);
  if (!g) return nullptr;
  const RunRecord* first = nullptr;
  for (const RunRecord* run : g->ok_runs)
    if (!first || run->spec.seed < first->spec.seed) first = run;
  return first;
}

// The widest side of a polynomial's coefficient n - q; NaN when it has none.
double WhiteSide(const RecomputedPolynomial& p) {
  return p.white < static_cast<int>(p.coefficients.size()) ? WidestSide(p.coefficients[p.white])
                                                            : kNaN;
}

// What make() recomputes from a stored run (a figure's polynomial or
// accumulator), once per context and run: several claims and their
// explainers read the same runs.
template <typename T, typename Make>
const T& RecomputedOnce(const ClaimContext& context, const char* kind, const RunRecord& run,
                        Make make) {
  return Cached<T>(context,
                   std::string("thesis003/") + kind + "/" +
                       std::to_string(reinterpret_cast<std::uintptr_t>(&run)),
                   [&] { return make(run); });
}

// Of the one configuration the selector under key picks, each ok run's
// recomputed polynomial by seed (computed once per context); empty, with
// *missing set, when there is none. Throws ClaimsError (the row then says
// why) when a run cannot be recomputed.
std::map<std::uint64_t, const RecomputedPolynomial*> PolynomialsUnder(
    const YAML::Node& node, const char* key, const ClaimContext& context, std::string* missing) {
  const RunSelector s = ParseSelector(node[key]);
  std::map<std::uint64_t, const RecomputedPolynomial*> out;
  const GroupSummary* g = OnlyMatch(context, s);
  if (!g || g->ok_runs.empty()) {
    *missing = MissingRuns(context, s);
    return out;
  }
  for (const RunRecord* run : g->ok_runs)
    out[run->spec.seed] = &RecomputedOnce<RecomputedPolynomial>(
        context, "polynomial", *run, [](const RunRecord& r) { return RecomputePolynomial(r); });
  return out;
}

// Per seed present in both, value(a's polynomial, b's); their median with
// its 95 % interval.
MedianInterval PairedBySeed(
    const std::map<std::uint64_t, const RecomputedPolynomial*>& a,
    const std::map<std::uint64_t, const RecomputedPolynomial*>& b,
    const std::function<double(const RecomputedPolynomial&, const RecomputedPolynomial&)>& value) {
  std::vector<double> values;
  for (const auto& [seed, pa] : a)
    if (auto it = b.find(seed); it != b.end()) values.push_back(value(*pa, *it->second));
  return MedianWithInterval(values);
}

std::string OverSeeds(const MedianInterval& m) {
  return FormatWithInterval(m) + ", median of " + std::to_string(m.n) +
         (m.n == 1 ? " seed" : " seeds");
}

double WhiteRatio(const RecomputedPolynomial& a, const RecomputedPolynomial& b) {
  return WhiteSide(a) / WhiteSide(b);
}

// Of the highest non-empty coefficient, the larger of its x width and its
// distance to the truth over the search box's width; infinity when that
// coefficient is below n - q.
double PeakSpread(const RecomputedPolynomial& p) {
  int top = -1;
  for (int k = 0; k < static_cast<int>(p.coefficients.size()); ++k)
    if (!p.coefficients[k].IsEmpty()) top = k;
  if (top < p.white) return kInfinity;
  const Interval x = p.coefficients[top][0];
  const double distance =
      p.truth.empty() ? kNaN : std::max({0.0, x.lo() - p.truth[0], p.truth[0] - x.hi()});
  return std::max(x.Width(), distance) / p.prior[0].Width();
}

// quantity white_shrink: C*(3)'s white side at `to` over `from`; peak: the
// peak's spread (PeakSpread) of `runs`; white_ratio: the white side of
// `runs` over that of `of`. Per seed, paired by seed; the median over the
// seeds is judged.
Measurement MeasureBoxPolynomial(const YAML::Node& measure, const ClaimContext& context) {
  const std::string quantity = Quantity(measure, {"white_shrink", "peak", "white_ratio"});
  Measurement m;
  const bool shrink = quantity == "white_shrink";
  const auto a = PolynomialsUnder(measure, shrink ? "to" : "runs", context, &m.missing);
  if (!m.missing.empty()) return m;
  const auto b = quantity == "peak"
                    ? a
                    : PolynomialsUnder(measure, shrink ? "from" : "of", context, &m.missing);
  if (!m.missing.empty()) return m;
  const auto value_of = [&](const RecomputedPolynomial& p, const RecomputedPolynomial& q) {
    return quantity == "peak" ? PeakSpread(p) : WhiteRatio(p, q);
  };
  const MedianInterval value = PairedBySeed(a, b, value_of);
  if (value.n == 0) {
    m.missing = "no seed has runs of both configurations: rerun " + context.spec;
    return m;
  }
  m.value = value.median;
  // The figure draws the smallest seed: its own value beside the median.
  const auto& [seed, first] = *a.begin();
  const auto other = b.find(seed);
  m.text = OverSeeds(value) +
           (quantity == "peak" ? " (peak spread over the search width)"
                               : " (ratio of the widest sides of coefficient n - q)");
  if (other != b.end())
    m.text += "; seed " + std::to_string(seed) + ", the figure's: " +
              FormatNumber(value_of(*first, *other->second));
  return m;
}

// An accumulator's source: 0, 1, ... or `sum` (every source); the counts'
// index in RecomputedAccumulator::counts.
int SourceIndex(const YAML::Node& measure, const RecomputedAccumulator& a) {
  if (!measure["source"]) throw ClaimsError("the measure needs 'source': a number or sum");
  const std::string source = measure["source"].as<std::string>();
  const int sources = static_cast<int>(a.counts.size()) - 1;
  if (source == "sum") return sources;
  const int s = std::stoi(source);
  if (s < 0 || s >= sources)
    throw ClaimsError("the run has no source " + source + " (it has " + std::to_string(sources) +
                      ")");
  return s;
}

int Sum(const std::vector<int>& v, int index, int sources) {
  int total = 0;
  for (int s = 0; s < sources; ++s)
    if (index == sources || index == s) total += v[s];
  return total;
}

// The cells of a hull as a box of the grid's coordinates (x, y).
Box CellsBox(const RecomputedAccumulator& a, const cv::Mat& counts, const CellHull& h) {
  const double cx = a.x.Width() / counts.cols, cy = a.y.Width() / counts.rows;
  return Box({Interval(a.x.lo() + h.col0 * cx, a.x.lo() + h.col1 * cx),
              Interval(a.y.lo() + h.row0 * cy, a.y.lo() + h.row1 * cy)});
}

// Whether the truth lies in the hull, widened by one cell.
bool TruthNear(const RecomputedAccumulator& a, const cv::Mat& counts, const CellHull& h) {
  if (a.truth.size() < 2) return false;
  const double cx = a.x.Width() / counts.cols, cy = a.y.Width() / counts.rows;
  const double col = std::floor((a.truth[0] - a.x.lo()) / cx);
  const double row = std::floor((a.truth[1] - a.y.lo()) / cy);
  return col >= h.col0 - 1 && col <= h.col1 && row >= h.row0 - 1 && row <= h.row1;
}

struct AccumulatorFigure {
  const RunRecord* run = nullptr;
  RecomputedAccumulator a;
  int index = 0;  // into a.counts
  AccumulatorMaximum maximum;
  int measurements = 0, outliers = 0;
};

AccumulatorFigure FigureOf(const YAML::Node& measure, const ClaimContext& context,
                           std::string* missing) {
  AccumulatorFigure f;
  const RunSelector s = ParseSelector(measure["runs"]);
  f.run = FigureRun(context, s);
  if (!f.run) {
    *missing = MissingRuns(context, s);
    return f;
  }
  f.a = RecomputedOnce<RecomputedAccumulator>(
      context, "accumulator", *f.run, [](const RunRecord& r) { return RecomputeAccumulator(r); });
  f.index = SourceIndex(measure, f.a);
  const int sources = static_cast<int>(f.a.counts.size()) - 1;
  f.maximum = FindMaximum(f.a.counts[f.index]);
  f.measurements = Sum(f.a.measurements, f.index, sources);
  f.outliers = Sum(f.a.outliers, f.index, sources);
  return f;
}

// quantity maxima: the number of separate regions of highest count;
// localizes: 1 when there is one, its count is the number of correct
// measurements and the truth lies within a cell of it, else 0.
Measurement MeasureAccumulator(const YAML::Node& measure, const ClaimContext& context) {
  const std::string quantity = Quantity(measure, {"maxima", "localizes"});
  Measurement m;
  const AccumulatorFigure f = FigureOf(measure, context, &m.missing);
  if (!m.missing.empty()) return m;
  const AccumulatorMaximum& max = f.maximum;
  const cv::Mat& counts = f.a.counts[f.index];
  const bool at_truth = max.regions == 1 && TruthNear(f.a, counts, max.hulls.front());
  const std::string counted = ", count " + std::to_string(max.count) + " of " +
                              std::to_string(f.measurements) + " (" +
                              std::to_string(f.measurements - f.outliers) + " correct)";
  if (quantity == "maxima") {
    m.value = max.regions;
    m.text = std::to_string(max.regions) + (max.regions == 1 ? " maximum" : " maxima") + counted;
  } else {
    m.value = at_truth && max.count == f.measurements - f.outliers ? 1 : 0;
    m.text = (max.regions == 1 ? std::string("1 maximum") : std::to_string(max.regions) + " maxima") +
             counted + (at_truth ? ", at the truth" : ", not at the truth");
  }
  return m;
}

// Why an accumulator's maxima are what they are: at each region of highest
// count, which measurements pass there (their contractors leave the
// region's box non-empty) and how many of those are outliers.
std::string RangeMeetings(const Claim& claim, const Measurement&, const ClaimContext& context) {
  std::string missing;
  const AccumulatorFigure f = FigureOf(claim.measure, context, &missing);
  if (!missing.empty()) return "";
  const Step step = FirstMeasurementSetStep(*f.run);
  const MeasurementSetView& view = *step.views.measurement_set;
  const int sources = static_cast<int>(f.a.counts.size()) - 1;
  const cv::Mat& counts = f.a.counts[f.index];
  std::map<std::string, int> kinds;  // "2 correct" -> regions
  int at_truth = 0;
  for (const CellHull& h : f.maximum.hulls) {
    Box box = view.prior;
    const Box cells = CellsBox(f.a, counts, h);
    box[0] = Intersect(box[0], cells[0]), box[1] = Intersect(box[1], cells[1]);
    int correct = 0, wrong = 0;
    for (std::size_t i = 0; i < view.measurements.size(); ++i) {
      const int source = view.sources.empty() ? 0 : view.sources[i];
      if (f.index != sources && source != f.index) continue;
      Box b = box;
      ContractContext contract;
      view.measurements[i]->Contract(b, contract);
      if (b.IsEmpty()) continue;
      (i < view.outliers.size() && view.outliers[i] ? wrong : correct) += 1;
    }
    ++kinds[std::to_string(correct) + " correct and " + std::to_string(wrong) + " outlying"];
    at_truth += TruthNear(f.a, counts, h);
  }
  std::string out = "measured: the " + std::to_string(f.maximum.regions) +
                    " regions of count " + std::to_string(f.maximum.count) +
                    " are where that many of the " + std::to_string(f.measurements) +
                    " ranges (" + std::to_string(f.outliers) + " outlying) meet:";
  for (const auto& [kind, n] : kinds) out += " " + std::to_string(n) + " where " + kind + " meet;";
  return out + " " + std::to_string(at_truth) +
         " at the truth. Two circles cross at two points, so each pair of ranges makes two "
         "candidates; the thesis' beacons and ranges, which its text does not give, made " +
         claim.published_text + ".";
}

// Why the white box did not shrink further: C*(1) at p = 30 (the q-relaxed
// fixpoint, which encloses the solution set) bounds how far it can go.
std::string WhiteFloor(const Claim& claim, const Measurement&, const ClaimContext& context) {
  std::string missing;
  const auto floor = PolynomialsUnder(claim.if_differs, "runs", context, &missing);
  if (!missing.empty()) return "";
  const auto from = PolynomialsUnder(claim.measure, "from", context, &missing);
  const auto to = PolynomialsUnder(claim.measure, "to", context, &missing);
  if (!missing.empty()) return "";
  const MedianInterval room = PairedBySeed(from, floor, WhiteRatio);
  const MedianInterval reached = PairedBySeed(to, floor, WhiteRatio);
  if (room.n == 0 || reached.n == 0) return "";
  return "measured: it shrinks, but from p = 1 it had only " + OverSeeds(room) +
         " × to go: C*(1)'s coefficient n - q at p = 30 (the q-relaxed fixpoint, which encloses "
         "the solution set) bounds it, and p = 30 reaches " + OverSeeds(reached) + " × that";
}

// The guarantee pooled over every configuration the selectors pick: of the
// steps whose assumption held, the share whose set holds the truth.
Measurement MeasureGuarantee(const YAML::Node& measure, const ClaimContext& context) {
  const std::vector<RunSelector> selectors = SelectorsUnder(measure, "runs");
  if (selectors.empty()) throw ClaimsError("the measure needs 'runs'");
  int judged = 0, held = 0, contained = 0, configurations = 0;
  for (const RunSelector& s : selectors)
    for (const GroupSummary* g : Matching(context, s)) {
      const GuaranteeSummary summary = SummariseGuarantee(*g);
      ++configurations;
      judged += summary.judged, held += summary.held, contained += summary.held_contained;
    }
  Measurement m;
  if (configurations == 0) {
    m.missing = MissingRuns(context, selectors.front());
  } else if (held == 0) {
    m.missing = judged == 0 ? "the runs record no assumption_held (their truth is unknown, or "
                              "they predate it): rerun " + context.spec
                            : "the assumption held on none of the " + std::to_string(judged) +
                                  " steps";
  } else {
    m.value = static_cast<double>(contained) / held;
    m.text = FormatNumber(m.value) + " over the " + std::to_string(held) + " of " +
             std::to_string(judged) + " steps whose assumption held (" +
             std::to_string(configurations) + " configurations, every seed)";
  }
  return m;
}

// The configuration the claim's measure judges (its `runs`).
const GroupSummary* Judged(const Claim& claim, const ClaimContext& context) {
  return OnlyMatch(context, ExplainedSelector(claim, "runs"));
}

// Where a marina configuration lost the truth: the share of steps that hold
// it, the episodes of loss, the restarts, and the misses' reasons.
std::string MarinaLoss(const Claim& claim, const Measurement&, const ClaimContext& context) {
  const GroupSummary* g = Judged(claim, context);
  if (!g) return "";
  const StepStats stats = StatsOf(*g);
  const GuaranteeSummary s = SummariseGuarantee(*g);
  double restarts = 0;
  int with_restarts = 0;
  for (const RunRecord* run : g->ok_runs)
    if (const std::optional<double> n = RunRestarts(*run)) restarts += *n, ++with_restarts;
  std::string out = "measured: the estimate held the truth on " +
                    FormatNumber(stats.consistency()) + " of " + std::to_string(stats.known) +
                    " steps (" + LabelOf(ExplainedSelector(claim, "runs"), g) + ")";
  if (with_restarts > 0)
    out += ", " + FormatNumber(restarts / with_restarts) + " restarts a run";
  if (!std::isnan(s.median_reacquire))
    out += ", a lost truth re-acquired after " + FormatNumber(s.median_reacquire) +
           " steps (median)";
  if (s.misses > 0)
    out += "; the misses: " + s.dominant + " on " + std::to_string(s.dominant_count) + " of " +
           std::to_string(s.misses);
  return out + ": the median error counts the steps spent lost.";
}

// Why the auto_q variant misses: its misses counted by their reason.
std::string MissReasons(const Claim& claim, const Measurement&, const ClaimContext& context) {
  const GroupSummary* g = Judged(claim, context);
  if (!g) return "";
  const GuaranteeSummary s = SummariseGuarantee(*g);
  if (s.misses == 0) return "";
  std::string out = "measured: of the " + std::to_string(s.misses) + " steps that missed the truth,";
  for (const auto& [category, n] : s.miss_categories)
    out += " " + std::to_string(n) + ": " + category + ";";
  return out + " auto_q takes the smallest q that leaves a set, which is below the true outliers "
               "whenever wrong returns happen to agree, so it carries no guarantee (the "
               "guaranteed configuration is judged in its own row).";
}

// The filter's coverage at each level, pooled over its runs' steps.
std::string CoverageLevels(const Claim& claim, const Measurement&, const ClaimContext& context) {
  const GroupSummary* g = Judged(claim, context);
  if (!g) return "";
  std::string out = "measured coverage of the credible regions:";
  for (const char* level : {"50", "90", "95"}) {
    const double c = PooledMetric(*g, std::string("property:coverage_") + level);
    if (std::isnan(c)) return "";
    out += std::string(" ") + level + " %: " + FormatNumber(c) + ";";
  }
  return out + " a region that over-covers at every level is wider than its level, one that "
               "under-covers lost the truth (docs/reproduction/thesis003.md, coverage).";
}

}  // namespace

void AddThesis003ClaimFunctions(ClaimFunctions* functions) {
  functions->measures["box_polynomial"] = MeasureBoxPolynomial;
  functions->measures["accumulator"] = MeasureAccumulator;
  functions->measures["guarantee"] = MeasureGuarantee;
  functions->explainers["white_floor"] = WhiteFloor;
  functions->explainers["range_meetings"] = RangeMeetings;
  functions->explainers["marina_loss"] = MarinaLoss;
  functions->explainers["miss_reasons"] = MissReasons;
  functions->explainers["coverage_levels"] = CoverageLevels;
}

}  // namespace icp
