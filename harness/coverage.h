// The coverage of a run's credible regions: the share of its steps whose
// truth lies in the region of each level (the step properties covered_50,
// covered_90, covered_95 of CoverageProperties, harness/metrics.h), as the
// run properties coverage_50, coverage_90, coverage_95. A calibrated
// probabilistic estimator's level-x region holds the truth on about x of
// the steps.
#ifndef ICPBENCH_HARNESS_COVERAGE_H_
#define ICPBENCH_HARNESS_COVERAGE_H_

#include <cstdint>

#include "core/estimate.h"
#include "harness/metrics.h"
#include "problems/problem.h"

namespace icp {

class CoverageCounter {
 public:
  // Appends the step's covered_<level> properties to properties and counts them.
  void Add(const Step& step, const Estimate& estimate, Properties* properties);
  // Appends coverage_<level> (the share of the steps judged) to properties;
  // nothing when no step was judged.
  void AppendRunProperties(Properties* properties) const;

 private:
  std::int64_t judged_ = 0;
  std::int64_t covered_[std::size(kCoverageLevels)] = {};
};

}  // namespace icp

#endif  // ICPBENCH_HARNESS_COVERAGE_H_
