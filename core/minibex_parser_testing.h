// What the Minibex parser's tests share: evaluating a parsed constraint.
#ifndef ICPBENCH_CORE_MINIBEX_PARSER_TESTING_H_
#define ICPBENCH_CORE_MINIBEX_PARSER_TESTING_H_

#include <vector>

#include "core/constraint_system.h"
#include "core/tape.h"

namespace icp::testing {

// Enclosure of constraint c's function at box.
inline Interval Eval(const ConstraintSystem& csp, int c, const Box& box) {
  std::vector<Interval> slots;
  return Tape(csp.graph(), csp.constraints()[c]).Forward(box, slots);
}

inline Box PointBox(const std::vector<double>& point) {
  Box box;
  for (double v : point) box.push_back(Interval(v));
  return box;
}

}  // namespace icp::testing

#endif  // ICPBENCH_CORE_MINIBEX_PARSER_TESTING_H_
