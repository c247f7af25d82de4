// The measures and explainers claims files name (paper/claims.h), and the
// helpers they share. The generic measures (claim_measures.cc) read a run
// metric over the runs a selector picks:
//
//   metric     one configuration's metric, the median over its ok runs
//              (seeds) with its 95 % interval (MedianWithInterval)
//   ratio      runs over of, paired by seed, the median of the ratios
//   fall       1 - to/from, paired by seed, the median (a fraction)
//   spread     the largest over the smallest median of a list
//   fastest    the label of the lowest median of a list (same_text rules)
//   lowest     the lowest of the metric pooled over each configuration's
//              steps, over every configuration the list picks (guarantees:
//              a consistency of 1 means every step)
//   linear_r2  over a problem parameter (`over`), the R² of the line through
//              (value, median metric), the lowest over the list
//
// Metrics: time_ms, time_us (mean solve time per step), run_time_s (solve
// time summed over a run), area (mean x-y area, m²), consistency (share of
// steps holding the truth), centre_rmse, median_centre_error (m), or
// property:NAME (a run property). A paper's own measures and explainers are
// in paper/<paper>_claims.cc.
#ifndef ICPBENCH_PAPER_CLAIM_MEASURES_H_
#define ICPBENCH_PAPER_CLAIM_MEASURES_H_

#include <string>
#include <vector>

#include "paper/claims.h"

namespace icp {

// The configurations (groups) with an ok run the selector picks.
std::vector<const GroupSummary*> Matching(const ClaimContext& context, const RunSelector& s);
// The one configuration the selector picks; nullptr when none; throws
// ClaimsError when it picks several.
const GroupSummary* OnlyMatch(const ClaimContext& context, const RunSelector& s);

// A metric of one run (see the top); NaN when the run lacks it.
double RunMetric(const RunRecord& run, const std::string& metric);
// The metric pooled over a group's steps (the group's metrics; properties:
// the mean over its runs weighted by steps).
double PooledMetric(const GroupSummary& group, const std::string& metric);
// The unit a metric's cells show ("ms", "m²", ""), with a leading space.
std::string UnitOf(const std::string& metric);

// How a selector's configuration shows in measured texts: its label, else
// the algorithm's display label with its parameters.
std::string LabelOf(const RunSelector& s, const GroupSummary* group);

// The selector under key of an explainer's claim: its if_differs names it,
// else its measure; throws ClaimsError when neither does.
RunSelector ExplainedSelector(const Claim& claim, const char* key);

// The missing-data text of a selector: "no ok run matches {...}: icpbench
// run SPEC produces them".
std::string MissingRuns(const ClaimContext& context, const RunSelector& s);

// Why an explainer found nothing, when the store can tell: the runs its
// claim picks were all stored with `record: runs` (no steps to read); ""
// otherwise.
std::string UnexplainedBecause(const Claim& claim, const ClaimContext& context);

// Each paper's measures and explainers (paper/<paper>_claims.cc).
void AddPaper000ClaimFunctions(ClaimFunctions* functions);
void AddPaper002ClaimFunctions(ClaimFunctions* functions);
void AddThesis003ClaimFunctions(ClaimFunctions* functions);
void AddPaper004ClaimFunctions(ClaimFunctions* functions);

}  // namespace icp

#endif  // ICPBENCH_PAPER_CLAIM_MEASURES_H_
