// A single window of the car-track CSP (paper 000 eq. 14) around a simulated
// drive: states (x_k, y_k, th_k), k = 0..w, linked by
//   x_k  = x_{k-1} + ds_k cos(th_{k-1} + dth_k / 2)
//   y_k  = y_{k-1} + ds_k sin(th_{k-1} + dth_k / 2)
//   th_k = th_{k-1} + dth_k
// with odometry ds_k and gyro dth_k as intervals (eq. 9-10) and GPS boxes as
// the x, y domains (eq. 11). 3w constraints, 3(w+1) variables. Every
// measurement interval holds the truth, so a sound algorithm never loses it.
// The full car-track problem (a lap, a sliding window) builds on this shape.
#ifndef ICPBENCH_PROBLEMS_CHAIN_CHAIN_H_
#define ICPBENCH_PROBLEMS_CHAIN_CHAIN_H_

#include <cstdint>
#include <memory>

#include "core/params.h"
#include "problems/problem.h"

namespace icp {

struct ChainParams {
  // Window length: number of motion steps (the paper uses 20).
  int w = 20;
  // Mean distance per step in metres (about 50 km/h at 5 Hz).
  double step_length = 2.78;
  // Odometry half-width in metres (eq. 9, steps plus slip).
  double odometry_error = 0.05;
  // Gyro half-width per step in radians (eq. 10).
  double gyro_error = 0.002;
  // GPS half-width in metres on x and y (eq. 11).
  double gps_error = 2.5;
  // Largest true heading change per step in radians.
  double max_turn = 0.05;
  // If false, th_0 starts as [-pi, pi] (paper 000 §4.3); else truth ± 0.1.
  bool heading_known = false;
};
void Describe(ChainParams& p, ParamSet& set);

// Builds the window for the given seed.
Step MakeChainStep(const ChainParams& params, std::uint64_t seed);

std::unique_ptr<Problem> MakeChain(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_CHAIN_CHAIN_H_
