#include "core/accumulate.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/memory_budget.h"

namespace icp {

namespace {
constexpr int kSmallBlock = 32;

struct Raster {
  Raster(const Grid& g, Contractor& c, const StopCondition& s, cv::Mat& m)
      : grid(g), contractor(c), stop(s), counts(m), box(g.search()) {}
  const Grid& grid;
  Contractor& contractor;
  const StopCondition& stop;
  cv::Mat& counts;  // CV_32S, this task's own
  WorkCounters work;
  bool stopped = false;
  int calls = 0;
  Box box;  // the block being contracted; the other components are the search box's

  void Count(int r0, int r1, int c0, int c1) {
    counts(cv::Range(r0, r1), cv::Range(c0, c1)) += cv::Scalar(1);
  }

  // Contracts the block [r0, r1) x [c0, c1) into box; false when the
  // contractor rejects it. Past the stop condition, counts the block.
  bool Contract(int r0, int r1, int c0, int c1) {
    // The clock is read every 256 blocks: a block costs well under a microsecond.
    if (stopped || ((calls++ & 255) == 0 && stop.ShouldStop())) {
      stopped = true;
      Count(r0, r1, c0, c1);
      return false;
    }
    box = grid.search();  // a contraction may have narrowed the other components
    box[grid.x()] = Interval(grid.CellX(c0).lo(), grid.CellX(c1 - 1).hi());
    box[grid.y()] = Interval(grid.CellY(r0).lo(), grid.CellY(r1 - 1).hi());
    ContractContext context(stop);
    const ContractSummary s = contractor.Contract(box, context);
    work += s.work;
    return s.status != ContractStatus::kEmpty && !box.IsEmpty();
  }

  // Marks the cells of block [r0, r1) x [c0, c1) that the contractor cannot reject.
  void Mark(int r0, int r1, int c0, int c1) {
    if (!Contract(r0, r1, c0, c1)) return;
    // Only the cells meeting the contracted box can hold a point it keeps.
    const auto [nc0, nc1] = grid.ColsMeeting(box[grid.x()]);
    const auto [nr0, nr1] = grid.RowsMeeting(box[grid.y()]);
    c0 = std::max(c0, nc0), c1 = std::min(c1, nc1);
    r0 = std::max(r0, nr0), r1 = std::min(r1, nr1);
    if (r0 >= r1 || c0 >= c1) return;
    if (r1 - r0 == 1 || c1 - c0 == 1 || (r1 - r0) * (c1 - c0) <= kSmallBlock) {
      // A strip or a small block: each cell is tested on its own, which
      // costs fewer contractions than splitting further.
      for (int r = r0; r < r1; ++r)
        for (int c = c0; c < c1; ++c)
          if (Contract(r, r + 1, c, c + 1)) ++counts.at<std::int32_t>(r, c);
      return;
    }
    if (r1 - r0 >= c1 - c0) {
      const int mid = r0 + (r1 - r0) / 2;
      Mark(r0, mid, c0, c1);
      Mark(mid, r1, c0, c1);
    } else {
      const int mid = c0 + (c1 - c0) / 2;
      Mark(r0, r1, c0, mid);
      Mark(r0, r1, mid, c1);
    }
  }
};
}  // namespace

std::size_t CountGridBytes(const Grid& grid) {
  return static_cast<std::size_t>(grid.rows()) * static_cast<std::size_t>(grid.cols()) *
         sizeof(std::int32_t);
}

std::string CountGridName(const Grid& grid) {
  return std::to_string(grid.cols()) + " x " + std::to_string(grid.rows()) + " cells";
}

cv::Mat Accumulate(const Grid& grid, const SharedContractors& measurements,
                   const StopCondition& stop, WorkCounters* work, bool* stopped) {
  const std::size_t bytes = CountGridBytes(grid);
  const std::optional<MemoryBudget> budget = DataMemoryBudget();
  CheckMemory(bytes, "an accumulator's count grid of " + CountGridName(grid), budget);
  cv::Mat counts(grid.rows(), grid.cols(), CV_32S, cv::Scalar(0));
  // Each thread counts into a grid of its own: as many threads as such grids
  // fit in the memory left, and with one, straight into counts (the sums are
  // the same whatever the split).
  std::size_t threads =
      static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
  if (budget)
    threads = std::min(threads, (budget->available - bytes) / std::max<std::size_t>(bytes, 1));
  WorkCounters total;
  std::atomic<bool> any_stopped = false;
  // Measurements not begun when the stop came: they count in every cell,
  // added once at the end (cell by cell, a fine grid took longer to stop
  // than to finish).
  std::atomic<int> unstarted = 0;
  // Adds one measurement's cells to `into`; returns its work.
  auto rasterise = [&](Contractor& measurement, cv::Mat& into) {
    if (stop.ShouldStop()) {
      any_stopped = true;
      ++unstarted;
      return WorkCounters();
    }
    Raster raster(grid, measurement, stop, into);
    raster.Mark(0, grid.rows(), 0, grid.cols());
    if (raster.stopped) any_stopped = true;
    return raster.work;
  };
  if (threads <= 1 || measurements.size() <= 1) {
    for (const std::shared_ptr<Contractor>& m : measurements) total += rasterise(*m, counts);
  } else {
    tbb::enumerable_thread_specific<cv::Mat> partial(
        [&] { return cv::Mat(grid.rows(), grid.cols(), CV_32S, cv::Scalar(0)); });
    std::mutex work_mutex;
    auto count = [&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, measurements.size(), 1),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          cv::Mat& own = partial.local();
                          for (std::size_t i = range.begin(); i != range.end(); ++i) {
                            const WorkCounters work = rasterise(*measurements[i], own);
                            std::lock_guard<std::mutex> lock(work_mutex);
                            total += work;
                          }
                        });
    };
    if (static_cast<int>(threads) < tbb::this_task_arena::max_concurrency())
      tbb::task_arena(static_cast<int>(threads)).execute(count);
    else
      count();
    for (const cv::Mat& p : partial) counts += p;
  }
  if (unstarted > 0) counts += cv::Scalar(unstarted.load());
  if (work) *work += total;
  if (stopped) *stopped = any_stopped;
  return counts;
}

}  // namespace icp
