// A problem is a seeded stream of CSPs (DESIGN.md): localization problems
// yield one CSP per time step over a sliding window, static problems one.
// Each step carries the ground truth when it is known, so the harness and
// the tests can check that an algorithm never loses it.
#ifndef ICPBENCH_PROBLEMS_PROBLEM_H_
#define ICPBENCH_PROBLEMS_PROBLEM_H_

#include <string_view>
#include <vector>

#include "core/box.h"
#include "core/constraint_system.h"

namespace icp {

struct Step {
  int index = 0;
  ConstraintSystem csp;        // its domains are the step's initial box
  std::vector<double> truth;   // one value per variable; empty when unknown
};

class Problem {
 public:
  virtual ~Problem() = default;
  virtual std::string_view Name() const = 0;
  // Fills step with the next CSP and returns true, or returns false when the
  // stream is over. previous_result is the contracted box of the previous
  // step (null for the first), for problems that carry state across steps.
  virtual bool Next(const Box* previous_result, Step* step) = 0;
};

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_PROBLEM_H_
