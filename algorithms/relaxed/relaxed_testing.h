// Test fixtures for the relaxed solvers: m random lines of the plane with
// interval offsets, the first m - outliers through a known point.
#ifndef ICPBENCH_ALGORITHMS_RELAXED_RELAXED_TESTING_H_
#define ICPBENCH_ALGORITHMS_RELAXED_RELAXED_TESTING_H_

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/constraint_contractor.h"
#include "core/random.h"
#include "core/view.h"

namespace icp::testing {

struct LinesCase {
  Views views;
  std::vector<double> truth;
  int outliers = 0;
};

// The measurement-set view of a CSP over (x, y): one contractor per
// constraint, the domains as the prior, which measurements are outliers.
inline Views PlaneMeasurementViews(const ConstraintSystem& csp, std::vector<bool> outliers) {
  Views views;
  MeasurementSetView view;
  view.prior = csp.domains();
  view.measurements = ConstraintContractors(csp);
  view.outliers = std::move(outliers);
  views.space.names = {"x", "y"};
  views.space.x = 0;
  views.space.y = 1;
  views.measurement_set = std::move(view);
  return views;
}

// Lines cos(a) x + sin(a) y in [c - 0.05, c + 0.05] over [-10, 10]^2; an
// outlier's offset is moved 1 to 5 away from the truth's.
inline LinesCase Lines(std::uint64_t seed, int m, int outliers) {
  RandomEngine rng(seed);
  LinesCase out;
  out.truth = {UniformReal(rng, -5, 5), UniformReal(rng, -5, 5)};
  out.outliers = outliers;
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-10, 10}), y = csp.AddVariable("y", {-10, 10});
  std::vector<bool> is_outlier;
  for (int i = 0; i < m; ++i) {
    const double a = UniformReal(rng, 0, M_PI);
    double c = std::cos(a) * out.truth[0] + std::sin(a) * out.truth[1] + UniformReal(rng, -0.02, 0.02);
    const bool outlier = i >= m - outliers;
    if (outlier) c += (UniformInt(rng, 0, 1) ? 1 : -1) * UniformReal(rng, 1, 5);
    csp.AddConstraint(std::cos(a) * x + std::sin(a) * y, Interval(c - 0.05, c + 0.05));
    is_outlier.push_back(outlier);
  }
  out.views = PlaneMeasurementViews(csp, std::move(is_outlier));
  return out;
}

}  // namespace icp::testing

#endif  // ICPBENCH_ALGORITHMS_RELAXED_RELAXED_TESTING_H_
