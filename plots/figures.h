// Figures from the results store (`icpbench plot DIR`), drawn by gnuplot
// through gnuplot-iostream, each written as NAME.png (pngcairo) and NAME.pdf
// (pdfcairo). Plots know no paper: each figure kind below draws the runs a
// caller selected (experiments/ selects a paper's), and PlotRuns adds the
// one generic figure:
//
//   fig_timing  box plot of the solve times per CSP (us, log scale), one box
//               per algorithm, over the problem configuration where the most
//               algorithms ran ok at default parameters (ties: the most
//               CSPs)
//   fig_profile_time, fig_profile_area
//               performance profiles of the time per CSP and the mean x-y
//               area over every problem instance of the runs
//               (report/performance_profile.h): rho against tau (log),
//               one step line per algorithm configuration
//
// A figure without data is skipped with a message, never an error.
#ifndef ICPBENCH_PLOTS_FIGURES_H_
#define ICPBENCH_PLOTS_FIGURES_H_

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "core/interval.h"
#include "harness/run_record.h"
#include "report/performance_profile.h"
#include "report/report.h"

namespace icp {

// What plotting wrote and what it skipped.
struct PlotOutput {
  std::vector<std::string> files;     // paths written, PNG then PDF per figure
  std::vector<std::string> messages;  // one per skipped figure, e.g.
                                      // "fig_timing: skipped: no ok run ..."
};

// Figures a caller draws before the generic one (into out_dir, appending to
// the output).
using FigureMaker =
    std::function<void(const std::vector<RunRecord>&, const std::string& out_dir, PlotOutput*)>;

// Draws the caller's figures, then the generic ones, from runs (with their
// steps) into out_dir, creating it. Throws std::runtime_error only when
// out_dir cannot be created; a missing gnuplot or a gnuplot error skips
// figures with a message.
PlotOutput PlotRuns(const std::vector<RunRecord>& runs, const std::string& out_dir,
                    const FigureMaker& more = nullptr);

// PlotRuns over the store in dir (LoadRunsFromDirectory: throws when dir
// holds no store); returns the files written. Messages, when asked for, get
// the skipped figures.
std::vector<std::string> PlotDirectory(const std::string& dir, const std::string& out_dir,
                                       std::vector<std::string>* messages = nullptr,
                                       const FigureMaker& more = nullptr);

// A figure's file name (without extension), its title, and why it is
// skipped when the selection holds nothing to draw.
struct FigureText {
  std::string name;
  std::string title;
  std::string skip_reason;
};

// A run's title in figures: "hc4 (seed 1)", "hc4 {ratio=0.1} (seed 2, steps=60)".
std::string RunLabel(const RunRecord& r);

// The skip message of a figure over steps that has nothing to draw: when
// some of runs (the ok runs it would draw) were stored with `record: runs`,
// that it needs their step rows, naming their experiments; else
// text.skip_reason. The figure kinds below skip the same way.
void SkipFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                PlotOutput* out);

// The figure kinds; each draws what it is given, in that order, and appends
// to out.
// Mean x-y area (of the newest state; and over the window's states when the
// points have it) and mean time per CSP against the swept value (x_label),
// one line per configuration (points as ParamSweep orders them).
void PlotSweepFigure(const FigureText& text, const std::string& x_label,
                     const std::vector<SweepPoint>& points, const std::string& out_dir,
                     PlotOutput* out);
// One quantity of a run against the swept value, a panel of the figure below.
struct SweepQuantity {
  std::string title;    // "MPV"
  std::string y_label;  // "volume (m^3)"
  std::function<double(const RunRecord&)> value;
};
// The same kind with other quantities, one panel each, in order; a panel
// none of whose points has a finite value is left out.
void PlotSweepFigure(const FigureText& text, const std::string& x_label,
                     const std::vector<SweepPoint>& points,
                     const std::vector<SweepQuantity>& quantities, const std::string& out_dir,
                     PlotOutput* out);
// Interval error corridors [lo - truth, hi - truth] of x and y over the
// steps, one row of panels per run, the y range shared by each column.
void PlotCorridorFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                        const std::string& out_dir, PlotOutput* out);
// The same with a title per run (labels[i] for runs[i]) instead of the run's
// algorithm, seed and problem parameters.
void PlotCorridorFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                        const std::vector<std::string>& labels, const std::string& out_dir,
                        PlotOutput* out);
// The GPS corridor of var ("x", "y") over a run's steps (paper 000 Fig. 3):
// rows {step, lo - truth, hi - truth} of the GPS box car-track records as
// the step properties gps_<var>_lo/hi; NaN where a step has none or the
// truth is unknown. PlotCorridorFigure draws it in grey behind each run's.
std::vector<std::vector<double>> GpsCorridorRows(const RunRecord& run, const std::string& var);
// x-y area over the steps, one line per run, log scale.
void PlotAreaFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                    const std::string& out_dir, PlotOutput* out);
// Distance from the estimate's centre to the truth over the steps, one line
// per run (the consistency of the estimates shown beside it: each line's
// title gives its share of steps holding the truth).
void PlotCentreErrorFigure(const FigureText& text, const std::vector<const RunRecord*>& runs,
                           const std::string& out_dir, PlotOutput* out);
// A run drawn on its map (equal scales): the map's set pixels as grey dots
// (wall_points, the pixels' centres), the true x-y trajectory of the first
// run with steps in black, and for each run the centre of its estimate at
// every step (the step property mean_<var> when the estimator reports one, a
// particle filter's weighted mean; else the middle of the hull), in its
// algorithm's colour; with boxes_every > 0, the x-y hull of every boxes_every-th step of
// the runs whose estimates are sets (not particles) as rectangles.
void PlotTrackFigure(const FigureText& text, const std::vector<std::pair<double, double>>& wall_points,
                     const std::vector<const RunRecord*>& runs, int boxes_every,
                     const std::string& out_dir, PlotOutput* out);
// Runs side by side on their map (equal scales, the rectangle x by y), one
// panel per (title, run): the map's set pixels as grey dots (map_points, the
// pixels' centres), the run's x-y box at every step in its algorithm's
// colour, and its true trajectory in black. Skipped when a run has no step
// rows.
void PlotBoxTrackFigure(const FigureText& text,
                        const std::vector<std::pair<double, double>>& map_points,
                        const std::vector<std::pair<std::string, const RunRecord*>>& panels,
                        const Interval& x, const Interval& y, const std::string& out_dir,
                        PlotOutput* out);
// Paper 004 Fig. 8: a top view of the landmarks' x-y position boxes at the
// given steps of a run (the step properties L<n>_x_lo ... L<n>_y_hi, clipped
// to the view, so that an unbounded cone reaches its edge), with their true
// positions (run properties L<n>_truth_x, _y) and the car's true track.
void PlotLandmarkBoxesFigure(const FigureText& text, const RunRecord& run,
                             const std::vector<int>& steps, const std::string& out_dir,
                             PlotOutput* out);
// Solve time per CSP, one box per group, pooling its ok runs' steps.
void PlotTimingFigure(const FigureText& text, const std::vector<const GroupSummary*>& groups,
                      const std::string& out_dir, PlotOutput* out);

// The performance profile of metric over the runs (RunsProfile), one step
// line per solver with an instance solved; skipped when none has.
void PlotProfileFigure(const FigureText& text, const std::vector<RunRecord>& runs,
                       ProfileMetric metric, const std::string& out_dir, PlotOutput* out);

// Points marked on an accumulator figure: big crosses (the truth) or small
// ones (beacons), one legend entry per set.
struct MarkerSet {
  std::string title;  // legend entry; "" for none
  std::vector<std::pair<double, double>> points;  // (x, y)
  bool big = false;
};
// An accumulator as an image: counts (CV_32S, row r the r-th cell of y from
// y.lo() up, column c the c-th cell of x) over the rectangle x by y, cells
// of equal size, with a colour bar "count" from 0 to the maximum and the
// markers on top (the truth's big cross open at its centre, so that it
// does not hide the maximum); equal scales on both axes (unless one side is
// more than 20 times the other); a '\n' in the title breaks it. A matrix of
// more than kAccumulatorPlotCells cells a side is drawn at BlockMax
// resolution so the data stays small and the maximum stays visible.
// Degenerate ones draw too: a single row or column of cells (even one
// cell), and a side of zero width, drawn as wide as the other side (or 1)
// about its point. Skipped when counts is empty or a side is unbounded.
void PlotAccumulatorFigure(const FigureText& text, const cv::Mat& counts, const Interval& x,
                           const Interval& y, const std::vector<MarkerSet>& markers,
                           const std::string& out_dir, PlotOutput* out);
inline constexpr int kAccumulatorPlotCells = 400;
// counts (CV_32S) in blocks of ceil(side / max_side) cells a side (the last
// block of a row or column may be smaller), each block its cells' maximum;
// counts itself when both sides are at most max_side.
cv::Mat BlockMax(const cv::Mat& counts, int max_side);

// The groups of the generic fig_timing (see the top) and their setting
// ("car-track, steps=40"); none without ok runs at default parameters.
std::vector<const GroupSummary*> TimingGroups(const std::vector<GroupSummary>& groups,
                                              std::string* setting);

}  // namespace icp

#endif  // ICPBENCH_PLOTS_FIGURES_H_
