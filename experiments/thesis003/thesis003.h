// Thesis 003 (relaxed CSPs: q-relaxed intersection, contractor polynomials,
// accumulators): which runs make its figures and its table. Runs are chosen
// by the name of the spec experiment that planned them (ExperimentOf: spec
// file "<spec>#<name>", any spec file), never by their parameters;
// specs/relaxed.yaml is the reference:
//
//   fig5_2           Fig. 5.2 (§5.1.4): the box polynomials of the
//                    `polynomial` solver, a p sweep (figure
//                    fig5_2_box_polynomials): experiments/thesis003/fig5_2.h.
//   lines-accumulator
//                    the accumulator of the same lines over the x-y plane
//                    (figure fig_lines_accumulator; not a figure of the
//                    thesis, which draws box polynomials there).
//   fig5_5           Figs. 5.5-5.7 (§5.2.3): the accumulators of two robots
//                    ranging beacons, source 0 alone, source 1 alone and
//                    their sum (fig5_5_robot_a, fig5_6_robot_b, fig5_7_sum).
//   city-roads       Fig. 4.17 (§4.8.7): experiments/thesis003/city_roads.h.
//   marina,          chapter 6, set membership vs particle filter in a
//   marina-drive     marina: experiments/thesis003/marina.h.
//   relaxed-lines,   the table "Thesis 003: relaxed solvers": every
//   relaxed-beacons  configuration (algorithm, params, problem, params) with
//                    a run of either experiment, pooled over its ok runs
//                    (every seed), as paper 000's Table 1 pools.
//
// A figure draws the accumulator of one run: the ok accumulator run of its
// experiment with the smallest seed. The store keeps metrics, not images,
// so the counts are recomputed from the run's definition (problem, params,
// seed; the accumulator's `cells`) on the problem's first step, on the grid
// the accumulator itself uses there (AccumulatorGrid over the view's prior).
#ifndef ICPBENCH_EXPERIMENTS_THESIS003_THESIS003_H_
#define ICPBENCH_EXPERIMENTS_THESIS003_THESIS003_H_

#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/box.h"
#include "harness/run_record.h"
#include "plots/figures.h"
#include "problems/problem.h"
#include "report/report.h"

namespace icp {

inline constexpr char kThesis003LinesAccumulator[] = "lines-accumulator";
inline constexpr char kThesis003Fig55[] = "fig5_5";
inline constexpr char kThesis003RelaxedLines[] = "relaxed-lines";
inline constexpr char kThesis003RelaxedBeacons[] = "relaxed-beacons";

// The run a figure of experiment draws: among the ok runs of algorithm
// accumulator planned by that experiment, the one with the smallest seed
// (the first in store order on a tie); nullptr when there is none.
const RunRecord* Thesis003FigureRun(const std::vector<RunRecord>& runs,
                                    const std::string& experiment);

// What the thesis shows in an accumulator figure: its maxima (the number of
// separate regions of highest count; 0: "several", at least two) and, for a
// single maximum, its count out of the measurements, at the truth.
struct AccumulatorPublished {
  const char* figure;   // the plot's name, e.g. "fig5_5_robot_a"
  const char* caption;  // the thesis' figure
  int source;           // the accumulator drawn: a source, or -1 for the sum
  int maxima;
  int count;            // of the single maximum; 0 when several
  int measurements;
};
// Figs. 5.5-5.7 (§5.2.3: robot A's 3 ranges with 1 outlier give 3 maxima,
// robot B's 4 with 2 outliers several, their sum a single maximum where 4 of
// the 7 agree).
const std::vector<AccumulatorPublished>& Thesis003PublishedAccumulators();

// The first step of a run's problem (made from its definition), which must
// offer the measurement-set view; throws std::invalid_argument (or
// ParamError) otherwise. What the figures recompute from.
Step FirstMeasurementSetStep(const RunRecord& run);

// An accumulator recomputed from a run's definition (see the top).
struct RecomputedAccumulator {
  // Each source's counts (sources numbered from 0; one when the view names
  // none), then their sum: SourceAccumulators' output. Row r is the r-th
  // cell of y from below, column c the c-th of x.
  std::vector<cv::Mat> counts;
  Interval x, y;                  // the grid's extent
  std::vector<double> truth;      // (x, y); empty when unknown
  std::vector<int> measurements;  // per source
  std::vector<int> outliers;      // per source: true outliers
  // Beacons per source, for beacon-ranges two-robots (read from the
  // shipped scene); empty otherwise.
  std::vector<std::vector<std::pair<double, double>>> beacons;
};
// Throws std::invalid_argument (or ParamError) when the run's problem or
// accumulator parameters no longer parse, or its first step has no
// measurement-set view.
RecomputedAccumulator RecomputeAccumulator(const RunRecord& run);

// Cells [row0, row1) x [col0, col1).
struct CellHull {
  int row0 = 0, row1 = 0, col0 = 0, col1 = 0;
};
// Where counts reach their maximum: that maximum, the number of separate
// (8-connected) regions of cells holding it, the hull of all those cells
// and each region's own hull.
struct AccumulatorMaximum {
  int count = 0;
  int regions = 0;
  int row0 = 0, row1 = 0, col0 = 0, col1 = 0;
  std::vector<CellHull> hulls;  // one per region, in label order
};
AccumulatorMaximum FindMaximum(const cv::Mat& counts);

// The report's table "Thesis 003: relaxed solvers" (see the top).
std::vector<TextTable> Thesis003Tables(const std::vector<RunRecord>& runs);

// The figures fig5_2_box_polynomials (fig5_2.h), fig_lines_accumulator,
// fig5_5_robot_a, fig5_6_robot_b and fig5_7_sum, chapter 6's, then
// fig4_17_city_roads (city_roads.h); each
// skipped with a message when its experiment has no ok run to draw.
void Thesis003Figures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                      PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_THESIS003_THESIS003_H_
