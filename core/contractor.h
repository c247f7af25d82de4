// The Contractor interface: the unit every algorithm is built from (DESIGN.md).
// Contract(box, context) shrinks box in place and never removes a point that
// satisfies the constraints it stands for. An empty result is a value
// (kEmpty), a timeout is a result (kStopped), never an exception.
#ifndef ICPBENCH_CORE_CONTRACTOR_H_
#define ICPBENCH_CORE_CONTRACTOR_H_

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/box.h"

namespace icp {

enum class ContractStatus {
  kContracted,  // the box shrank
  kFixpoint,    // nothing could be removed
  kEmpty,       // no solution in the box; the box is empty
  kStopped,     // the stop condition fired; the box is sound but maybe not at a fixpoint
};
std::string_view ToString(ContractStatus status);

// Work done by a contraction, for comparisons that do not depend on the clock.
struct WorkCounters {
  std::int64_t revise_calls = 0;   // HC4Revise / primitive projections
  std::int64_t newton_steps = 0;   // univariate interval Newton steps (BC3, BC4)
  std::int64_t bisections = 0;     // bisections while shaving bounds
  std::int64_t inner_calls = 0;    // calls of an inner contractor (3B)
  WorkCounters& operator+=(const WorkCounters& o);
};

struct ContractSummary {
  ContractStatus status = ContractStatus::kFixpoint;
  std::string message;
  WorkCounters work;
};

// When to give up: a wall-clock deadline and/or a cancellation flag.
class StopCondition {
 public:
  using Clock = std::chrono::steady_clock;
  StopCondition() = default;
  static StopCondition After(std::chrono::duration<double> budget);
  StopCondition& WithCancelFlag(const std::atomic<bool>* flag) {
    cancel_ = flag;
    return *this;
  }
  bool ShouldStop() const;

 private:
  Clock::time_point deadline_ = Clock::time_point::max();
  const std::atomic<bool>* cancel_ = nullptr;
};

// What a contraction is told beside the box, in one argument so that every
// contractor, and every wrapper of one (3B), has the same entry point (STYLE.md
// §1, §7.3): when to give up, and which variables changed since the box was
// last at a fixpoint of the contractor. A contractor may treat more variables
// as changed than it is told (that is always sound); told fewer, it may stop
// short of its fixpoint.
class ContractContext {
 public:
  // A fresh box: every variable counts as changed.
  explicit ContractContext(const StopCondition& stop = StopCondition()) : stop_(stop) {}

  const StopCondition& stop() const { return stop_; }
  // True when every variable counts as changed; then changed() is meaningless.
  bool all_changed() const { return all_changed_; }
  // The changed variables, as indices into the box, when !all_changed(). An
  // empty list says the box is at a fixpoint already.
  const std::vector<int>& changed() const { return changed_; }

  // Says that only vars changed since the last fixpoint (3B, after moving a
  // bound of a box its inner contractor had contracted).
  void SetChanged(std::span<const int> vars) {
    all_changed_ = false;
    changed_.assign(vars.begin(), vars.end());
  }

 private:
  StopCondition stop_;
  bool all_changed_ = true;
  std::vector<int> changed_;
};

class Contractor {
 public:
  virtual ~Contractor() = default;
  virtual std::string_view Name() const = 0;
  // The one entry point (STYLE.md §7.3): whatever a contraction needs to know
  // beside the box travels in context.
  virtual ContractSummary Contract(Box& box, ContractContext& context) = 0;
};

// Summary status for a contraction from before to after.
ContractStatus StatusOf(const Box& before, const Box& after);

// True when some component of after is narrower than in before by more than
// ratio times its width (or became bounded).
inline bool ShrankByMoreThan(const Interval& before, const Interval& after, double ratio) {
  if (after.IsEmpty()) return !before.IsEmpty();
  const auto [wb, wa] = Widths(before, after);
  if (wb == kInf) return wa < kInf;
  return wb - wa > ratio * wb;
}

}  // namespace icp

#endif  // ICPBENCH_CORE_CONTRACTOR_H_
