// Paper 004 (interval localization over an ICSP graph): real-time
// localization against post-localization (§4.2) and their consistency (eq.
// 31), on the car track. Runs are the car-track runs of spec experiment
// `window` (paper 000's Fig. 2 sweep in specs/default.yaml), chosen as Fig. 2
// chooses them (Paper000Fig2Points); their window estimators report each
// window's oldest state, whose last report is the state's post-localized box
// (WindowEstimator, PostLocalizedStates). They give:
//
//   the table "Paper 004: real-time vs post-localization": per
//   configuration and w, pooled over its ok runs, the share of real-time
//   boxes and of post-localized states that hold the truth, their mean x-y
//   areas and the mean widths of their x and y interval-error corridors,
//   beside the paper's (consistent all along; PL narrower; 11.7 cm and
//   13.4 cm real-time corridors on its own visual-localization data);
//
//   the figure fig13_post_localization (Figs. 12-13's equivalent): the x
//   and y interval-error corridors of one run's real-time boxes above those
//   of its post-localized states, on shared scales: HC4 at default
//   parameters (carry=first) at w = 50 (the paper's window), else at the w
//   nearest to 50, smallest seed.
#ifndef ICPBENCH_EXPERIMENTS_PAPER004_PAPER004_H_
#define ICPBENCH_EXPERIMENTS_PAPER004_PAPER004_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "plots/figures.h"
#include "report/report.h"

namespace icp {

// The paper's published values (for paper/'s comparison): its localization
// is consistent at every step (eq. 31, §5.2, Fig. 12), and so is its
// post-localization over a window of Xi = 50 steps, whose corridors are
// narrower (§4.2, Fig. 13).
struct Paper004Published {
  double consistency_rate = 1;        // share of steps whose box holds the truth
  int post_localization_window = 50;  // Xi, steps
};
inline constexpr Paper004Published kPaper004;

// One configuration and w of the table (see the top): its real-time boxes'
// and its post-localized states' metrics, pooled over its ok runs.
struct PostLocalizationPoint {
  SweepPoint point;
  RunMetrics real_time;
  RunMetrics post;
};
std::vector<PostLocalizationPoint> Paper004PostLocalization(const std::vector<RunRecord>& runs);
// The same pooling over any points: each point's real-time steps and
// post-localized states (PostLocalizedStates) over its ok runs.
std::vector<PostLocalizationPoint> PoolPostLocalization(const std::vector<SweepPoint>& points);

// The mean width of var's interval-error corridor (mean hi - lo); NaN when
// the metrics have no such corridor.
double CorridorWidth(const RunMetrics& m, const std::string& var);

// The run fig13_post_localization draws (see the top), or nullptr.
const RunRecord* Paper004FigureRun(const std::vector<RunRecord>& runs);

std::vector<TextTable> Paper004Tables(const std::vector<RunRecord>& runs);
void Paper004Figures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                     PlotOutput* out);
// A run's interval-error corridors in real time (top) and post-localized
// (its PostLocalizedStates, bottom): Figs. 12-13.
void PlotPostLocalizationFigure(const FigureText& text, const RunRecord& run,
                                const std::string& out_dir, PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_PAPER004_PAPER004_H_
