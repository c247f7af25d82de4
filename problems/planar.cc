#include "problems/planar.h"

#include <stdexcept>
#include <utility>

#include "core/constraint_contractor.h"

namespace icp {

StateSpace PlanarStateSpace() {
  StateSpace space;
  space.names = {"x", "y"};
  space.x = 0;
  space.y = 1;
  return space;
}

Step MakePlanarStep(int time, const ConstraintSystem& csp, std::vector<double> truth,
                    std::vector<bool> outliers, std::vector<int> sources) {
  if (csp.num_variables() != 2 || truth.size() != 2)
    throw std::invalid_argument("MakePlanarStep: the state must be (x, y)");
  Step step;
  step.views.step = time;
  step.views.space = PlanarStateSpace();
  MeasurementSetView set;
  set.prior = csp.domains();
  set.measurements = ConstraintContractors(csp);
  set.outliers = std::move(outliers);
  set.sources = std::move(sources);
  step.views.measurement_set = std::move(set);
  CspView view;
  view.csp = csp;
  view.states = {{time, 0}, {time, 1}};
  view.newest = time;
  step.views.csp = std::move(view);
  step.csp_truth = truth;
  step.truth = std::move(truth);
  return step;
}

// A partial Fisher-Yates shuffle, through core/random.h (portable seeds).
std::vector<bool> DrawOutliers(int n, int k, RandomEngine& rng) {
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::vector<bool> flags(n, false);
  for (int i = 0; i < k; ++i) {
    const int j = static_cast<int>(UniformInt(rng, i, n - 1));
    std::swap(order[i], order[j]);
    flags[order[i]] = true;
  }
  return flags;
}

}  // namespace icp
