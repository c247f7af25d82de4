#include "algorithms/accumulator/accumulator.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>

#include "core/accumulate.h"
#include "core/memory_budget.h"

namespace icp {

void Describe(AccumulatorParams& p, ParamSet& set) {
  Describe(p.relaxed, set);
  set.Add("cells", &p.cells, "grid cells per axis over the prior's x-y box", Range::Closed(1, 20000));
}

Grid AccumulatorGrid(const Box& prior, const Box& search, const StateSpace& space, int cells) {
  int x = space.x, y = space.y;
  if (x < 0 || y < 0) {
    if (prior.size() < 2)
      throw std::invalid_argument("accumulator: the state needs two components to grid");
    x = 0, y = 1;
  }
  if (!(search[x].Width() < kInf) || !(search[y].Width() < kInf))
    throw std::invalid_argument("accumulator: the search box must be bounded in the gridded components");
  auto count = [&](int c) {
    // A point search box (x in [1, 1]) has one cell: 0 / 0 is NaN.
    const double n = std::ceil(prior[c].Width() / search[c].Width() * cells);
    return n >= 1 ? static_cast<int>(std::min<double>(n, cells)) : 1;
  };
  return Grid(prior, x, y, count(x), count(y));
}

std::vector<cv::Mat> SourceAccumulators(const Grid& grid, const MeasurementSetView& view,
                                        const StopCondition& stop, WorkCounters* work,
                                        bool* stopped) {
  const int sources =
      view.sources.empty() ? 1 : 1 + *std::max_element(view.sources.begin(), view.sources.end());
  // Every grid it keeps, before one is allocated (one source: its counts
  // are the sum); Accumulate fits its threads' own grids in what is left.
  const std::size_t grids = sources == 1 ? 1 : static_cast<std::size_t>(sources) + 1;
  CheckMemory(grids * CountGridBytes(grid),
              "the accumulator's " +
                  (grids > 1 ? std::to_string(grids) + " count grids" : "count grid") + " of " +
                  CountGridName(grid) + " (the parameter cells)");
  std::vector<SharedContractors> by_source(sources);
  for (std::size_t i = 0; i < view.measurements.size(); ++i)
    by_source[view.sources.empty() ? 0 : view.sources[i]].push_back(view.measurements[i]);
  std::vector<cv::Mat> out;
  *stopped = false;
  try {
    cv::Mat sum;
    if (sources > 1) sum = cv::Mat(grid.rows(), grid.cols(), CV_32S, cv::Scalar(0));
    for (const SharedContractors& ms : by_source) {
      bool s = false;
      out.push_back(Accumulate(grid, ms, stop, work, &s));
      *stopped = *stopped || s;
      if (sources > 1) sum += out.back();
    }
    out.push_back(sources > 1 ? sum : out.back());
  } catch (const cv::Exception& e) {
    // OpenCV's own "Insufficient memory": the harness's out-of-memory reason.
    if (e.code == cv::Error::StsNoMem) throw std::bad_alloc();
    throw;
  }
  return out;
}

namespace {

class AccumulatorEstimator : public RelaxedEstimator {
 public:
  explicit AccumulatorEstimator(const AccumulatorParams& p) : RelaxedEstimator(p.relaxed), p_(p) {}

 protected:
  RelaxedSolution Solve(const Box& prior, const MeasurementSetView& view, const StateSpace& space,
                        int least_q, const StopCondition& stop) override {
    RelaxedSolution out;
    const Grid grid = AccumulatorGrid(prior, view.prior, space, p_.cells);
    bool stopped = false;
    std::vector<cv::Mat> counts = SourceAccumulators(grid, view, stop, &out.summary.work, &stopped);
    if (stopped) {
      out.summary.status = ContractStatus::kStopped;
      out.summary.message =
          "time limit reached: the cells not yet examined count every measurement pending there";
    }
    const int m = static_cast<int>(view.measurements.size());
    double max_count = 0;
    cv::minMaxLoc(counts.back(), nullptr, &max_count);
    // The cells counting m - q' are non-empty exactly when q' >= m - max.
    out.q = ChooseQ(least_q, params().auto_q, m,
                    [&](int q) { return m - q <= static_cast<int>(max_count); });
    if (counts.size() > 2)
      for (std::size_t s = 0; s + 1 < counts.size(); ++s) {
        double source_max = 0;
        cv::minMaxLoc(counts[s], nullptr, &source_max);
        out.properties.push_back({"max_count_source_" + std::to_string(s),
                                  static_cast<std::int64_t>(source_max)});
      }
    out.estimate = std::make_unique<AccumulatorEstimate>(counts.back(), grid.search(), grid.x(),
                                                         grid.y(), std::max(0, m - out.q));
    return out;
  }

 private:
  AccumulatorParams p_;
};

}  // namespace

std::unique_ptr<Estimator> MakeAccumulator(const ParamMap& params, std::uint64_t) {
  return std::make_unique<AccumulatorEstimator>(ParseParams<AccumulatorParams>("accumulator", params));
}

}  // namespace icp
