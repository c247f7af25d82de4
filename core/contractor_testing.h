// Test helpers for contractors: the minimal contractor of a fixed box, and
// how many of some contractors keep a point.
#ifndef ICPBENCH_CORE_CONTRACTOR_TESTING_H_
#define ICPBENCH_CORE_CONTRACTOR_TESTING_H_

#include <memory>
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
