// A problem is a seeded stream of CSPs (DESIGN.md): localization problems
// yield one CSP per time step over a sliding window, static problems one.
// Each step carries the ground truth when it is known, so the harness and
// the tests can check that an algorithm never loses it.
#ifndef ICPBENCH_PROBLEMS_PROBLEM_H_
#define ICPBENCH_PROBLEMS_PROBLEM_H_

#include <string>
#include <string_view>
#include <vector>

#include "core/box.h"
#include "core/constraint_system.h"
#include "core/view.h"

namespace icp {

// A variable reported per step (the newest state of a localization window).
struct ReportedVariable {
  std::string name;  // display name: "x", "y", "theta", or the CSP's own
  int index;         // index in the step's CSP
};

struct Step {
  int index = 0;
  ConstraintSystem csp;        // its domains are the step's initial box
  std::vector<double> truth;   // one value per CSP variable; empty when unknown
  // The variables whose bounds and truth the harness records; empty means
  // every variable of the CSP.
  std::vector<ReportedVariable> reported;
  // Positions in `reported` of the planar position (for the x-y area and the
  // centre error), -1 when the problem has none.
  int x = -1;
  int y = -1;
};

class Problem {
 public:
  virtual ~Problem() = default;
  virtual std::string_view Name() const = 0;
  // Fills step with the next CSP and returns true, or returns false when the
  // stream is over. previous_result is the contracted box of the previous
  // step (null for the first), for problems that carry state across steps;
  // an empty previous_result means the algorithm lost the track.
  virtual bool Next(const Box* previous_result, Step* step) = 0;
  // Number of steps the stream will yield, for progress reports.
  virtual int NumSteps() const = 0;
};

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_PROBLEM_H_
