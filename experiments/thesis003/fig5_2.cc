#include "experiments/thesis003/fig5_2.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "algorithms/polynomial/polynomial.h"
#include "experiments/thesis003/thesis003.h"
#include "plots/box_polynomial_figure.h"
#include "problems/line_intersection/line_intersection.h"
#include "report/report.h"

namespace icp {

namespace {

// Line cos(a) x + sin(a) y = c clipped to the rectangle x by y (Liang-Barsky
// over its direction); false when it misses the rectangle.
bool ClipLine(double a, double c, const Interval& x, const Interval& y,
              std::array<double, 4>* segment) {
  const double px = c * std::cos(a), py = c * std::sin(a);  // the foot of the normal
  const double dx = -std::sin(a), dy = std::cos(a);
  double t0 = -std::numeric_limits<double>::infinity(), t1 = -t0;
  const auto clip = [&](double p, double d, const Interval& r) {
    if (std::fabs(d) < 1e-12) return r.Contains(p);
    double lo = (r.lo() - p) / d, hi = (r.hi() - p) / d;
    if (lo > hi) std::swap(lo, hi);
    t0 = std::max(t0, lo), t1 = std::min(t1, hi);
    return t0 <= t1;
  };
  if (!clip(px, dx, x) || !clip(py, dy, y)) return false;
  *segment = {px + t0 * dx, py + t0 * dy, px + t1 * dx, py + t1 * dy};
  return true;
}

// The coefficient of degree k of a polynomial as drawn, for titles.
std::string WhiteSide(const std::vector<Box>& coefficients, int white) {
  if (white < 0 || white >= static_cast<int>(coefficients.size())) return "none";
  const Box& b = coefficients[white];
  return b.IsEmpty() ? "empty" : FormatNumber(WidestSide(b));
}

}  // namespace

const RunRecord* Fig52PolynomialRun(const std::vector<RunRecord>& runs,
                                    const std::string& approximation, int p) {
  const RunRecord* best = nullptr;
  for (const RunRecord& r : runs) {
    if (r.status != RunStatus::kOk || r.spec.algorithm != "polynomial" ||
        ExperimentOf(r) != kThesis003Fig52)
      continue;
    PolynomialParams params;
    try {
      params = ParseParams<PolynomialParams>("polynomial", r.spec.algorithm_params);
    } catch (const std::exception&) {
      continue;  // a run whose parameters no longer parse is not one of these
    }
    if (params.approximation != approximation || params.p != p) continue;
    if (!best || r.spec.seed < best->spec.seed) best = &r;
  }
  return best;
}

double WidestSide(const Box& box) {
  if (box.IsEmpty()) return std::numeric_limits<double>::infinity();
  double widest = 0;
  for (std::size_t i = 0; i < std::min<std::size_t>(box.size(), 2); ++i)
    widest = std::max(widest, box[i].Width());
  return widest;
}

RecomputedPolynomial RecomputePolynomial(const RunRecord& run, bool repeated) {
  const PolynomialParams params =
      ParseParams<PolynomialParams>("polynomial", run.spec.algorithm_params);
  const Step step = FirstMeasurementSetStep(run);
  const MeasurementSetView& view = *step.views.measurement_set;
  RecomputedPolynomial out;
  out.prior = view.prior;
  if (step.truth.size() >= 2) out.truth = {step.truth[0], step.truth[1]};
  ContractSummary summary;
  const std::vector<Box> by_q =
      PolynomialHullsByQ(params, view.prior, view.measurements, StopCondition(), &summary);
  out.coefficients.assign(by_q.rbegin(), by_q.rend());
  if (repeated && params.approximation == "c3")
    out.repeated = RepeatedSortTransform(view.prior, view.measurements, params.p, StopCondition());
  const int n = static_cast<int>(view.measurements.size());
  out.white = n - static_cast<int>(std::count(view.outliers.begin(), view.outliers.end(), true));
  if (run.spec.problem == "line-intersection" && view.prior.size() >= 2) {
    const LineIntersectionParams lp =
        ParseLineIntersection("line-intersection", run.spec.problem_params);
    for (const DrawnLine& line : DrawLineIntersection(lp, run.spec.seed).lines) {
      std::array<double, 4> segment;
      if (ClipLine(line.angle, line.offset, view.prior[0], view.prior[1], &segment))
        out.lines.push_back(segment);
    }
  }
  return out;
}

void Fig52Figure(const std::vector<RunRecord>& runs, const std::string& out_dir, PlotOutput* out) {
  const std::string name = "fig5_2_box_polynomials";
  struct Wanted {
    const char* approximation;
    int p;
  };
  const Wanted kWanted[3] = {{"c3", 1}, {"c3", 10}, {"c1", 30}};
  const RunRecord* chosen[3];
  std::string missing;
  for (int i = 0; i < 3; ++i) {
    chosen[i] = Fig52PolynomialRun(runs, kWanted[i].approximation, kWanted[i].p);
    if (!chosen[i])
      missing += std::string(missing.empty() ? "" : ", ") + "approximation=" +
                 kWanted[i].approximation + " p=" + std::to_string(kWanted[i].p);
  }
  if (!missing.empty()) {
    out->messages.push_back(name + ": skipped: no ok polynomial run of experiment " +
                            kThesis003Fig52 + " with " + missing);
    return;
  }
  RecomputedPolynomial a, b, d;
  try {
    a = RecomputePolynomial(*chosen[0]);
    b = RecomputePolynomial(*chosen[1], true);
    d = RecomputePolynomial(*chosen[2]);
  } catch (const std::exception& e) {
    out->messages.push_back(name + ": skipped: " + e.what());
    return;
  }
  const int p = 10;
  const auto white = [](const std::vector<Box>& c, int k) {
    return "\nwhite: degree " + std::to_string(k) + ", widest side " + WhiteSide(c, k);
  };
  std::vector<BoxPolynomialPanel> panels = {
      {"(a) C*(3), p = 1" + white(a.coefficients, a.white), a.coefficients, a.white},
      {"(b) C^(p*), p = 10" + white(b.repeated, b.white * p), b.repeated, b.white * p},
      {"(c) Ĉ* (every 10th), p = 10" + white(b.coefficients, b.white), b.coefficients, b.white},
      {"(d) C*(1), p = 30" + white(d.coefficients, d.white), d.coefficients, d.white},
  };
  const RunRecord& r = *chosen[0];
  const std::string title =
      "Fig. 5.2: box polynomials of " + std::to_string(a.coefficients.size() - 1) +
      " lines, n - q = " + std::to_string(a.white) + " (" + r.spec.problem +
      (r.spec.problem_params.empty() ? "" : " " + CompactParams(r.spec.problem_params)) +
      ", seed " + std::to_string(r.spec.seed) + ")";
  PlotBoxPolynomialFigure({name, title, ""}, panels, a.prior[0], a.prior[1], a.lines, a.truth,
                          out_dir, out);
}

}  // namespace icp
