#include "core/box_polynomial.h"

namespace icp {

std::vector<Box> HornerSortTransform(const Box& x, const SharedContractors& sequence,
                                     const StopCondition& stop, WorkCounters* work,
                                     bool* stopped) {
  if (stopped) *stopped = false;
  Box empty(x.size());
  empty.SetEmpty();
  std::vector<Box> coefficients = {x};
  for (const std::shared_ptr<Contractor>& c : sequence) {
    coefficients.push_back(empty);
    // Highest degree first, so coefficient j - 1 is still [X_k]'s when
    // coefficient j is updated in place.
    for (std::size_t j = coefficients.size() - 1; j >= 1; --j) {
      const Box& lower = coefficients[j - 1];
      if (lower.IsEmpty()) continue;
      Box contracted = lower;
      if (!stop.ShouldStop()) {
        ContractContext context(stop);
        const ContractSummary s = c->Contract(contracted, context);
        if (work) *work += s.work;
        if (s.status == ContractStatus::kEmpty) contracted.SetEmpty();
        if (s.status == ContractStatus::kStopped && stopped) *stopped = true;
      } else if (stopped) {
        *stopped = true;
      }
      coefficients[j] = Hull(coefficients[j], contracted);
    }
  }
  return coefficients;
}

}  // namespace icp
