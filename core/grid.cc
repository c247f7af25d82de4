#include "core/grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace icp {

Grid::Grid(Box search, int x, int y, int cols, int rows)
    : search_(std::move(search)), x_(x), y_(y), cols_(cols), rows_(rows) {
  if (cols < 1 || rows < 1) throw std::invalid_argument("grid: cols and rows must be >= 1");
  if (x < 0 || y < 0 || x >= static_cast<int>(search_.size()) || y >= static_cast<int>(search_.size()))
    throw std::invalid_argument("grid: x and y must be components of the search box");
  if (search_.IsEmpty() || !(search_[x].Width() < kInf) || !(search_[y].Width() < kInf))
    throw std::invalid_argument("grid: the search box must be non-empty and bounded in x and y");
  Cells(search_[x_], cols_, &col_lo_, &col_hi_);
  Cells(search_[y_], rows_, &row_lo_, &row_hi_);
}

void Grid::Cells(const Interval& extent, int n, std::vector<double>* lo, std::vector<double>* hi) {
  const Interval step = (Interval(extent.hi()) - Interval(extent.lo())) / Interval(n);
  for (int i = 0; i < n; ++i) {
    const Interval cell = Interval(extent.lo()) + step * Interval(i, i + 1.0);
    // The outer cells end exactly on the search box, and no cell leaves it:
    // over a few ulps the rounded step is wider than the extent (the true
    // cells lie inside, so clamping keeps them covered).
    lo->push_back(i == 0 ? extent.lo() : std::clamp(cell.lo(), extent.lo(), extent.hi()));
    hi->push_back(i == n - 1 ? extent.hi() : std::clamp(cell.hi(), extent.lo(), extent.hi()));
  }
}

Interval Grid::CellX(int col) const { return Interval(col_lo_[col], col_hi_[col]); }
Interval Grid::CellY(int row) const { return Interval(row_lo_[row], row_hi_[row]); }

Box Grid::Block(int row0, int row1, int col0, int col1) const {
  Box box = search_;
  box[x_] = Interval(col_lo_[col0], col_hi_[col1 - 1]);
  box[y_] = Interval(row_lo_[row0], row_hi_[row1 - 1]);
  return box;
}

std::pair<int, int> Grid::Meeting(const std::vector<double>& lo, const std::vector<double>& hi,
                                  const Interval& v) {
  if (v.IsEmpty()) return {0, 0};
  const int n = static_cast<int>(lo.size());
  // The cells are of equal width up to rounding: a division guesses the
  // index, the exact bounds correct it by a step or two. Over a point or a
  // few ulps the width is 0 or underflows and the quotient NaN or infinite:
  // the guess is clamped before the cast, and the bounds walk the rest.
  const double start = lo[0], width = (hi[n - 1] - lo[0]) / n;
  auto guess = [&](double t) {
    const double f = std::floor((t - start) / width);
    return !(f >= 0) ? 0 : f >= n ? n - 1 : static_cast<int>(f);
  };
  // The first cell ending at or after v.lo, and one past the last cell
  // starting at or before v.hi (both bound lists ascend): the guess when it
  // is right, else a binary search (cells of a few ulps share bounds, and a
  // walk from the guess would cross all of them).
  int first = guess(v.lo());
  if (!((first == 0 || hi[first - 1] < v.lo()) && hi[first] >= v.lo()))
    first = static_cast<int>(std::partition_point(hi.begin(), hi.end(),
                                                  [&](double b) { return b < v.lo(); }) -
                             hi.begin());
  int last = guess(v.hi()) + 1;
  if (!((last == n || lo[last] > v.hi()) && lo[last - 1] <= v.hi()))
    last = static_cast<int>(std::partition_point(lo.begin(), lo.end(),
                                                 [&](double b) { return b <= v.hi(); }) -
                            lo.begin());
  if (first >= last) return {0, 0};
  return {first, last};
}

std::pair<int, int> Grid::ColsMeeting(const Interval& v) const { return Meeting(col_lo_, col_hi_, v); }
std::pair<int, int> Grid::RowsMeeting(const Interval& v) const { return Meeting(row_lo_, row_hi_, v); }

bool Grid::CellOf(double px, double py, int* row, int* col) const {
  if (!search_[x_].Contains(px) || !search_[y_].Contains(py)) return false;
  *col = ColsMeeting(Interval(px)).first;
  *row = RowsMeeting(Interval(py)).first;
  return true;
}

}  // namespace icp
