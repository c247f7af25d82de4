// Per-run metrics from per-step records (DESIGN.md "Metrics").
#ifndef ICPBENCH_HARNESS_METRICS_H_
#define ICPBENCH_HARNESS_METRICS_H_

#include <cstdint>
#include <vector>

#include "harness/run_record.h"

namespace icp {

// Aggregates steps: mean area, consistency rate, centre RMSE, corridors, and
// mean/median/p90 solve time with a bootstrap 95% interval of the mean
// (resamples drawn with a generator seeded by bootstrap_seed, so reports are
// reproducible).
RunMetrics ComputeMetrics(const std::vector<StepRecord>& steps, std::uint64_t bootstrap_seed = 1);

// The p-quantile (0 <= p <= 1) of values by linear interpolation between
// order statistics; NaN for no values.
double Quantile(std::vector<double> values, double p);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_METRICS_H_
