// Tables from the results store (`icpbench report DIR [--format md|tex|csv]`).
// The generic report is an overview line and one table:
//
//   Runs per configuration: one row per (algorithm, algorithm params,
//   problem, problem params), aggregated over seeds: run counts by status,
//   CSPs, mean area, consistency rate (paper 004 eq. 31), centre RMSE and the
//   solve time per CSP (median, p90, mean). Mean area and mean time are the
//   median over the runs (seeds) of each run's mean with its 95 % interval
//   (MedianWithInterval); the others pool the steps.
//   Below it (md, tex) a short list of the failed, timed-out and skipped
//   runs with their reasons.
//
// A caller's tables follow (TableMaker: experiments/ adds a paper's), built
// with the helpers below so they read the same; last (md, tex), the
// performance profiles of the time per CSP and of the mean area over every
// problem instance (report/performance_profile.h).
//
// Aggregation: a group's metrics are ComputeMetrics over the pooled steps of
// its ok runs (every CSP weighs the same, whichever seed it came from). When
// some ok run of the group has no step records loaded, the runs' stored
// metrics are combined instead, weighted by their step counts (root of the
// weighted mean square for the RMSE); the time median and p90 then cannot be
// pooled and are shown only for a single run.
//
// Parameters show as "k=v,k2=v2" ("default" in md/tex, an empty field in CSV
// when none were given). Numbers have about 4 significant digits
// (FormatNumber), a median with an interval the digits its interval supports
// (FormatWithInterval); a missing one (NaN) shows as "—". Times are per CSP,
// each column in one unit picked from its values (TimeUnit).
//
// CSV holds the runs-per-configuration table only, one header row then one
// row per group, RFC 4180 quoting, 6 significant digits, NaN as an empty
// field.
#ifndef ICPBENCH_REPORT_REPORT_H_
#define ICPBENCH_REPORT_REPORT_H_

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "core/params.h"
#include "harness/run_record.h"

namespace icp {

// A table in display form: cells are Unicode text as Markdown shows them
// ("—" for a missing value); the LaTeX writer escapes them.
struct TextTable {
  std::string title;
  std::vector<std::string> headers;
  std::vector<bool> numeric;  // right-aligned columns
  // LaTeX only: the width (cm) of each column whose cells wrap, 0 for none;
  // a wrapped column keeps its long cells instead of moving them to notes.
  std::vector<double> wrap_cm{};
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> notes;  // paragraphs after the table
  std::vector<std::string> items;  // a bullet list after the notes
  bool omit_if_empty = false;      // no rows: the notes only, no header
};

// Tables a caller adds after the generic one (md and tex only).
using TableMaker = std::function<std::vector<TextTable>(const std::vector<RunRecord>&)>;

// The report in format "md", "tex" or "csv"; throws std::invalid_argument for
// any other. No runs give the tables' headers with no rows.
std::string Report(const std::vector<RunRecord>& runs, const std::string& format,
                   const TableMaker& more = nullptr);

// Report() over the runs (with their steps) of the results store in dir.
// Throws std::runtime_error when dir holds no store, StoreError when it
// cannot be read.
std::string ReportDirectory(const std::string& dir, const std::string& format,
                            const TableMaker& more = nullptr);

// Loads every run of the store in dir with its steps; the shared entry of
// ReportDirectory and the plots. The store keeps effective parameters; the
// runs come back with only those that differ from the current defaults
// (WithoutDefaults, harness/spec.h), which is what the tables show. Throws as
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
  // Every run and the ok runs, in store order (pointers into the input
  // vector).
  std::vector<const RunRecord*> runs;
  std::vector<const RunRecord*> ok_runs;
};

// An ok run stored with `record: runs`: metrics over its steps, no step
// rows. Tables use its run metrics; tables and figures over steps cannot.
bool RecordedRunsOnly(const RunRecord& run);

// True (ExperimentOf: harness/run_record.h) when some run of the group (any status) is of that experiment.
bool HasExperiment(const GroupSummary& group, const std::string& experiment);

// Groups runs by (algorithm, algorithm params, problem, problem params),
// ordered by problem, problem params, algorithm (display order, then name)
// and algorithm params; numeric parameter values compare as numbers.
std::vector<GroupSummary> SummariseGroups(const std::vector<RunRecord>& runs);

// Aggregates the given runs as one group (counts, problems, metrics).
GroupSummary Summarise(const std::vector<const RunRecord*>& runs);

// One point of a sweep over one problem parameter: a configuration
// (algorithm, its params, the problem params other than the swept one) at one
// value, over its ok runs.
struct SweepPoint {
  std::string label;  // "hc4", or "hc4 {ratio=0.1} [gps_period=5]"
  std::string algorithm;
  double value = 0;
  int runs = 0;
  int steps = 0;
  double mean_area = 0;    // m^2
  double mean_time_s = 0;  // per CSP
  // The mean over the steps of window_mean_area (the mean x-y area of the
  // window's states, reported by window estimators); NaN when none reports it.
  double mean_window_area = 0;
  std::vector<const RunRecord*> ok_runs;  // pointers into the input vector
};
// The points of every configuration of problem with ok runs at two or more
// numeric values of param (absent: the problem's current default), ordered
// by algorithm (display order), label and value.
std::vector<SweepPoint> ParamSweep(const std::vector<RunRecord>& runs, const std::string& problem,
                                   const std::string& param);

// The median of values (one per run: a seed) with a distribution-free 95 %
// confidence interval of the median from order statistics: [x_(k),
// x_(n+1-k)] for the largest k whose coverage 1 - 2 P(Binomial(n, 1/2) < k)
// is at least 0.95. No such k below n = 6 values (with 6, [min, max] covers
// 1 - 2/64 = 96.9 %): lo and hi are then NaN. NaN values are left out.
struct MedianInterval {
  int n = 0;
  double median = std::numeric_limits<double>::quiet_NaN();  // NaN for no values
  double lo = std::numeric_limits<double>::quiet_NaN();      // NaN when n < 6
  double hi = std::numeric_limits<double>::quiet_NaN();
  double coverage = std::numeric_limits<double>::quiet_NaN();  // exact; NaN when n < 6
};
MedianInterval MedianWithInterval(std::vector<double> values);
// The runs whose values the tables summarise: value(run) for each ok run of
// the group (its stored metrics are there with or without step rows).
MedianInterval RunMedian(const GroupSummary& group,
                         const std::function<double(const RunRecord&)>& value);
// Per seed, value(a's run) / value(b's run) over the seeds where both groups
// have an ok run (a paired comparison: the same instance), then their
// median with its interval; e.g. time_mean_s of BC4 over HC4.
MedianInterval PairedRatio(const GroupSummary& a, const GroupSummary& b,
                           const std::function<double(const RunRecord&)>& value);
// A run's mean solve time per step and mean area: the values RunMedian is
// most often given.
double RunMeanTime(const RunRecord& run);
double RunMeanArea(const RunRecord& run);
// The mean over a run's steps of window_mean_area (see SweepPoint); NaN
// without steps or the property.
double RunMeanWindowArea(const RunRecord& run);

// How tables and figures show an algorithm: its registry display data; for
// one no longer registered (an old store), its name, order 1000 and grey.
Display DisplayOf(const std::string& algorithm);
// Display order, then name: the order of algorithms in tables and figures.
bool AlgorithmLess(const std::string& a, const std::string& b);
// "k=v,k2=v2" (sorted by key); "" for no params.
std::string CompactParams(const ParamMap& params);
// "hc4 {ratio=0.1}"; just name for no params.
std::string WithParams(const std::string& name, const ParamMap& params);
// CompactParams, or "default" for no params: a table cell.
std::string ParamsCell(const ParamMap& params);
// A group's runs cell: its ok runs, "2 of 3" when some were not ok.
std::string OkRunsCell(const GroupSummary& group);
// A table item for one of a group's problems (a run that was not ok, with
// its reason): "hc4 on car-track {w=5}: failed (seed 3): threw: boom".
std::string ProblemItem(const GroupSummary& group, const std::string& problem);
// FormatNumber(a / b); "—" when either is NaN or b is 0.
std::string FormatRatio(double a, double b);
// About 4 significant digits without exponent for 1e-3 <= |v| < 1e9
// (trailing zeros dropped: 0.52, 1400, 0.4873; integers from 1e4 on),
// exponent form otherwise; "—" for NaN, "∞"/"-∞" for infinities.
std::string FormatNumber(double v);
// A median with its interval, rounded to what the interval supports: to the
// decimal of the leading digit of its half-width (one more when that digit is
// 1), e.g. 18.2 [17.9, 18.6], 0.0712 [0.0700, 0.0731], 1400 [1300, 1500];
// the values are multiplied by scale (a column's unit) first. Without an
// interval (fewer than 6 values) or with one of zero width, FormatNumber of
// the median; "—" for none.
std::string FormatWithInterval(const MedianInterval& m, double scale = 1);
// A column's unit for times in seconds: the largest of s, ms, µs and ns in
// which the median magnitude of the column's non-zero values is at least 1
// (µs when it has none), so one column has one unit and, unless it spans
// more than three decades below its median, no exponent.
struct Unit {
  std::string name;  // "ms"
  double scale;      // seconds -> unit: 1e3
};
Unit TimeUnit(const std::vector<double>& seconds);
// Long entries of a table's text columns, moved under it: every non-numeric
// cell longer than max_chars becomes a marker "(a)", "(b)", ... (equal texts
// share one) and a note "(a) text" comes first under the table. TexTable does
// this with kMaxTexCellChars, so one long cell cannot shrink a whole table.
inline constexpr std::size_t kMaxTexCellChars = 36;
// TexTable's tabular is shrunk to this share of the text height when taller
// (with its caption it must fit a float page), as "0.85" for LaTeX.
inline constexpr const char* kMaxTexTableHeight = "0.85";
TextTable WithLongCellsAsNotes(TextTable table, std::size_t max_chars);

// LaTeX text for a table cell: _ & % # { } $ ~ ^ \ escaped, the few
// non-ASCII signs of the tables (— µ ² × ∞ … ≤ ≥ § − ± ≈, Greek letters
// such as ρ τ θ) and < > | (which the default text font lacks) written as
// LaTeX.
std::string TexEscape(const std::string& text);
// One table as `report --format tex` writes it (a booktabs table float,
// shrunk to the line width when wider, its notes as paragraphs, its items as
// a list): what paper/ includes too.
std::string TexTable(const TextTable& table);

}  // namespace icp

#endif  // ICPBENCH_REPORT_REPORT_H_
