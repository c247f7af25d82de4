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
}

Interval Grid::Cell(const Interval& extent, int n, int i) const {
  if (i == 0 && n == 1) return extent;
  const Interval step = (Interval(extent.hi()) - Interval(extent.lo())) / Interval(n);
  const Interval cell = Interval(extent.lo()) + step * Interval(i, i + 1.0);
  // The outer cells end exactly on the search box.
  return Interval(i == 0 ? extent.lo() : cell.lo(), i == n - 1 ? extent.hi() : cell.hi());
}

Interval Grid::CellX(int col) const { return Cell(search_[x_], cols_, col); }
Interval Grid::CellY(int row) const { return Cell(search_[y_], rows_, row); }

Box Grid::Block(int row0, int row1, int col0, int col1) const {
  Box box = search_;
  box[x_] = Interval(CellX(col0).lo(), CellX(col1 - 1).hi());
  box[y_] = Interval(CellY(row0).lo(), CellY(row1 - 1).hi());
  return box;
}

std::pair<int, int> Grid::Meeting(const Interval& extent, int n, const Interval& v,
                                  bool columns) const {
  const Interval w = Intersect(v, extent);
  if (w.IsEmpty()) return {0, 0};
  auto cell = [&](int i) { return columns ? CellX(i) : CellY(i); };
  auto guess = [&](double t) {
    const double f = (t - extent.lo()) / (extent.hi() - extent.lo()) * n;
    return std::clamp(static_cast<int>(std::floor(f)), 0, n - 1);
  };
  // The division may be off by one cell either way; the exact cell bounds decide.
  int first = guess(w.lo());
  while (first > 0 && cell(first - 1).hi() >= w.lo()) --first;
  while (first < n - 1 && cell(first).hi() < w.lo()) ++first;
  int last = guess(w.hi());
  while (last < n - 1 && cell(last + 1).lo() <= w.hi()) ++last;
  while (last > 0 && cell(last).lo() > w.hi()) --last;
  return {first, last + 1};
}

std::pair<int, int> Grid::ColsMeeting(const Interval& v) const {
  return Meeting(search_[x_], cols_, v, true);
}
std::pair<int, int> Grid::RowsMeeting(const Interval& v) const {
  return Meeting(search_[y_], rows_, v, false);
}

bool Grid::CellOf(double px, double py, int* row, int* col) const {
  if (!search_[x_].Contains(px) || !search_[y_].Contains(py)) return false;
  *col = ColsMeeting(Interval(px)).first;
  *row = RowsMeeting(Interval(py)).first;
  return true;
}

}  // namespace icp
