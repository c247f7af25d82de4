// Shared by the static and moving planar problems (line-intersection,
// beacon-ranges): one step whose state is a position (x, y), measured by one
// constraint per measurement of a ConstraintSystem over x, y. The step
// offers the measurement-set view (one contractor per constraint) and the
// CSP view (all constraints at once, for ICP: empty as soon as one outlier
// contradicts the others).
#ifndef ICPBENCH_PROBLEMS_PLANAR_H_
#define ICPBENCH_PROBLEMS_PLANAR_H_

#include <vector>

#include "core/constraint_system.h"
#include "core/random.h"
#include "problems/problem.h"

namespace icp {

// The state space {"x", "y"} with x = 0, y = 1.
StateSpace PlanarStateSpace();

// A step at time `time` from csp, whose variables are x then y with the
// search box as domains, and whose constraint i is measurement i. truth is
// the true (x, y); outliers and sources as in MeasurementSetView (one per
// constraint, or empty). predict is left unset.
Step MakePlanarStep(int time, const ConstraintSystem& csp, std::vector<double> truth,
                    std::vector<bool> outliers, std::vector<int> sources);

// Which of n measurements are outliers: k distinct ones, drawn uniformly.
std::vector<bool> DrawOutliers(int n, int k, RandomEngine& rng);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_PLANAR_H_
