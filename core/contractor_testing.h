// Test helpers for contractors: the minimal contractor of a fixed box, one
// that cancels the stop condition after some calls, and how many of some
// contractors keep a point.
#ifndef ICPBENCH_CORE_CONTRACTOR_TESTING_H_
#define ICPBENCH_CORE_CONTRACTOR_TESTING_H_

#include <atomic>
#include <memory>
#include <string_view>
#include <vector>

#include "core/contractor.h"

namespace icp::testing {

// Intersects the box with a fixed box: one revise call each time.
class ClipTo : public Contractor {
 public:
  explicit ClipTo(Box set) : set_(std::move(set)) {}
  std::string_view Name() const override { return "clip"; }
  ContractSummary Contract(Box& box, ContractContext&) override {
    const Box before = box;
    for (std::size_t d = 0; d < box.size(); ++d) box[d] = Intersect(box[d], set_[d]);
    if (box.IsEmpty()) box.SetEmpty();
    ContractSummary s;
    s.status = StatusOf(before, box);
    s.work.revise_calls = 1;
    return s;
  }

 private:
  Box set_;
};

// Another contractor that raises a cancel flag (StopCondition::WithCancelFlag)
// at its n-th contraction, shared by the copies of it: the stop condition
// fires in the middle of whatever calls it, at the same place every time.
class CancelAfter : public Contractor {
 public:
  CancelAfter(std::shared_ptr<Contractor> inner, std::shared_ptr<int> calls_left,
              std::atomic<bool>* flag)
      : inner_(std::move(inner)), calls_left_(std::move(calls_left)), flag_(flag) {}
  std::string_view Name() const override { return "cancel-after"; }
  ContractSummary Contract(Box& box, ContractContext& context) override {
    if (--*calls_left_ <= 0) *flag_ = true;
    return inner_->Contract(box, context);
  }

 private:
  std::shared_ptr<Contractor> inner_;
  std::shared_ptr<int> calls_left_;
  std::atomic<bool>* flag_;
};

// Wraps every contractor of cs so that the flag rises at the n-th
// contraction among them all.
inline std::vector<std::shared_ptr<Contractor>> CancelAfterCalls(
    const std::vector<std::shared_ptr<Contractor>>& cs, int n, std::atomic<bool>* flag) {
  auto left = std::make_shared<int>(n);
  std::vector<std::shared_ptr<Contractor>> out;
  for (const auto& c : cs) out.push_back(std::make_shared<CancelAfter>(c, left, flag));
  return out;
}

// How many of the contractors keep the degenerate box at point.
inline int KeptBy(const std::vector<std::shared_ptr<Contractor>>& contractors,
                  const std::vector<double>& point) {
  int n = 0;
  for (const auto& c : contractors) {
    Box box(point.size());
    for (std::size_t d = 0; d < point.size(); ++d) box[d] = Interval(point[d]);
    ContractContext context;
    c->Contract(box, context);
    n += box.IsEmpty() ? 0 : 1;
  }
  return n;
}

}  // namespace icp::testing

#endif  // ICPBENCH_CORE_CONTRACTOR_TESTING_H_
