// Random CSPs built around a random point p that satisfies them: each
// constraint is f(x) in F(p), where f is a random expression and F(p) its
// interval evaluation on the point box p (an enclosure of the exact f(p)).
// A sound contractor never removes p. Shared by the soundness suites.
#ifndef ICPBENCH_TESTS_RANDOM_CSP_H_
#define ICPBENCH_TESTS_RANDOM_CSP_H_

#include <cstdint>
#include <vector>

#include "core/constraint_system.h"

namespace icp::testing {

struct RandomCsp {
  ConstraintSystem csp;
  std::vector<double> point;  // satisfies every constraint
};

struct RandomCspOptions {
  int min_variables = 2;
  int max_variables = 6;
  int min_constraints = 1;
  int max_constraints = 6;
  int max_depth = 4;
  double domain_half_width = 3.0;  // largest distance of a bound from p
  // Division and min: operations whose natural extension is not the exact
  // range even with single occurrences (a divisor interval holding 0).
  bool discontinuous_ops = true;
};

RandomCsp MakeRandomCsp(std::uint64_t seed, const RandomCspOptions& options = {});

}  // namespace icp::testing

#endif  // ICPBENCH_TESTS_RANDOM_CSP_H_
