// Tables from the results store (`icpbench report DIR [--format md|tex|csv]`):
//
//  1. Runs per configuration: one row per (algorithm, algorithm params,
//     problem, problem params), aggregated over seeds: run counts by status,
//     CSPs, mean area, consistency rate (paper 004 eq. 31), centre RMSE and
//     the solve time per CSP (median, p90, mean with a bootstrap 95 %
//     interval). Below it (md, tex) a short list of the failed, timed-out and
//     skipped runs with their reasons.
//  2. Paper 000 Table 1, published vs measured: the mean milliseconds per CSP
//     of HC4, BC3, BC4 and 3B-BC4 on car-track at w = 20 with default
//     algorithm parameters, beside the published ones, with the ratios to HC4.
//  3. Window sweep (paper 000 Fig. 2 as text): mean area and mean time per
//     CSP against w, for each car-track configuration run at several w.
//
// Aggregation: a group's metrics are ComputeMetrics over the pooled steps of
// its ok runs (every CSP weighs the same, whichever seed it came from). When
// some ok run of the group has no step records loaded, the runs' stored
// metrics are combined instead, weighted by their step counts (root of the
// weighted mean square for the RMSE); median, p90 and the interval of the
// mean then cannot be pooled and are shown only for a single run.
//
// Parameters show as "k=v,k2=v2" ("default" in md/tex, an empty field in CSV
// when none were given). Numbers have about 4 significant digits
// (FormatNumber), a missing one (NaN) shows as "—". Times are µs per CSP in
// table 1, ms in tables 2 and 3 (the paper's unit).
//
// CSV holds table 1 only, one header row then one row per group, RFC 4180
// quoting, 6 significant digits, NaN as an empty field; tables 2 and 3
// follow from its columns.
#ifndef ICPBENCH_HARNESS_REPORT_H_
#define ICPBENCH_HARNESS_REPORT_H_

#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "core/params.h"
#include "harness/run_record.h"

namespace icp {

// The report in format "md", "tex" or "csv"; throws std::invalid_argument for
// any other. No runs give the tables' headers with no rows.
std::string Report(const std::vector<RunRecord>& runs, const std::string& format);

// Report() over the runs (with their steps) of the results store in dir.
// Throws std::runtime_error when dir holds no store, StoreError when it
// cannot be read.
std::string ReportDirectory(const std::string& dir, const std::string& format);

// Loads every run of the store in dir with its steps; the shared entry of
// ReportDirectory and the plots. The store keeps effective parameters; the
// runs come back with only those that differ from the current defaults
// (NonDefaultParams), which is what the tables show. Throws as
// ReportDirectory.
std::vector<RunRecord> LoadRunsFromDirectory(const std::string& dir);

// The runs of one configuration, aggregated over seeds (see the top).
struct GroupSummary {
  std::string algorithm;
  ParamMap algorithm_params;
  std::string problem;
  ParamMap problem_params;
  int ok = 0;
  int failed = 0;
  int timeout = 0;
  int skipped = 0;
  // One line per distinct (status, reason) of the group's non-ok runs, e.g.
  // "timeout (seeds 1, 3): run exceeded 600 s".
  std::vector<std::string> problems;
  // Over the ok runs; metrics.steps is their total number of CSPs. NaN
  // fields where no ok run has the value.
  RunMetrics metrics;
  // Time statistics come from pooled steps (false: from stored run metrics).
  bool pooled = true;
  // The ok runs, in store order (pointers into the input vector).
  std::vector<const RunRecord*> ok_runs;
};

// The entries of params whose value differs from defaults (or that defaults
// lacks).
ParamMap NonDefaultParams(const ParamMap& defaults, const ParamMap& params);

// Groups runs by (algorithm, algorithm params, problem, problem params),
// ordered by problem, problem params, algorithm (display order, then name)
// and algorithm params; numeric parameter values compare as numbers.
std::vector<GroupSummary> SummariseGroups(const std::vector<RunRecord>& runs);

// Aggregates the given runs as one group (counts, problems, metrics).
GroupSummary Summarise(const std::vector<const RunRecord*>& runs);

// The window w of a car-track run: its "w" parameter, 20 when absent, NaN
// when not a number.
double CarTrackWindow(const RunSpec& spec);

// True for the paper 000 setting of Table 1 and Figs 3-4: problem car-track
// with w = 20 (or absent) and algorithm params empty (the defaults). Other
// problem parameters are not constrained.
bool IsPaperSetting(const RunSpec& spec);

// True when the problem params set nothing but w and steps: the paper's
// scenario (the simulated lap, possibly shortened), not a variant such as a
// GPS outage.
bool IsPaperScenario(const ParamMap& problem_params);

// The group that paper 000 Table 1 compares for algorithm: among the groups
// in the paper setting with ok runs, those in the paper scenario first, then
// the one with the most CSPs in ok runs; nullptr when none.
const GroupSummary* FindPaperGroup(const std::vector<GroupSummary>& groups,
                                   const std::string& algorithm);

// The algorithms of paper 000 Table 1 with their published mean time per CSP.
struct PublishedTime {
  const char* algorithm;  // registry key; shown by its display label
  double ms;
};
const std::vector<PublishedTime>& PaperTable1();

// One point of the window sweep: a car-track configuration (algorithm, its
// params, the problem params other than w) at one w, over its ok runs.
struct WindowPoint {
  std::string label;  // "hc4", or "hc4 {ratio=0.1} [gps_period=5]"
  std::string algorithm;
  double w = 0;
  int runs = 0;
  int steps = 0;
  double mean_area = 0;    // m^2
  double mean_time_s = 0;  // per CSP
  bool paper_scenario = false;  // IsPaperScenario of the problem params
};
// The points of every configuration with ok runs at two or more w, ordered by
// algorithm (display order), label and w.
std::vector<WindowPoint> WindowSweep(const std::vector<RunRecord>& runs);

// How tables and figures show an algorithm: its registry display data; for
// one no longer registered (an old store), its name, order 1000 and grey.
Display DisplayOf(const std::string& algorithm);
// Display order, then name: the order of algorithms in tables and figures.
bool AlgorithmLess(const std::string& a, const std::string& b);
// "k=v,k2=v2" (sorted by key); "" for no params.
std::string CompactParams(const ParamMap& params);
// About 4 significant digits without exponent for 1e-3 <= |v| < 1e9
// (trailing zeros dropped: 0.52, 1400, 0.4873; integers from 1e4 on),
// exponent form otherwise; "—" for NaN, "∞"/"-∞" for infinities.
std::string FormatNumber(double v);
// LaTeX text for a table cell: _ & % # { } $ ~ ^ \ escaped, the few
// non-ASCII signs of the tables (— µ ² × ∞ …) written as LaTeX.
std::string TexEscape(const std::string& text);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_REPORT_H_
