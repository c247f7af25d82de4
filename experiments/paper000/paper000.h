// Paper 000 (HC3, HC4, BC3, BC4 and 3B-BC4 on the car-track CSP, Table 1 and
// Figs 2-4): its published values and which runs make its tables and
// figures. Runs are chosen by the name of the spec experiment that planned
// them (ExperimentOf: spec_file "<spec>#<name>", any spec file), never by
// their parameters:
//
//   table1  Table 1 (published vs measured ms per CSP), Fig. 3 (corridors),
//           Fig. 4 (area over the steps): every configuration (algorithm,
//           params, problem, params) with a run of experiment table1 and
//           ok runs, pooled over all its runs (every seed).
//   window  Fig. 2 (area and time against w): every car-track configuration
//           (w aside) with an ok run of experiment window, at every w it was
//           run at. A run two experiments plan is stored under the first
//           (specs/default.yaml's window runs half a lap, so its w = 20
//           runs are its own).
//
// The window-sweep table lists every car-track configuration run at two or
// more w, whatever the experiment (so the GPS-outage sweep is there too).
// A spec of one's own gets the paper's tables and figures by naming its
// experiments table1 and window (specs/default.yaml is the reference).
#ifndef ICPBENCH_EXPERIMENTS_PAPER000_PAPER000_H_
#define ICPBENCH_EXPERIMENTS_PAPER000_PAPER000_H_

#include <string>
#include <vector>

#include "report/report.h"
#include "harness/run_record.h"
#include "plots/figures.h"

namespace icp {

inline constexpr char kPaper000Table1[] = "table1";
inline constexpr char kPaper000Window[] = "window";

// The algorithms of paper 000 Table 1 with their published mean time per CSP
// (one recorded lap, 2000 CSPs, w = 20).
struct PublishedTime {
  const char* algorithm;  // registry key; shown by its display label
  double ms;
};
const std::vector<PublishedTime>& Paper000PublishedTimes();

// Paper 000 §5 on Fig. 2 (one recorded lap, w from 1 to 200): the mean
// localization area falls by 15 % from w = 1 to w = 20 (760 to 650 m²),
// widening the window further gains about 4 % more, and the computing time
// grows linearly with w.
struct Paper000Fig2Published {
  double area_w1_m2 = 760;
  double area_w20_m2 = 650;
  double further_fall = 0.04;  // from w = 20 to w = w_max
  double w_max = 200;
};
inline constexpr Paper000Fig2Published kPaper000Fig2;

// The groups of Table 1 and Figs 3-4 (see the top), in SummariseGroups
// order.
std::vector<const GroupSummary*> Paper000Table1Groups(const std::vector<GroupSummary>& groups);

// The runs of Figs 3 and 4: for each group of Table 1 in algorithm order,
// its ok run with steps and the smallest seed.
std::vector<const RunRecord*> Paper000LapRuns(const std::vector<GroupSummary>& groups);

// Every car-track configuration run at two or more w (ParamSweep over "w").
std::vector<SweepPoint> Paper000WindowSweep(const std::vector<RunRecord>& runs);
// The points of Fig. 2: those of the configurations with a run of
// experiment window.
std::vector<SweepPoint> Paper000Fig2Points(const std::vector<SweepPoint>& sweep);

// The report's tables: Table 1 published vs measured, then the window sweep
// (Fig. 2 as text): medians over the runs (seeds) with their 95 % intervals
// (MedianWithInterval), ratios to HC4 paired by seed.
std::vector<TextTable> Paper000Tables(const std::vector<RunRecord>& runs);
// The report's: Paper000Tables, then the tables of the suite's own
// experiments on the car track (own_experiments.h).
std::vector<TextTable> Paper000ReportTables(const std::vector<RunRecord>& runs);

// The figures fig2_window, fig3_corridors and fig4_area.
void Paper000Figures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                     PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_PAPER000_PAPER000_H_
