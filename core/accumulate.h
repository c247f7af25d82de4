// The discrete accumulator (paper 003 §5.2.2): over a grid of the search
// box, the number of measurements whose contractor cannot reject each cell,
// the upper bound [A*]^+ of eq. 5.28. Every point that satisfies k
// measurements lies in a cell counting at least k (prop. 32), so the cells
// counting >= m - q enclose the q-relaxed solution set.
//
// A measurement's band is rasterised by its own contractor instead of
// testing every cell: a block of cells is contracted, shrunk to the cells
// meeting what is left, and split in two until single cells remain, so the
// cost grows with the cells the band crosses, not with the grid.
// Measurements are counted in parallel (TBB), one contractor per task.
#ifndef ICPBENCH_CORE_ACCUMULATE_H_
#define ICPBENCH_CORE_ACCUMULATE_H_

#include <cstddef>
#include <string>

#include <opencv2/core.hpp>

#include "core/contractor_algebra.h"
#include "core/grid.h"

namespace icp {

// Counts (CV_32S, grid.rows() x grid.cols()) of measurements that cannot
// reject each cell. When stop fires, the blocks not yet examined are counted
// for every measurement they were pending for (sound) and *stopped is set.
// Each thread counts into a grid of its own: under a data limit
// (core/memory_budget.h) only as many threads run as grids fit, one
// counting straight into the result when no more does; MemoryBudgetError
// (a std::bad_alloc) before anything is allocated when the result does not fit.
cv::Mat Accumulate(const Grid& grid, const SharedContractors& measurements,
                   const StopCondition& stop, WorkCounters* work = nullptr,
                   bool* stopped = nullptr);

// The bytes of one count grid over grid, and its size for messages
// ("2000 x 1000 cells").
std::size_t CountGridBytes(const Grid& grid);
std::string CountGridName(const Grid& grid);

}  // namespace icp

#endif  // ICPBENCH_CORE_ACCUMULATE_H_
