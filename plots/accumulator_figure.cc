// An accumulator (a matrix of counts over a rectangle) as an image with its
// markers, reduced by BlockMax when it has too many cells to draw.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "plots/figures.h"
#include "plots/figures_internal.h"

namespace icp {

namespace {
constexpr char kBigMarker[] = "#ff1a1a";
constexpr char kSmallMarker[] = "#ff9f1c";
// Sides that differ more than this many times are drawn not to scale: equal
// scales would draw the longer one as a line (and gnuplot warns of an
// extreme aspect ratio).
constexpr double kMaxEqualScales = 20;

// The side of BlockMax's blocks.
int BlockSide(const cv::Mat& counts, int max_side) {
  return std::max(
      {1, (counts.rows + max_side - 1) / max_side, (counts.cols + max_side - 1) / max_side});
}

// Whether an axis of this range draws as a point: gnuplot widens (and warns
// of) an empty range, and one of a few ulps has no tics to draw.
bool Degenerate(const Interval& range) {
  return !(range.Width() > 1e-9 * std::max({1.0, std::fabs(range.lo()), std::fabs(range.hi())}));
}

// The range an axis draws: range itself, or for a degenerate one a range
// about it as wide as the other axis (else 1), over which its cells are
// stretched: a zero-width cell has nothing to draw.
Interval DrawnRange(const Interval& range, const Interval& other) {
  if (!Degenerate(range)) return range;
  const double half = Degenerate(other) ? 0.5 : other.Width() / 2;
  const double mid = range.Mid();
  return Interval(mid - half, mid + half);
}

// gnuplot draws no image of fewer than 2 x 2 points ("Image grid must be at
// least 4 points"): a single row or column is drawn as two of half the size.
cv::Mat AtLeastTwoBySide(const cv::Mat& drawn, int* rows_per_cell, int* cols_per_cell) {
  *rows_per_cell = drawn.rows < 2 ? 2 : 1;
  *cols_per_cell = drawn.cols < 2 ? 2 : 1;
  if (*rows_per_cell == 1 && *cols_per_cell == 1) return drawn;
  cv::Mat out(drawn.rows * *rows_per_cell, drawn.cols * *cols_per_cell, CV_32S);
  for (int r = 0; r < out.rows; ++r)
    for (int c = 0; c < out.cols; ++c)
      out.at<int>(r, c) = drawn.at<int>(r / *rows_per_cell, c / *cols_per_cell);
  return out;
}
}  // namespace

cv::Mat BlockMax(const cv::Mat& counts, int max_side) {
  if (counts.type() != CV_32S) throw std::invalid_argument("BlockMax: counts must be CV_32S");
  if (max_side < 1) throw std::invalid_argument("BlockMax: max_side must be >= 1");
  const int block = BlockSide(counts, max_side);
  if (block == 1) return counts;
  const int rows = (counts.rows + block - 1) / block, cols = (counts.cols + block - 1) / block;
  cv::Mat out(rows, cols, CV_32S, cv::Scalar(std::numeric_limits<int>::min()));
  for (int r = 0; r < counts.rows; ++r) {
    const int* in = counts.ptr<int>(r);
    int* o = out.ptr<int>(r / block);
    for (int c = 0; c < counts.cols; ++c) o[c / block] = std::max(o[c / block], in[c]);
  }
  return out;
}

void PlotAccumulatorFigure(const FigureText& text, const cv::Mat& counts, const Interval& x,
                           const Interval& y, const std::vector<MarkerSet>& markers,
                           const std::string& out_dir, PlotOutput* out) {
  if (counts.empty() || x.IsEmpty() || y.IsEmpty()) return Skip(text, out);
  if (!std::isfinite(x.Width()) || !std::isfinite(y.Width())) {
    std::ostringstream range;
    range << x << " x " << y;
    out->messages.push_back(text.name + ": skipped: the accumulator's range " + range.str() +
                            " is not bounded");
    return;
  }
  const Interval range_x = DrawnRange(x, y), range_y = DrawnRange(y, x);
  // Each pixel of the drawn matrix stands for a block of block x block
  // cells (the last of a row or column may hold fewer and overhang the
  // range, which clips it), or for half a cell of a single row or column.
  const int block = BlockSide(counts, kAccumulatorPlotCells);
  int rows_per_cell = 1, cols_per_cell = 1;
  const cv::Mat drawn =
      AtLeastTwoBySide(BlockMax(counts, kAccumulatorPlotCells), &rows_per_cell, &cols_per_cell);
  const double cell_x = range_x.Width() / counts.cols * block / cols_per_cell,
               cell_y = range_y.Width() / counts.rows * block / rows_per_cell;
  double max_count = 0;
  cv::minMaxLoc(counts, nullptr, &max_count);
  std::ostringstream data;
  data << "$counts << EOD\n";
  for (int r = 0; r < drawn.rows; ++r) {
    const int* row = drawn.ptr<int>(r);
    for (int c = 0; c < drawn.cols; ++c) data << (c ? " " : "") << row[c];
    data << "\n";
  }
  data << "EOD\n";
  auto num = [](double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
  };
  // The truth's cross is drawn as four arms around an open centre, so it
  // does not hide the maximum it marks; small crosses are plain points.
  const double side = std::max(range_x.Width(), range_y.Width());
  const double arm_out = 0.045 * side, arm_in = 0.012 * side;
  std::string arrows;
  int arrow = 0;
  for (const MarkerSet& m : markers) {
    if (!m.big) continue;
    for (const auto& [px, py] : m.points) {
      for (const double dx : {-1.0, 1.0}) {
        for (const double dy : {-1.0, 1.0}) {
          arrows += "set arrow " + std::to_string(++arrow) + " from " + num(px + dx * arm_in) +
                    "," + num(py + dy * arm_in) + " to " + num(px + dx * arm_out) + "," +
                    num(py + dy * arm_out) + " nohead front lw 3.5 lc rgb '" + kBigMarker + "'\n";
        }
      }
    }
  }
  Panel panel;
  // The title wrapped to the square plot, narrower than the page.
  panel.setup = data.str() + "set title " + MultiLine(Wrapped(text.title, 0.7 * kPrintWidthIn)) +
                " noenhanced\nunset grid\n" +
                "set xlabel 'x (m)'\nset ylabel 'y (m)'\n" +
                (side <= kMaxEqualScales * std::min(range_x.Width(), range_y.Width())
                     ? "set size ratio -1\n"
                     : "set size square\n") +
                "set xrange [" + num(range_x.lo()) + ":" + num(range_x.hi()) +
                "]\nset yrange [" + num(range_y.lo()) + ":" + num(range_y.hi()) + "]\n" +
                "set cbrange [0:" + num(std::max(1.0, max_count)) + "]\nset cblabel 'count'\n" +
                "set cbtics " + num(std::max(1.0, std::ceil(max_count / 10))) + "\n" +
                // viridis: light enough at low counts that single bands show
                "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', "
                "1 '#fde725')\n" +
                "set bmargin 5.5\nset tics out\n"
                "set key at screen 0.45, screen 0.015 center bottom horizontal noenhanced\n" +
                arrows;
  panel.series.push_back({"", {},
                          "$counts matrix using (" + num(range_x.lo()) + " + ($1 + 0.5) * " +
                              num(cell_x) + "):(" + num(range_y.lo()) + " + ($2 + 0.5) * " +
                              num(cell_y) + "):3 with image notitle"});
  for (const MarkerSet& m : markers) {
    const std::string title = m.title.empty() ? " notitle" : " title " + Quote(m.title);
    if (m.big) {  // the arrows above; a legend entry only
      if (!m.title.empty() && !m.points.empty())
        panel.series.push_back(
            {"with points pt 2 ps 2.5 lw 3.5 lc rgb '" + std::string(kBigMarker) + "'" + title,
             {}, "keyentry"});
      continue;
    }
    Series s{std::string("using 1:2 with points pt 2 ps 1.8 lw 2.5 lc rgb '") + kSmallMarker + "'" +
                 title,
             {}, ""};
    for (const auto& [px, py] : m.points) s.rows.push_back({px, py});
    if (HasPoint(s)) panel.series.push_back(std::move(s));
  }
  RenderPanel(text.name, kPrintWidthIn, 5.4, panel, out_dir, out);
}

}  // namespace icp
