// Paper 002's estimators on a landmark-observation view (core/view.h):
//   landmark-tracking  multi-target tracking of typed landmarks (§3.2-3.6).
//     Each step: the pose box predicted by the odometry (eq. 5-7, as
//     constraints over the previous and the new pose); then each track is
//     followed (§3.5): the world boxes of the returns of its type (eq. 8-9)
//     are matched with the track's box by `association`; a match adds eq.
//     10-11 for the return and the track's landmark and propagates them by
//     the `inner` contractor, and is cancelled when that empties the box;
//     then every return left starts a track (§3.4): the map landmarks of
//     its type inside its world box are tried in map order, the first whose
//     constraints leave the box non-empty is taken, none: an outlier.
//     association = belief: overlap masses (Fig. 6), Royère fusion, the
//     largest pignistic probability, "no match" an outcome
//     (belief_association.h); first: the first return of the track's type
//     whose box meets the track's and whose constraints leave the box
//     non-empty. A track unmatched for more than track_timeout steps is
//     dropped (the paper's "definitive disappearance"). Should the pose box
//     ever empty (every match kept it non-empty, so only through rounding),
//     the estimator restarts from the view's prior.
//   dead-reckoning  the odometry alone (eq. 5-7; Fig. 9); it associates
//     nothing (no associations reported).
// Both cut the predicted x and y to the view's prior (the map's bounds).
// Both estimate the pose box (x, y, theta). Sound when every association is
// right: each constraint then holds at the true pose; a wrong association
// may lose the truth, which the harness counts (associations_wrong).
#ifndef ICPBENCH_ALGORITHMS_LANDMARK_TRACKING_LANDMARK_TRACKING_H_
#define ICPBENCH_ALGORITHMS_LANDMARK_TRACKING_LANDMARK_TRACKING_H_

#include <cstdint>
#include <memory>
#include <string>

#include "algorithms/estimator.h"
#include "core/params.h"

namespace icp {

struct LandmarkTrackingParams {
  // The CSP contractor that propagates a match: hc3 as in the paper, or
  // hc4, bc4, ...
  std::string inner = "hc3";
  // How a track picks its return: belief (paper 002 §3.5) or first.
  std::string association = "belief";
  // Steps a track survives without a match (a landmark hidden for a while).
  int track_timeout = 3;
};
void Describe(LandmarkTrackingParams& p, ParamSet& set);
ParamMap ResolveLandmarkTracking(const std::string& owner, const ParamMap& values);
std::unique_ptr<Estimator> MakeLandmarkTracking(const ParamMap& params, std::uint64_t seed);

struct DeadReckoningParams {};
void Describe(DeadReckoningParams& p, ParamSet& set);
std::unique_ptr<Estimator> MakeDeadReckoning(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_LANDMARK_TRACKING_LANDMARK_TRACKING_H_
