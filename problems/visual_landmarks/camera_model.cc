#include "problems/visual_landmarks/camera_model.h"

#include <cmath>

namespace icp {

std::optional<Pixel> Project(const std::array<double, 3>& pose, const std::array<double, 3>& point,
                             const CameraIntrinsics& camera) {
  const double dx = point[0] - pose[0];
  const double dy = point[1] - pose[1];
  const double dz = point[2] - camera.mount_height;
  const double c = std::cos(pose[2]), s = std::sin(pose[2]);
  const double zc = dx * c + dy * s;
  if (!(zc > 0)) return std::nullopt;
  const Pixel pixel{camera.cu + camera.focal * (dx * s - dy * c) / zc,
                    camera.cv + camera.focal * (-dz) / zc};
  if (pixel.u < 0 || pixel.u > camera.width || pixel.v < 0 || pixel.v > camera.height)
    return std::nullopt;
  return pixel;
}

Box InitialCone(const Box& pose, const Interval& u, const Interval& v,
                const CameraIntrinsics& camera) {
  const Interval focal(camera.focal);
  const Interval a = (u - Interval(camera.cu)) / focal;  // right per unit forward
  const Interval b = (v - Interval(camera.cv)) / focal;  // down per unit forward
  Box cone(kLandmarkComponents);
  cone[kLandmarkXc] = pose[0];
  cone[kLandmarkYc] = pose[1];
  cone[kLandmarkZc] = Interval(camera.mount_height);
  cone[kAlpha] = pose[2] - Atan(a);
  cone[kPhi] = Atan(-b / Sqrt(Interval(1.0) + Sqr(a)));
  cone[kDepth] = Interval(0.0, kInf);
  const std::array<Interval, 3> position = LandmarkPosition(cone);
  for (int axis = 0; axis < 3; ++axis) cone[kLandmarkX + axis] = position[axis];
  return cone;
}

std::array<Interval, 3> LandmarkPosition(const Box& landmark) {
  const Interval& d = landmark[kDepth];
  const Interval horizontal = d * Cos(landmark[kPhi]);
  std::array<Interval, 3> out = {landmark[kLandmarkXc] + horizontal * Cos(landmark[kAlpha]),
                                 landmark[kLandmarkYc] + horizontal * Sin(landmark[kAlpha]),
                                 landmark[kLandmarkZc] + d * Sin(landmark[kPhi])};
  if (landmark.size() >= static_cast<std::size_t>(kLandmarkComponents))
    for (int axis = 0; axis < 3; ++axis) out[axis] = Intersect(out[axis], landmark[kLandmarkX + axis]);
  if (out[0].IsEmpty() || out[1].IsEmpty() || out[2].IsEmpty())
    for (Interval& axis : out) axis = Interval::Empty();
  return out;
}

void AddConeDefinition(ConstraintSystem& csp, const LandmarkExprs& l) {
  const Expr horizontal = l.d * Cos(l.phi);
  csp.AddConstraint(l.x, Relation::kEq, l.xc + horizontal * Cos(l.alpha));
  csp.AddConstraint(l.y, Relation::kEq, l.yc + horizontal * Sin(l.alpha));
  csp.AddConstraint(l.z, Relation::kEq, l.zc + l.d * Sin(l.phi));
}

void AddObservation(ConstraintSystem& csp, const PoseExprs& pose, const LandmarkExprs& landmark,
                    const Interval& u, const Interval& v, const CameraIntrinsics& camera,
                    bool on_position) {
  // The pixel box's slopes, a = X_c / Z_c and b = Y_c / Z_c: interval
  // constants, so "X_c - [a] Z_c = 0" says "X_c = a Z_c for some a in [a]".
  const Interval focal(camera.focal);
  const Expr a = csp.Constant((u - Interval(camera.cu)) / focal);
  const Expr b = csp.Constant((v - Interval(camera.cv)) / focal);
  const Expr cos_theta = Cos(pose.theta), sin_theta = Sin(pose.theta);
  const Expr right_minus_a_ahead_x = sin_theta - a * cos_theta;
  const Expr right_minus_a_ahead_y = -cos_theta - a * sin_theta;
  // On the cone: D = delta + d m, delta = c - (x, y, height), every camera
  // coordinate linear in d, so X_c - a Z_c = N + d K with d once.
  const Expr horizontal = Cos(landmark.phi);
  const Expr mx = horizontal * Cos(landmark.alpha), my = horizontal * Sin(landmark.alpha);
  const Expr mz = Sin(landmark.phi);
  const Expr delta_x = landmark.xc - pose.x, delta_y = landmark.yc - pose.y;
  const Expr delta_z = landmark.zc - camera.mount_height;
  csp.AddConstraint(delta_x * right_minus_a_ahead_x + delta_y * right_minus_a_ahead_y +
                        landmark.d * (mx * right_minus_a_ahead_x + my * right_minus_a_ahead_y),
                    Interval(0.0));
  // Y_c - b Z_c = -D_z - b (D_x cos theta + D_y sin theta).
  csp.AddConstraint(-delta_z - b * (delta_x * cos_theta + delta_y * sin_theta) +
                        landmark.d * (-mz - b * (mx * cos_theta + my * sin_theta)),
                    Interval(0.0));
  if (!on_position) {
    csp.AddConstraint(delta_x * cos_theta + delta_y * sin_theta +
                          landmark.d * (mx * cos_theta + my * sin_theta),
                      Interval(0.0, kInf));  // Z_c >= 0
    return;
  }
  // On the position: D = L - (x, y, height), linear in L.
  const Expr dx = landmark.x - pose.x, dy = landmark.y - pose.y;
  const Expr ahead = dx * cos_theta + dy * sin_theta;  // Z_c
  csp.AddConstraint(dx * right_minus_a_ahead_x + dy * right_minus_a_ahead_y, Interval(0.0));
  csp.AddConstraint(-(landmark.z - camera.mount_height) - b * ahead, Interval(0.0));
  csp.AddConstraint(ahead, Interval(0.0, kInf));
}

}  // namespace icp
