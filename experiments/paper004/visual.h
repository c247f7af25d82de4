// Paper 004's own system in the report and the figures (issue 29), from the
// visual-landmarks runs of specs/default.yaml (teach) and specs/repeat.yaml
// (repeat):
//
//   Table 2: the MDW of LIC and of DIGO at Xi = 10 on the paper's straight
//   route (medians over seeds), η = (LIC - DIGO) / LIC paired by seed, and
//   the paper's values beside them;
//   Fig. 9 as a table: DIGO's MPV, MDW and time per step against Xi;
//   the repeat phase: each configuration's real-time and post-localized
//   consistency and corridor widths (Figs. 12-13);
//
//   figures fig8_landmark_boxes (the landmarks' x-y boxes shrinking, DIGO at
//   Xi = 10, smallest seed), fig9_window (MPV and time per step against Xi)
//   and fig12_13_repeat (real-time and post-localized corridors of DIGO at
//   Xi = 50 in repeat, smallest seed).
//
// A teach run is one of visual-landmarks with phase teach on the straight
// route at the problem's defaults but for w; a repeat run, one with phase
// repeat.
#ifndef ICPBENCH_EXPERIMENTS_PAPER004_VISUAL_H_
#define ICPBENCH_EXPERIMENTS_PAPER004_VISUAL_H_

#include <string>
#include <vector>

#include "experiments/paper004/paper004.h"
#include "harness/run_record.h"
#include "plots/figures.h"
#include "report/report.h"

namespace icp {

// Paper 004 Table 2 (§5.1): MDW per axis, m, and η, per cent.
struct Paper004Table2 {
  double lic[3] = {0.117, 0.068, 0.024};
  double digo[3] = {0.103, 0.061, 0.022};
  double eta_percent[3] = {12, 10.3, 8.3};
  int window = 10;  // Xi of its DIGO
};
inline constexpr Paper004Table2 kPaper004Table2;

bool IsVisualTeachRun(const RunRecord& run);
bool IsVisualRepeatRun(const RunRecord& run);

// The repeat configurations (DIGO's over two or more w) with their
// real-time and post-localized metrics pooled over their ok runs.
std::vector<PostLocalizationPoint> Paper004RepeatPostLocalization(const std::vector<RunRecord>& runs);

std::vector<TextTable> Paper004VisualTables(const std::vector<RunRecord>& runs);
void Paper004VisualFigures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                           PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_PAPER004_VISUAL_H_
