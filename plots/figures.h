// Figures from the results store (`icpbench plot DIR`), drawn by gnuplot
// through gnuplot-iostream, each written as NAME.png (pngcairo) and NAME.pdf
// (pdfcairo):
//
//   fig2_window     paper 000 Fig. 2: mean x-y area and mean time per CSP
//                   against the window w, one line per car-track
//                   configuration run at two or more w (WindowSweep); only
//                   the paper-scenario ones (IsPaperScenario) when there are
//                   any, so variants such as GPS outages stay in the table
//   fig3_corridors  paper 000 Fig. 3: interval error corridors
//                   [lo - truth, hi - truth] of x and y over the steps, one
//                   row of panels per algorithm
//   fig4_area       paper 000 Fig. 4: x-y area over the steps, one line per
//                   algorithm, log scale
//   fig_timing      box plot of the solve times per CSP (us, log scale), one
//                   box per algorithm
//
// Figs 3 and 4 show, for each of hc4, bc3, bc4, 3b-bc4 (and any other
// algorithm so run), the ok run with the smallest seed of the group
// FindPaperGroup picks (car-track, w = 20, default algorithm params). The
// timing box plot pools the steps of those groups' ok runs; without
// car-track runs it uses the problem configuration with the most ok runs at
// default algorithm params. A figure without data is skipped with a message,
// never an error.
#ifndef ICPBENCH_PLOTS_FIGURES_H_
#define ICPBENCH_PLOTS_FIGURES_H_

#include <string>
#include <vector>

#include "harness/run_record.h"

namespace icp {

// What plotting wrote and what it skipped.
struct PlotOutput {
  std::vector<std::string> files;     // paths written, PNG then PDF per figure
  std::vector<std::string> messages;  // one per skipped figure, e.g.
                                      // "fig2_window: skipped: no car-track ..."
};

// Draws every figure from runs (with their steps) into out_dir, creating it.
// Throws std::runtime_error only when out_dir cannot be created; a missing
// gnuplot or a gnuplot error skips figures with a message.
PlotOutput PlotRuns(const std::vector<RunRecord>& runs, const std::string& out_dir);

// PlotRuns over the store in dir (LoadRunsFromDirectory: throws when dir
// holds no store); returns the files written. Messages, when asked for, get
// the skipped figures.
std::vector<std::string> PlotDirectory(const std::string& dir, const std::string& out_dir,
                                       std::vector<std::string>* messages = nullptr);

// The figures one by one, as PlotRuns draws them; each appends to out.
void PlotWindowFigure(const std::vector<RunRecord>& runs, const std::string& out_dir,
                      PlotOutput* out);
void PlotCorridorFigure(const std::vector<RunRecord>& runs, const std::string& out_dir,
                        PlotOutput* out);
void PlotAreaFigure(const std::vector<RunRecord>& runs, const std::string& out_dir,
                    PlotOutput* out);
void PlotTimingFigure(const std::vector<RunRecord>& runs, const std::string& out_dir,
                      PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_PLOTS_FIGURES_H_
