// q-relaxed: the repeated q-relaxed intersection of the measurement
// contractors (paper 003 §2.4, §3.6.2, §4.4; Jaulin 2009), over the
// measurement-set view. mode=contract gives the fixpoint box of
// Fixpoint(QIntersection(measurements, q)) from the prior; mode=pave the
// relaxed set inversion (RSIVIA): a paving of boxes narrower than epsilon,
// tighter than the hull where the solution set has several pieces.
//
// Sound: every point of the prior that satisfies at least m - q measurements
// is kept. Each round's q-relaxed intersection of the contracted boxes is the
// exact hull of the points in at least m - q of them (core/
// relaxed_intersection.h), so the fixpoint box is never wider than that of
// IBEX's CtcFixPoint(CtcQInter) over the same contractors
// (tests/q_relaxed_fixpoint_test.cc).
#ifndef ICPBENCH_ALGORITHMS_Q_RELAXED_Q_RELAXED_H_
#define ICPBENCH_ALGORITHMS_Q_RELAXED_Q_RELAXED_H_

#include <cstdint>
#include <memory>
#include <string>

#include "algorithms/relaxed/relaxed_estimator.h"

namespace icp {

struct QRelaxedParams {
  RelaxedParams relaxed;
  std::string mode = "contract";
  // Pavings: a box narrower than this in every component is not bisected
  // further (state units). Halving it roughly doubles the boxes of a curve
  // and quadruples those of an area.
  double epsilon = 0.05;
  // The fixpoint stops when no component shrinks by more than this
  // fraction of its width.
  double ratio = 1e-3;
  int max_iterations = 1000;
  // Pavings: bisection stops (soundly, coarser) past this many boxes.
  int max_boxes = 100000;
};
void Describe(QRelaxedParams& p, ParamSet& set);

std::unique_ptr<Estimator> MakeQRelaxed(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_Q_RELAXED_Q_RELAXED_H_
