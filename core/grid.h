// A regular grid of cells over components x and y of a search box (paper 003
// Def. 22): `cols` cells across x, `rows` across y, row r covering y, column
// c covering x. Cell bounds are computed outward, so the cells cover the
// search box and neighbouring cells overlap by at most a few ulps; a point
// on a shared border belongs to both cells.
#ifndef ICPBENCH_CORE_GRID_H_
#define ICPBENCH_CORE_GRID_H_

#include <utility>
#include <vector>

#include "core/box.h"

namespace icp {

class Grid {
 public:
  // Throws std::invalid_argument unless search is bounded in x and y and
  // cols, rows >= 1.
  Grid(Box search, int x, int y, int cols, int rows);

  int cols() const { return cols_; }
  int rows() const { return rows_; }
  int x() const { return x_; }
  int y() const { return y_; }
  const Box& search() const { return search_; }

  Interval CellX(int col) const;
  Interval CellY(int row) const;
  // The search box with x and y narrowed to the block of cells
  // [row0, row1) x [col0, col1).
  Box Block(int row0, int row1, int col0, int col1) const;
  // The columns [first, last) whose cells meet v (v within the search x);
  // first == last when none does. Likewise for rows.
  std::pair<int, int> ColsMeeting(const Interval& v) const;
  std::pair<int, int> RowsMeeting(const Interval& v) const;
  // The cell holding (px, py), or false when the point is outside the grid.
  bool CellOf(double px, double py, int* row, int* col) const;

 private:
  // Bounds of the n cells over extent: [lo[i], hi[i]].
  static void Cells(const Interval& extent, int n, std::vector<double>* lo, std::vector<double>* hi);
  static std::pair<int, int> Meeting(const std::vector<double>& lo, const std::vector<double>& hi,
                                     const Interval& v);

  Box search_;
  int x_, y_;
  int cols_, rows_;
  // Computed once: the accumulator asks for them millions of times.
  std::vector<double> col_lo_, col_hi_, row_lo_, row_hi_;
};

}  // namespace icp

#endif  // ICPBENCH_CORE_GRID_H_
