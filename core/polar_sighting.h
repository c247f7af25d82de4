// Paper 002's measurement and motion equations as constraints and interval
// functions, shared by the indoor-landmarks problem (its measurement-set
// view) and the landmark-tracking estimators:
//   - a range-and-bearing sighting of a known point (eq. 10-11),
//   - a sighting put in the world frame from a pose box (eq. 8-9),
//   - a differential drive's odometry (§3.3, eq. 5-7).
// Every function and constraint is sound: it holds at the true values
// whenever the intervals hold them.
#ifndef ICPBENCH_CORE_POLAR_SIGHTING_H_
#define ICPBENCH_CORE_POLAR_SIGHTING_H_

#include <array>
#include <string>

#include "core/box.h"
#include "core/constraint_system.h"
#include "core/view.h"

namespace icp {

// Adds the sighting `observation` of the point (xl, yl) from the pose
// (x, y, heading) to csp:
//   sqrt((xl - x)^2 + (yl - y)^2) in [range]                        (eq. 10)
//   atan2(v, u) in [bearing] - b                                     (eq. 11)
// where (u, v) is the point's offset rotated by -(heading + b) and b the
// bearing interval's midpoint. Eq. 11 as the paper writes it, bearing =
// atan2(yl - y, xl - x) - heading, holds only modulo 2 pi, and atan2's
// branch cut splits a bearing interval that crosses it; measured from b the
// angle stays within the bearing's half-width, away from the cut, so this
// form is exact for every representative of the heading. A bearing interval
// of width 2 pi or more says nothing and adds no bearing constraint.
void AddPolarSighting(ConstraintSystem& csp, Expr x, Expr y, Expr heading, double xl, double yl,
                      const PolarObservation& observation);

// The sighting alone as a system over the pose: variables x, y, theta with
// the domains of `pose` (three components), constrained as AddPolarSighting
// does.
ConstraintSystem PoseSighting(double xl, double yl, const PolarObservation& observation,
                              const Box& pose);

// The world box of the sighted point seen from any pose of `pose` (x, y,
// heading), eq. 8-9: x + d cos(heading + bearing), y + d sin(heading +
// bearing).
std::array<Interval, 2> SightingWorldBox(const Box& pose, const PolarObservation& observation);

// The displacement d = (R_r w_r + R_l w_l) / 2 and the turn
// (R_r w_r - R_l w_l) / L of one step (paper 002 §3.3).
Interval OdometryDistance(const WheelOdometry& odometry);
Interval OdometryTurn(const WheelOdometry& odometry);

// The pose box after the step (eq. 5-7): x + d cos(heading + turn / 2),
// y + d sin(heading + turn / 2), heading + turn.
Box PredictPose(const Box& pose, const WheelOdometry& odometry);

// Adds the step's motion from pose `from` to pose `to` (x, y, heading
// expressions of csp) as eq. 5-7 with the wheel radii, track width and
// rotations as variables named <name><suffix> (R_r, R_l, L, w_r, w_l, d,
// turn), their domains the odometry's intervals, so that constraint
// propagation may narrow them together.
void AddWheelOdometry(ConstraintSystem& csp, const std::array<Expr, 3>& from,
                      const std::array<Expr, 3>& to, const WheelOdometry& odometry,
                      const std::string& suffix);

}  // namespace icp

#endif  // ICPBENCH_CORE_POLAR_SIGHTING_H_
