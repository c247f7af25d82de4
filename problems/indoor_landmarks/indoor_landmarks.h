// The indoor-landmarks problem (paper 002): a robot at the end of a corridor
// localized from wheel odometry and typed range-and-bearing returns against
// a map of typed landmarks (the drive: indoor_drive.h; the map:
// indoor_map.h). The state is the pose (x, y, theta), theta unwrapped.
//
// Views of step k:
//   - landmark observations: the map, the odometry from step k - 1, the
//     typed polar returns; associating them is the estimator's job;
//   - measurement set: one measurement per return, "it comes from some
//     landmark of its type" (the union over those landmarks of eq. 10-11,
//     core/polar_sighting.h), an outlier when no landmark of its type
//     explains it at the true pose (a spurious return, as a rule); prior:
//     the start box at step 0, later the map's bounds with any heading
//     (theta in [-3 pi, 3 pi]);
//     predict: eq. 5-7, its heading moved by a multiple of 2 pi into the
//     prior's frame (headings in [-3 pi, 3 pi], so that any heading interval
//     narrower than 2 pi fits in it);
//   - probabilistic: motion drawn within the odometry's intervals (wheel
//     radii, track, rotations), likelihood per return the best landmark of
//     its type (Gaussian in range and bearing with sigma the error bound)
//     mixed with a 5 % floor for spurious returns.
// The true identity of every return is kept for scoring
// (Step::observation_truth), never shown to an estimator.
#ifndef ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_LANDMARKS_H_
#define ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_LANDMARKS_H_

#include <cstdint>
#include <memory>
#include <string>

#include "core/params.h"
#include "problems/indoor_landmarks/indoor_drive.h"
#include "problems/problem.h"

namespace icp {

// Also checks the map file.
ParamMap ResolveIndoorLandmarks(const std::string& owner, const ParamMap& values);
std::unique_ptr<Problem> MakeIndoorLandmarks(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_LANDMARKS_H_
