// accumulator: the discrete accumulator of the measurements (paper 003
// §2.6, §5.2): a grid over the x-y components of the prior (the first two
// components when the state names no position) with cells of the view's
// search box over `cells` (so `cells` x `cells` over the search box, and
// the same cell size over the smaller prior of a filtering step), each
// cell counting the measurements that cannot reject it (eq. 5.28, upper
// bound). The estimate is the set of cells counting at least m - q: with
// auto_q and q = 0, the cells with the highest count, m - q being that
// count. With several sources (robots) the accumulator of each is computed
// apart and the estimate is their sum (§5.2.3, prop. 13: the distributed
// case); step properties give each source's highest count.
//
// Sound: every point that satisfies m - q measurements lies in a cell
// counting at least m - q (prop. 32). The other components of a cell are
// the prior's.
#ifndef ICPBENCH_ALGORITHMS_ACCUMULATOR_ACCUMULATOR_H_
#define ICPBENCH_ALGORITHMS_ACCUMULATOR_ACCUMULATOR_H_

#include <cstdint>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "algorithms/relaxed/relaxed_estimator.h"
#include "core/grid.h"

namespace icp {

struct AccumulatorParams {
  RelaxedParams relaxed;
  // Cells per axis: the set's resolution is the prior's width over this;
  // time and memory grow with the cells a measurement's band crosses (about
  // linearly in `cells` for curves).
  int cells = 1000;
};
void Describe(AccumulatorParams& p, ParamSet& set);

// The grid over prior that the accumulator uses for a state space: its x-y
// components, or the first two, in cells of search's extent over `cells`
// (prior lies in search); throws std::invalid_argument for a state of one
// component or a search box unbounded there.
Grid AccumulatorGrid(const Box& prior, const Box& search, const StateSpace& space, int cells);

// The counts of each source's measurements apart (sources numbered from 0;
// empty `sources`: one source), then their sum as the last element (the
// same matrix as the first with one source). Throws MemoryBudgetError (a
// std::bad_alloc) before allocating when the grids do not fit under the
// process's data limit (a worker's memory_limit_mb), std::bad_alloc when
// an allocation fails all the same.
std::vector<cv::Mat> SourceAccumulators(const Grid& grid, const MeasurementSetView& view,
                                        const StopCondition& stop, WorkCounters* work,
                                        bool* stopped);

std::unique_ptr<Estimator> MakeAccumulator(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_ACCUMULATOR_ACCUMULATOR_H_
