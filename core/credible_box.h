// Credible boxes of a weighted sample (a particle filter's cloud): the box
// that stands for a probabilistic estimate at a level, so that its coverage
// of the truth can be measured (harness/coverage.h) like a set's
// containment.
#ifndef ICPBENCH_CORE_CREDIBLE_BOX_H_
#define ICPBENCH_CORE_CREDIBLE_BOX_H_

#include <vector>

#include <opencv2/core.hpp>

#include "core/box.h"

namespace icp {

// The q-quantile of values under weights (non-negative, positive sum): the
// least value v such that the weight of the values <= v exceeds q times the
// total (for q < 1; the greatest value with positive weight for q >= 1).
double WeightedQuantile(const std::vector<double>& values, const std::vector<double>& weights,
                        double q);

// The weight left out on each side of one component of the level box of d
// components: (1 - level^(1/d)) / 2 (Šidák), so that each component's
// central interval holds level^(1/d) of the weight and, were the components
// independent, the box would hold exactly `level`. level in (0, 1).
double CredibleTail(double level, int d);

// The credible box at `level` of a weighted cloud (one CV_64F row per
// particle, one column per component; weights non-negative with a positive
// sum, one per row): per component, the weighted quantiles tail and 1 - tail
// (CredibleTail). Linear time in the particles (a selection of the few in
// each tail, not a sort). Not a guaranteed enclosure: a sample's region.
// Throws std::invalid_argument on a size mismatch, no positive weight or a
// level outside (0, 1).
Box CredibleBox(const cv::Mat& cloud, const std::vector<double>& weights, double level);

}  // namespace icp

#endif  // ICPBENCH_CORE_CREDIBLE_BOX_H_
