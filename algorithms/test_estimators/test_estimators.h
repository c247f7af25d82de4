// Test-only estimators, one per kind of estimate that is not a box, so the
// harness's run loop, store, reports and figures are exercised with every
// kind before the real ones (relaxed solvers, particle filter) exist. Each
// contracts the CSP view with HC4 (carry=first) and turns the newest state's
// box into its kind:
//   test-paving       the box split into `splits` x `splits` boundary boxes
//                     over x and y (so it encloses what the box encloses);
//   test-accumulator  a `cells` x `cells` grid over the box widened by half
//                     its width on each side (within the step's domains):
//                     cells meeting the box count 2, the others 1, threshold 2;
//   test-particles    `particles` points drawn uniformly in the box (seeded),
//                     equal weights.
#ifndef ICPBENCH_ALGORITHMS_TEST_ESTIMATORS_TEST_ESTIMATORS_H_
#define ICPBENCH_ALGORITHMS_TEST_ESTIMATORS_TEST_ESTIMATORS_H_

#include <cstdint>
#include <memory>

#include "algorithms/estimator.h"
#include "core/params.h"

namespace icp {

struct TestPavingParams {
  int splits = 3;
};
void Describe(TestPavingParams& p, ParamSet& set);
std::unique_ptr<Estimator> MakeTestPaving(const ParamMap& params, std::uint64_t seed);

struct TestAccumulatorParams {
  int cells = 16;
};
void Describe(TestAccumulatorParams& p, ParamSet& set);
std::unique_ptr<Estimator> MakeTestAccumulator(const ParamMap& params, std::uint64_t seed);

struct TestParticlesParams {
  int particles = 200;
};
void Describe(TestParticlesParams& p, ParamSet& set);
std::unique_ptr<Estimator> MakeTestParticles(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_TEST_ESTIMATORS_TEST_ESTIMATORS_H_
