#include "core/paving.h"

#include <cmath>
#include <stdexcept>

namespace icp {

namespace {
// A split point strictly inside a non-degenerate interval, finite even when
// a bound is infinite.
double SplitPoint(const Interval& x) {
  const double lo = x.lo(), hi = x.hi();
  if (std::isinf(lo) && std::isinf(hi)) return 0;
  if (std::isinf(lo)) return hi - std::max(1.0, std::abs(hi));
  if (std::isinf(hi)) return lo + std::max(1.0, std::abs(lo));
  return lo + (hi - lo) / 2;
}
}  // namespace

PavingResult Pave(const Box& x, Contractor& contractor, double epsilon, std::int64_t max_boxes,
                  const StopCondition& stop) {
  if (!(epsilon > 0)) throw std::invalid_argument("paving: epsilon must be > 0");
  if (max_boxes < 1) throw std::invalid_argument("paving: max_boxes must be >= 1");
  PavingResult result;
  std::vector<Box> stack = {x};
  while (!stack.empty()) {
    Box box = std::move(stack.back());
    stack.pop_back();
    if (result.truncated) {
      result.boxes.push_back(std::move(box));
      continue;
    }
    ContractContext context(stop);
    const ContractSummary s = contractor.Contract(box, context);
    result.work += s.work;
    if (s.status == ContractStatus::kEmpty || box.IsEmpty()) continue;
    std::size_t widest = 0;
    for (std::size_t d = 1; d < box.size(); ++d)
      if (box[d].Width() > box[widest].Width()) widest = d;
    const double split = SplitPoint(box[widest]);
    const bool splittable = box[widest].lo() < split && split < box[widest].hi();
    if (!(box[widest].Width() >= epsilon) || !splittable) {
      result.boxes.push_back(std::move(box));
      continue;
    }
    const bool stopped = s.status == ContractStatus::kStopped || stop.ShouldStop();
    if (stopped || static_cast<std::int64_t>(result.boxes.size() + stack.size()) + 2 > max_boxes) {
      result.truncated = true;
      result.stopped = stopped;
      result.boxes.push_back(std::move(box));
      continue;
    }
    Box upper = box;
    box[widest] = Interval(box[widest].lo(), split);
    upper[widest] = Interval(split, upper[widest].hi());
    ++result.bisections;
    stack.push_back(std::move(upper));
    stack.push_back(std::move(box));
  }
  return result;
}

}  // namespace icp
