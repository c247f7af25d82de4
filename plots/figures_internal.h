// What the figure kinds of plots/ share and callers do not see: a figure as
// panels of series, gnuplot quoting, rendering, and the skip messages.
#ifndef ICPBENCH_PLOTS_FIGURES_INTERNAL_H_
#define ICPBENCH_PLOTS_FIGURES_INTERNAL_H_

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "harness/run_record.h"
#include "plots/figures.h"

namespace icp::detail::plots {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One plotted item: inline data sent after the plot command ('-'), or a
// function when rows is empty and function is set (e.g. the zero line).
struct Series {
  std::string spec;  // what follows '-' (or the function): "using 1:2 with lines ..."
  std::vector<std::vector<double>> rows;
  std::string function;
};

struct Panel {
  std::string setup;  // gnuplot commands before the plot command
  std::vector<Series> series;
};

// The size the paper prints a figure at: its template's text width (17 cm)
// and at most 0.75 of its text height (FigureTex in paper/sections.cc). A
// figure drawn no larger, with kFontPt fonts, prints its text at kFontPt or
// more (the paper never shrinks it); tests/paper_pages_test.cc checks it.
inline constexpr double kPrintWidthIn = 6.5;
inline constexpr double kPrintMaxHeightIn = 7.5;
inline constexpr int kFontPt = 8;

// A figure: panels in a rows x cols multiplot (one panel: no multiplot).
struct Figure {
  std::string name;  // file name without extension
  std::string title;
  double width_in = kPrintWidthIn;
  double height_in = 4;
  int rows = 1;
  int cols = 1;
  std::vector<Panel> panels;
  // Placed by hand instead of gnuplot's equal layout when either is set:
  // the rows' relative heights (empty: equal), and a strip this high at the
  // bottom for a legend set 'at screen' (FooterKey) by one of the panels.
  std::vector<double> row_weights;
  double footer_in = 0;
};

// A panel's legend in the figure's footer strip (Figure::footer_in), as wide
// as the page, in at most two rows.
inline constexpr char kFooterKey[] =
    "set key at screen 0.5, screen 0.01 center bottom horizontal maxrows 2 noenhanced\n";

// The height of the footer strip a kFooterKey legend of these entries
// needs: two entries a row when they are short, else one.
double FooterHeight(const std::vector<std::string>& titles);

// text broken at spaces into lines of about what width_in holds at kFontPt
// ('\n' between them), for titles that would run over their panel.
std::string Wrapped(const std::string& text, double width_in);

// "set xtics STEP\n" (axis "x", "y") with a round step giving at most
// max_tics tics over [lo, hi]; "" when the range is not finite.
std::string TicsFor(const std::string& axis, double lo, double hi, int max_tics);

// Colours by algorithm, the same in every figure.
std::string Colour(const std::string& algorithm);

// A gnuplot single-quoted string.
std::string Quote(const std::string& text);

// A gnuplot double-quoted string, so that a '\n' in text breaks the line.
std::string MultiLine(const std::string& text);

// Series that draw the same data (rows equal to a relative 1e-9, NaN
// equal to NaN): groups of indices into rows, each group in the order of its
// first member, its members in order.
std::vector<std::vector<std::size_t>> EqualGroups(
    const std::vector<std::vector<std::vector<double>>>& rows);

// The legend entry of a group of equal series, "hc4 = bc3 = bc4 (seed 1)":
// the labels joined by " = ", a parenthesised suffix they share written once.
std::string JoinedLabel(const std::vector<std::string>& labels,
                        const std::vector<std::size_t>& group);

// Records, for the figure's caption (paper/sections.cc FigureTex reads
// "NAME: note: ..."), that the series of each group of several were drawn
// once: "hc4 = bc3 = bc4 draw the same values (where: ...) and are drawn once".
void NoteEqualSeries(const std::string& figure, const std::vector<std::string>& labels,
                     const std::vector<std::vector<std::size_t>>& groups, const std::string& where,
                     PlotOutput* out);

// True when the positive finite values of v span at least kLogSpan (a
// decade): the axis reads better on a log scale. False when some value is
// not positive (a log scale cannot draw it).
inline constexpr double kLogSpan = 10;
bool SpansDecades(const std::vector<double>& v);

// v when finite, else NaN (gnuplot leaves a gap); Positive also for v <= 0
// (a log scale cannot draw it).
double Finite(double v);
double Positive(double v);

// True when the series draws something: a function, or a row without NaN.
bool HasPoint(const Series& s);
// Skipped with that reason when no run's rows hold two points without NaN:
// a line or band over the steps cannot show one step. True when skipped.
bool SkippedForOneStep(const FigureText& text, const std::vector<std::vector<std::vector<double>>>& rows,
                       PlotOutput* out);

// Writes f as out_dir/NAME.png and .pdf in one gnuplot session and records
// the files that came out non-empty.
void Render(const Figure& f, const std::string& out_dir, PlotOutput* out);

// Render of an untitled figure of one panel.
void RenderPanel(const std::string& name, double width_in, double height_in, const Panel& panel,
                 const std::string& out_dir, PlotOutput* out);

// The runs stored with `record: runs` (no step rows), and how many.
std::vector<const RunRecord*> RunsOnlyOf(const std::vector<const RunRecord*>& runs);
int CountRunsOnly(const std::vector<const RunRecord*>& runs);

// "1 run", "2 runs".
std::string RunCount(std::size_t n);

// "recorded with `record: runs` (experiment marina; run metrics only, no step
// rows; rerun with record: steps to draw them)": how the runs were stored,
// the spec experiments that planned them, and how to get their steps.
std::string RecordedWithRunsOnly(const std::vector<const RunRecord*>& runs);

// "2 runs were recorded with `record: runs` (...)".
std::string RunsOnlyText(int n);

// The skip message of a figure: text.skip_reason, unless some of runs (what
// it would draw) were stored with `record: runs`: then that it needs their
// step rows, so the user knows the runs exist and how to draw them.
void Skip(const FigureText& text, PlotOutput* out, const std::vector<const RunRecord*>& runs = {});

// Drawn, but without the runs that have no step rows: a note naming them.
void NoteRunsOnly(const FigureText& text, const std::vector<const RunRecord*>& runs,
                  PlotOutput* out);

// What figures on a map draw (track_figure.cc): the map's pixels as grey
// dots titled 'map'; a run's true x-y trajectory in black titled 'truth';
// the x-y hull of every every-th step of a run (not the empty ones) as
// rectangles in its algorithm's colour, titled title ("": none).
Series MapSeries(const std::vector<std::pair<double, double>>& points);
Series TruthSeries(const RunRecord& run);
Series BoxesSeries(const RunRecord& run, int every, const std::string& title);

}  // namespace icp::detail::plots

// The files of plots/, the only includers, use these names as they are.
// They are declared in detail::plots so that their symbols cannot clash with
// another library's.
namespace icp {
using detail::plots::BoxesSeries;
using detail::plots::Colour;
using detail::plots::CountRunsOnly;
using detail::plots::EqualGroups;
using detail::plots::Figure;
using detail::plots::Finite;
using detail::plots::FooterHeight;
using detail::plots::HasPoint;
using detail::plots::SkippedForOneStep;
using detail::plots::JoinedLabel;
using detail::plots::kFontPt;
using detail::plots::kFooterKey;
using detail::plots::kNaN;
using detail::plots::kPrintMaxHeightIn;
using detail::plots::kPrintWidthIn;
using detail::plots::MapSeries;
using detail::plots::MultiLine;
using detail::plots::NoteEqualSeries;
using detail::plots::NoteRunsOnly;
using detail::plots::Panel;
using detail::plots::Positive;
using detail::plots::Quote;
using detail::plots::RecordedWithRunsOnly;
using detail::plots::Render;
using detail::plots::RenderPanel;
using detail::plots::RunCount;
using detail::plots::RunsOnlyOf;
using detail::plots::RunsOnlyText;
using detail::plots::Series;
using detail::plots::Skip;
using detail::plots::SpansDecades;
using detail::plots::TicsFor;
using detail::plots::TruthSeries;
using detail::plots::Wrapped;
}  // namespace icp

#endif  // ICPBENCH_PLOTS_FIGURES_INTERNAL_H_
