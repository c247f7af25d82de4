// Thesis 003 chapter 6: set-membership localization in a marina against a
// particle filter (§6.7). Runs are those of spec experiments `marina` and
// `marina-<anything>` (specs/marina.yaml: `marina`, the full drive, and
// `marina-outliers`; the default suite: `marina-drive`); they give:
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
//   the figures of experiments/thesis003/marina_figures.h.
#ifndef ICPBENCH_EXPERIMENTS_THESIS003_MARINA_H_
#define ICPBENCH_EXPERIMENTS_THESIS003_MARINA_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "report/report.h"

namespace icp {

inline constexpr char kThesis003Marina[] = "marina";
inline constexpr char kThesis003MarinaDrive[] = "marina-drive";

// Whether a spec experiment's runs are chapter 6's: `marina` or `marina-*`.
bool IsMarinaExperiment(const std::string& experiment);

// The thesis' own run times for its 600 m drive on the real data set
// (§6.7): set membership in C/C++ on one core of a 2 GHz Centrino Duo
// T2500, 1 h 10 min; the particle filter (600 particles) in Matlab on a
// 2.2 GHz Core2, 31 min.
inline constexpr double kThesis003SetMembershipRunS = 4200;
inline constexpr double kThesis003ParticleFilterRunS = 1860;

TextTable MarinaTable(const std::vector<RunRecord>& runs);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_THESIS003_MARINA_H_
