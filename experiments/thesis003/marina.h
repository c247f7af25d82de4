// Thesis 003 chapter 6: set-membership localization in a marina against a
// particle filter (§6.7). Runs are those of spec experiments `marina` and
// `marina-<anything>` (specs/marina.yaml: `marina`, the full drive, and
// `marina-outliers`; the default suite: `marina-short`); they give:
//
//   the table "Thesis 003 ch. 6: marina, set membership vs particle filter":
//   per configuration (algorithm, problem params: start, outlier rate, ...)
//   pooled over its ok runs (every seed): the share of steps whose estimate
//   holds the truth, the centre error (RMSE and median), the restarts per
//   run (the relaxed solvers' static recovery, run property `resets`; the
//   filter's reinitialisations, `reinitialisations`), and the time per step and
//   per run, beside the thesis' 1 h 10 min (C/C++) and 31 min (Matlab, 600
//   particles) for its 600 m run, then the guarantee's columns
//   (guarantee_columns.h);
//
//   the figures fig6_8_marina_tracks (the map, the true trajectory, the
//   set-membership boxes and centres and the particle cloud's mean: Figs.
//   6.8 and 6.9 in one) and fig6_errors (centre error over time, both
//   methods). They draw one seed: the smallest seed of an ok run of
//   experiment `marina` (else `marina-short`, else any marina-*), with
//   start=known when there is one, and for each algorithm the ok run of
//   that experiment with the same problem params and seed whose
//   configuration has the lowest centre RMSE (each method at its best).
#ifndef ICPBENCH_EXPERIMENTS_THESIS003_MARINA_H_
#define ICPBENCH_EXPERIMENTS_THESIS003_MARINA_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "plots/figures.h"
#include "report/report.h"

namespace icp {

inline constexpr char kThesis003Marina[] = "marina";
inline constexpr char kThesis003MarinaShort[] = "marina-short";

// Whether a spec experiment's runs are chapter 6's: `marina` or `marina-*`.
bool IsMarinaExperiment(const std::string& experiment);

// The thesis' own run times for its 600 m drive on the real data set
// (§6.7): set membership in C/C++ on one core of a 2 GHz Centrino Duo
// T2500, 1 h 10 min; the particle filter (600 particles) in Matlab on a
// 2.2 GHz Core2, 31 min.
inline constexpr double kThesis003SetMembershipRunS = 4200;
inline constexpr double kThesis003ParticleFilterRunS = 1860;

// The runs the figures draw (see the top), in algorithm display order;
// empty when no marina experiment has an ok run. Runs stored with `record:
// runs` (no steps to draw) count only where no run with steps takes their
// place: as the reference when no ok run has steps, and as an algorithm's
// run when it has none with steps; the figures name them.
std::vector<const RunRecord*> MarinaFigureRuns(const std::vector<RunRecord>& runs);

TextTable MarinaTable(const std::vector<RunRecord>& runs);

// fig6_8_marina_tracks and fig6_errors; skipped with a message when there
// is no ok run to draw (naming `record: runs` when the runs were stored
// without steps).
void MarinaFigures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                   PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_THESIS003_MARINA_H_
