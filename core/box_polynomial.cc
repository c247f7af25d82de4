#include "core/box_polynomial.h"

#include <algorithm>

namespace icp {

namespace {

// One step of the Horner scheme, contractor c applied to coefficients
// [low, high] of degree j - 1 into those of degree j (highest first, so
// that coefficient j - 1 is still the previous step's when j is updated).
// Past the stop condition a contractor counts as the identity (sound) and
// *fired is set.
void HornerStep(Contractor& c, std::vector<Box>& coefficients, std::size_t low, std::size_t high,
                const StopCondition& stop, WorkCounters* work, bool* stopped, bool* fired) {
  for (std::size_t j = high; j >= std::max<std::size_t>(low, 1); --j) {
    const Box& lower = coefficients[j - 1];
    if (lower.IsEmpty()) continue;
    Box contracted = lower;
    if (!*fired && stop.ShouldStop()) *fired = true;
    if (!*fired) {
      ContractContext context(stop);
      const ContractSummary s = c.Contract(contracted, context);
      if (work) *work += s.work;
      if (s.status == ContractStatus::kEmpty) contracted.SetEmpty();
      if (s.status == ContractStatus::kStopped && stopped) *stopped = true;
    }
    coefficients[j] = Hull(coefficients[j], contracted);
  }
}

}  // namespace

std::vector<Box> HornerSortTransform(const Box& x, const SharedContractors& sequence,
                                     const StopCondition& stop, WorkCounters* work,
                                     bool* stopped) {
  if (stopped) *stopped = false;
  Box empty(x.size());
  empty.SetEmpty();
  std::vector<Box> coefficients = {x};
  bool fired = false;
  std::size_t k = 0;  // contractors applied
  for (; k < sequence.size() && !fired; ++k) {
    coefficients.push_back(empty);
    HornerStep(*sequence[k], coefficients, 1, coefficients.size() - 1, stop, work, stopped, &fired);
  }
  if (fired && stopped) *stopped = true;
  const std::size_t rest = sequence.size() - k;
  if (rest == 0) return coefficients;
  // The stop fired: the rest counts as the identity, under which coefficient
  // j becomes the hull of coefficients j - rest to j. Contraction nests the
  // coefficients (j inside j - 1), so the hull of those from j - rest up
  // encloses it: O(n) instead of the rest of the n^2 / 2 hulls.
  std::vector<Box>& from = coefficients;  // from[i]: the hull of coefficients i and up
  for (std::size_t i = from.size() - 1; i-- > 0;) from[i] = Hull(from[i], from[i + 1]);
  std::vector<Box> out;
  out.reserve(sequence.size() + 1);
  for (std::size_t j = 0; j <= sequence.size(); ++j) out.push_back(from[j >= rest ? j - rest : 0]);
  return out;
}

Box HornerCoefficient(const Box& x, const SharedContractors& sequence, int degree,
                      const StopCondition& stop, WorkCounters* work, bool* stopped) {
  if (stopped) *stopped = false;
  const std::size_t n = sequence.size(), d = static_cast<std::size_t>(std::max(degree, 0));
  if (d > n) {
    Box empty(x.size());
    empty.SetEmpty();
    return empty;
  }
  Box empty(x.size());
  empty.SetEmpty();
  // After k contractors only degrees d - (n - k) to min(k, d) can still
  // reach degree d: the others are never computed.
  std::vector<Box> coefficients(d + 1, empty);
  coefficients[0] = x;
  bool fired = false;
  std::size_t k = 0;
  for (; k < n && !fired; ++k) {
    const std::size_t low = d + k + 1 > n ? d + k + 1 - n : 0, high = std::min(k + 1, d);
    HornerStep(*sequence[k], coefficients, low, high, stop, work, stopped, &fired);
    // Every coefficient that can still reach degree d is empty: so is it.
    bool all_empty = true;
    for (std::size_t j = low; j <= high && all_empty; ++j) all_empty = coefficients[j].IsEmpty();
    if (all_empty) {
      if (fired && stopped) *stopped = true;
      return empty;
    }
  }
  if (fired && stopped) *stopped = true;
  if (k == n) return coefficients[d];
  // Stopped: as in HornerSortTransform, the hull of what can still reach d.
  Box out = empty;
  for (std::size_t j = d + k > n ? d + k - n : 0; j <= std::min(k, d); ++j)
    out = Hull(out, coefficients[j]);
  return out;
}

}  // namespace icp
