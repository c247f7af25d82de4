// Paving by branch and contract (SIVIA, Jaulin et al. 2001; paper 003 §3.7):
// the box is contracted, and what remains is bisected along its widest
// component until every piece is narrower than epsilon. With the repeated
// q-intersection of measurement contractors as the contractor, this is the
// relaxed set inversion (RSIVIA, Jaulin 2009) of the q-relaxed solvers.
//
// Every piece is a boundary box (the contractor cannot prove a box inside the
// set): the union of the pieces encloses every point the contractor keeps.
#ifndef ICPBENCH_CORE_PAVING_H_
#define ICPBENCH_CORE_PAVING_H_

#include <cstdint>
#include <vector>

#include "core/contractor.h"

namespace icp {

struct PavingResult {
  std::vector<Box> boxes;
  std::int64_t bisections = 0;
  WorkCounters work;
  // The stop condition fired or max_boxes was reached: the boxes still to
  // process were kept unpaved (sound, coarser).
  bool truncated = false;
  // Truncated by the stop condition or a contraction that stopped short
  // (kStopped), not by max_boxes.
  bool stopped = false;
};

// Throws std::invalid_argument unless epsilon > 0 and max_boxes >= 1.
PavingResult Pave(const Box& x, Contractor& contractor, double epsilon, std::int64_t max_boxes,
                  const StopCondition& stop);

}  // namespace icp

#endif  // ICPBENCH_CORE_PAVING_H_
