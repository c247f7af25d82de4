#include "core/polar_sighting.h"

#include <numbers>
#include <stdexcept>

namespace icp {

void AddPolarSighting(ConstraintSystem& csp, Expr x, Expr y, Expr heading, double xl, double yl,
                      const PolarObservation& observation) {
  Expr dx = xl - x;
  Expr dy = yl - y;
  csp.AddConstraint(Sqrt(Sqr(dx) + Sqr(dy)), observation.range);
  const Interval& bearing = observation.bearing;
  if (!(bearing.hi() - bearing.lo() < 2 * std::numbers::pi)) return;
  const double b = 0.5 * (bearing.lo() + bearing.hi());
  Expr direction = heading + b;
  Expr c = Cos(direction);
  Expr s = Sin(direction);
  csp.AddConstraint(Atan2(c * dy - s * dx, c * dx + s * dy), bearing - Interval(b));
}

ConstraintSystem PoseSighting(double xl, double yl, const PolarObservation& observation,
                              const Box& pose) {
  if (pose.size() != 3) throw std::invalid_argument("PoseSighting: the pose is (x, y, theta)");
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", pose[0]);
  Expr y = csp.AddVariable("y", pose[1]);
  Expr theta = csp.AddVariable("theta", pose[2]);
  AddPolarSighting(csp, x, y, theta, xl, yl, observation);
  return csp;
}

std::array<Interval, 2> SightingWorldBox(const Box& pose, const PolarObservation& observation) {
  const Interval direction = pose[2] + observation.bearing;
  return {pose[0] + observation.range * Cos(direction),
          pose[1] + observation.range * Sin(direction)};
}

Interval OdometryDistance(const WheelOdometry& o) {
  return (o.right_radius * o.right_rotation + o.left_radius * o.left_rotation) / Interval(2);
}

Interval OdometryTurn(const WheelOdometry& o) {
  return (o.right_radius * o.right_rotation - o.left_radius * o.left_rotation) / o.track;
}

Box PredictPose(const Box& pose, const WheelOdometry& odometry) {
  const Interval d = OdometryDistance(odometry);
  const Interval turn = OdometryTurn(odometry);
  const Interval mid = pose[2] + turn / Interval(2);
  return Box({pose[0] + d * Cos(mid), pose[1] + d * Sin(mid), pose[2] + turn});
}

void AddWheelOdometry(ConstraintSystem& csp, const std::array<Expr, 3>& from,
                      const std::array<Expr, 3>& to, const WheelOdometry& o,
                      const std::string& suffix) {
  Expr rr = csp.AddVariable("R_r" + suffix, o.right_radius);
  Expr rl = csp.AddVariable("R_l" + suffix, o.left_radius);
  Expr track = csp.AddVariable("L" + suffix, o.track);
  Expr wr = csp.AddVariable("w_r" + suffix, o.right_rotation);
  Expr wl = csp.AddVariable("w_l" + suffix, o.left_rotation);
  Expr d = csp.AddVariable("d" + suffix, OdometryDistance(o));
  Expr turn = csp.AddVariable("turn" + suffix, OdometryTurn(o));
  csp.AddConstraint(2 * d, Relation::kEq, rr * wr + rl * wl);
  csp.AddConstraint(turn * track, Relation::kEq, rr * wr - rl * wl);
  Expr mid = from[2] + 0.5 * turn;
  csp.AddConstraint(to[0], Relation::kEq, from[0] + d * Cos(mid));
  csp.AddConstraint(to[1], Relation::kEq, from[1] + d * Sin(mid));
  csp.AddConstraint(to[2], Relation::kEq, from[2] + turn);
}

}  // namespace icp
