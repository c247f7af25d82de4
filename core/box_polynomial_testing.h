// The expanded sort transform by its definition (paper 003 eq. 5.7, and
// eq. 4.37's relaxed composition): coefficient j is the hull over the
// subsets of j contractors of their composition, in index order, applied to
// x. 2^n compositions: what HornerSortTransform avoids; a reference for
// tests and benchmarks.
#ifndef ICPBENCH_CORE_BOX_POLYNOMIAL_TESTING_H_
#define ICPBENCH_CORE_BOX_POLYNOMIAL_TESTING_H_

#include <vector>

#include "core/contractor_algebra.h"

namespace icp::testing {

inline std::vector<Box> ExpandedSortTransform(const Box& x, const SharedContractors& cs) {
  const int n = static_cast<int>(cs.size());
  std::vector<Box> out(n + 1, Box(x.size()));
  for (Box& b : out) b.SetEmpty();
  for (std::uint32_t mask = 0; mask < (1u << n); ++mask) {
    Box box = x;
    for (int i = 0; i < n && !box.IsEmpty(); ++i)
      if (mask & (1u << i)) {
        ContractContext context;
        if (cs[i]->Contract(box, context).status == ContractStatus::kEmpty) box.SetEmpty();
      }
    Box& coefficient = out[__builtin_popcount(mask)];
    coefficient = Hull(coefficient, box);
  }
  return out;
}

}  // namespace icp::testing

#endif  // ICPBENCH_CORE_BOX_POLYNOMIAL_TESTING_H_
