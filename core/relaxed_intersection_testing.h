// The reference q-relaxed intersection of boxes, by brute force: the hull of
// the grid points (each coordinate one of the boxes' bounds in its
// dimension) that lie in at least m - q of the closed boxes. Exact: the
// points of at least m - q boxes form a union of intersections of closed
// boxes, each a closed box whose corners are such grid points. O((2m)^n m).
#ifndef ICPBENCH_CORE_RELAXED_INTERSECTION_TESTING_H_
#define ICPBENCH_CORE_RELAXED_INTERSECTION_TESTING_H_

#include <algorithm>
#include <span>
#include <vector>

#include "core/box.h"

namespace icp::testing {

inline Box ReferenceRelaxedIntersection(std::span<const Box> boxes, int q, std::size_t n) {
  const int m = static_cast<int>(boxes.size());
  Box out(n);
  if (q >= m) return out;
  out.SetEmpty();
  std::vector<std::vector<double>> grid(n);
  for (const Box& b : boxes) {
    if (b.IsEmpty()) continue;
    for (std::size_t d = 0; d < n; ++d) {
      grid[d].push_back(b[d].lo());
      grid[d].push_back(b[d].hi());
    }
  }
  if (grid.empty() || grid[0].empty()) return out;
  for (auto& g : grid) {
    std::sort(g.begin(), g.end());
    g.erase(std::unique(g.begin(), g.end()), g.end());
  }
  // Odometer over the grid's indices.
  std::vector<std::size_t> at(n, 0);
  std::vector<double> point(n);
  while (true) {
    for (std::size_t d = 0; d < n; ++d) point[d] = grid[d][at[d]];
    int cover = 0;
    for (const Box& b : boxes) {
      if (b.IsEmpty()) continue;
      bool in = true;
      for (std::size_t d = 0; d < n && in; ++d) in = b[d].Contains(point[d]);
      cover += in ? 1 : 0;
    }
    if (cover >= m - q)
      for (std::size_t d = 0; d < n; ++d) out[d] = Hull(out[d], Interval(point[d]));
    std::size_t d = 0;
    while (d < n && ++at[d] == grid[d].size()) at[d++] = 0;
    if (d == n) break;
  }
  return out;
}

}  // namespace icp::testing

#endif  // ICPBENCH_CORE_RELAXED_INTERSECTION_TESTING_H_
