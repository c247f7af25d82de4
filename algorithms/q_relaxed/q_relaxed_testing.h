// The reference of q-relaxed's contract mode, written plainly: what IBEX's
// CtcFixPoint(CtcQInter(one HC4 contractor per measurement, m - q), ratio)
// computes. Each round contracts a copy of the box with every measurement,
// takes the brute-force q-relaxed intersection of the results
// (core/relaxed_intersection_testing.h) and repeats until no component
// shrinks by more than ratio of its width (the stop rule of q-relaxed's
// FixpointContractor), the box is empty, or max_iterations rounds ran.
// `intersect` replaces the q-relaxed intersection of boxes (a test shows
// that the thesis' per-dimension one gives wider fixpoints).
#ifndef ICPBENCH_ALGORITHMS_Q_RELAXED_Q_RELAXED_TESTING_H_
#define ICPBENCH_ALGORITHMS_Q_RELAXED_Q_RELAXED_TESTING_H_

#include <functional>
#include <span>
#include <vector>

#include "core/contractor_algebra.h"
#include "core/relaxed_intersection_testing.h"

namespace icp::testing {

using BoxesIntersection = std::function<Box(std::span<const Box> boxes, int q, std::size_t n)>;

inline Box ReferenceQRelaxedFixpoint(const Box& prior, const SharedContractors& measurements, int q,
                                     const BoxesIntersection& intersect = ReferenceRelaxedIntersection,
                                     double ratio = 1e-3, int max_iterations = 1000) {
  Box box = prior;
  for (int it = 0; it < max_iterations && !box.IsEmpty(); ++it) {
    std::vector<Box> contracted;
    for (const auto& measurement : measurements) {
      Box b = box;
      ContractContext context;
      if (measurement->Contract(b, context).status == ContractStatus::kEmpty) b.SetEmpty();
      contracted.push_back(b);
    }
    const Box next = Intersect(intersect(contracted, q, box.size()), box);
    bool shrank = false;
    for (std::size_t d = 0; d < box.size(); ++d) shrank = shrank || ShrankByMoreThan(box[d], next[d], ratio);
    box = next;
    if (!shrank) break;
  }
  if (box.IsEmpty()) box.SetEmpty();
  return box;
}

}  // namespace icp::testing

#endif  // ICPBENCH_ALGORITHMS_Q_RELAXED_Q_RELAXED_TESTING_H_
