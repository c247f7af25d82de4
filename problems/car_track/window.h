// The CSP of paper 000 eq. 14 over one window of car states, shared by the
// car-track problem and the single-window chain problem. States j = oldest..
// newest, each (x[j], y[j], th[j]), linked for j > oldest by
//   x[j]  = x[j-1] + ds_j cos(th[j-1] + dth_j / 2)
//   y[j]  = y[j-1] + ds_j sin(th[j-1] + dth_j / 2)
//   th[j] = th[j-1] + dth_j
// with [ds_j] and [dth_j] interval constants: 3 (newest - oldest)
// constraints over 3 (newest - oldest + 1) variables, stored from the oldest
// state to the newest (variable 3 (j - oldest) + component), named with the
// absolute step number and tagged with their StateRef.
#ifndef ICPBENCH_PROBLEMS_CAR_TRACK_WINDOW_H_
#define ICPBENCH_PROBLEMS_CAR_TRACK_WINDOW_H_

#include <vector>

#include "core/interval.h"
#include "core/view.h"

namespace icp {

// What one state j contributes: its domains and the motion into it from
// state j - 1 (unused for the oldest state).
struct CarWindowState {
  Interval x, y, th;  // initial domains
  Interval ds, dth;   // odometry and gyro intervals of the motion into j
};

// The state space of a car: x, y (the planar position) and the heading th,
// periodic with period 2 pi.
StateSpace CarStateSpace();

// The window over states[0..n-1] = steps oldest..oldest + n - 1.
CspView BuildCarWindow(int oldest, const std::vector<CarWindowState>& states);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_CAR_TRACK_WINDOW_H_
