// Test helpers for problems that offer a measurement-set view: how a
// measurement's contractor treats the truth.
#ifndef ICPBENCH_PROBLEMS_MEASUREMENT_CHECKS_H_
#define ICPBENCH_PROBLEMS_MEASUREMENT_CHECKS_H_

#include <string>
#include <vector>

#include "core/box.h"
#include "core/contractor.h"
#include "problems/problem.h"

namespace icp {

// The box [p - radius, p + radius] around a point.
inline Box BoxAround(const std::vector<double>& p, double radius) {
  Box box;
  for (double v : p) box.push_back(Interval(v - radius, v + radius));
  return box;
}

// True when contracting a tiny box around truth leaves a box that still
// holds the truth: the measurement is consistent with it.
inline bool KeepsTruth(Contractor& contractor, const std::vector<double>& truth) {
  Box box = BoxAround(truth, 1e-9);
  ContractContext context;
  contractor.Contract(box, context);
  return !box.IsEmpty() && box.Contains(truth);
}

// True when contracting the degenerate box [truth, truth] empties it: the
// measurement contradicts the truth.
inline bool RejectsTruth(Contractor& contractor, const std::vector<double>& truth) {
  Box box = BoxAround(truth, 0);
  ContractContext context;
  contractor.Contract(box, context);
  return box.IsEmpty();
}

// The constraints of a step's CSP view in Minibex syntax, to compare
// instances.
inline std::vector<std::string> Constraints(const Step& step) {
  std::vector<std::string> out;
  const ConstraintSystem& csp = step.views.csp->csp;
  for (int c = 0; c < static_cast<int>(csp.constraints().size()); ++c)
    out.push_back(csp.ConstraintToString(c));
  return out;
}

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_MEASUREMENT_CHECKS_H_
