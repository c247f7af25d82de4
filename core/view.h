// What an algorithm consumes of a problem (DESIGN.md "A problem offers
// views"): ICP algorithms need the CSP view; relaxed solvers the
// measurement-set view (one contractor per measurement); the particle filter
// the probabilistic view (motion model and likelihood). The harness pairs
// algorithms with problems by view and records other pairs as skipped.
#ifndef ICPBENCH_CORE_VIEW_H_
#define ICPBENCH_CORE_VIEW_H_

#include <string_view>

namespace icp {

enum class View { kCsp, kMeasurementSet, kProbabilistic };

inline std::string_view ToString(View view) {
  switch (view) {
    case View::kCsp: return "csp";
    case View::kMeasurementSet: return "measurement-set";
    case View::kProbabilistic: return "probabilistic";
  }
  return "?";
}

}  // namespace icp

#endif  // ICPBENCH_CORE_VIEW_H_
