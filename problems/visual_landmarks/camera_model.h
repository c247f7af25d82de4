// Paper 004's camera and landmark model (§3.3-3.4, eq. 12-19), the part of
// the visual-landmarks problem that every estimator's constraints come from.
//
// Conventions (the paper leaves them open):
//   - World frame: x, y on the ground, z up. A pose (x, y, theta) is the
//     car's position on the ground and its heading, counter-clockwise from
//     the x axis.
//   - The camera's optical centre is at (x, y, height), its optical axis
//     along the heading, level (no pitch, no roll). Camera frame: X_c to the
//     right, Y_c down, Z_c forward. A point at D = L - (x, y, height) in the
//     world is at
//       Z_c = D_x cos theta + D_y sin theta,
//       X_c = D_x sin theta - D_y cos theta,
//       Y_c = -D_z,
//     and is seen, when Z_c > 0, at the pixel (eq. 14, pinhole)
//       u = c_u + f X_c / Z_c,  v = c_v + f Y_c / Z_c.
//   - m(alpha, phi) = (cos phi cos alpha, cos phi sin alpha, sin phi): alpha
//     the azimuth, counter-clockwise from the world x axis, phi the
//     elevation above the horizontal. A landmark is six intervals
//     (x_c, y_c, z_c, alpha, phi, d), L = c + d m(alpha, phi) (eq. 12), c the
//     optical centre when it was first seen.
//   - Its position L = (x, y, z) is three more components, defined by eq. 12
//     (AddConeDefinition), and the observations are written on L: each is
//     then linear in the landmark (two planes through the camera's centre),
//     which HC4 intersects well, while eq. 12 carries what they say to the
//     cone and back. The solution set is the paper's (L is a function of
//     the cone); on the paper's scene HC4 bounds L two to three times
//     tighter than with the observations written on the cone alone
//     (docs/reproduction/paper004.md).
#ifndef ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_CAMERA_MODEL_H_
#define ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_CAMERA_MODEL_H_

#include <array>
#include <optional>

#include "core/box.h"
#include "core/constraint_system.h"
#include "core/interval.h"

namespace icp {

// Paper 004 §5.1: a 640 x 480 image, fk_u = fk_v = 320 px, the principal
// point at its centre. The camera height is ours (the paper does not say).
struct CameraIntrinsics {
  double focal = 320;  // px, fk_u = fk_v
  double cu = 320;     // px
  double cv = 240;     // px
  int width = 640;     // px
  int height = 480;    // px
  double mount_height = 1.5;  // m, the optical centre above the ground
};

// The components of a landmark, in this order in a Box: the cone's six
// intervals, then the position L that eq. 12 defines.
enum LandmarkComponent {
  kLandmarkXc, kLandmarkYc, kLandmarkZc, kAlpha, kPhi, kDepth, kLandmarkX, kLandmarkY, kLandmarkZ
};
inline constexpr int kConeComponents = 6;
inline constexpr int kLandmarkComponents = 9;

// A pixel, in px.
struct Pixel {
  double u = 0;
  double v = 0;
};

// Where the point L (world) is seen from the pose (x, y, theta): nothing when
// it is behind the camera (Z_c <= 0) or outside the image. For the simulator.
std::optional<Pixel> Project(const std::array<double, 3>& pose, const std::array<double, 3>& point,
                             const CameraIntrinsics& camera);

// The landmark's cone at its first sighting (undelayed initialisation,
// paper 004 Fig. 5): c the camera's optical centre over the pose box, the
// ray's direction from the pixel box, d in [0, +oo]. Holds every landmark
// that projects into the pixel box from some pose of the pose box: with
// a = ([u] - c_u) / f and b = ([v] - c_v) / f the ray's slopes in the
// camera frame, alpha = theta - atan(a) and phi = atan(-b / sqrt(1 + a^2)).
// The pose box is (x, y, theta). The position components are eq. 12 over
// the cone.
Box InitialCone(const Box& pose, const Interval& u, const Interval& v,
                const CameraIntrinsics& camera);

// The landmark's position box: eq. 12 in interval arithmetic over the cone,
// intersected with the position components when the box has them; the box
// that MPV and MDW measure (eq. 32). Empty when the landmark is.
std::array<Interval, 3> LandmarkPosition(const Box& landmark);

// The variables of one observation ICSP (eq. 16): a pose and a landmark's
// six parameters, as expressions of some ConstraintSystem.
struct PoseExprs {
  Expr x, y, theta;
};
struct LandmarkExprs {
  Expr xc, yc, zc, alpha, phi, d, x, y, z;
};

// Eq. 12 as three constraints: (x, y, z) = c + d m(alpha, phi).
void AddConeDefinition(ConstraintSystem& csp, const LandmarkExprs& landmark);

// Adds the observation (eq. 18-19) of a landmark seen at the pixel box
// [u] x [v] from the pose: u in [u] and v in [v] with Z_c > 0, written as
//   X_c - a Z_c = 0,  Y_c - b Z_c = 0,  Z_c >= 0,
// a in ([u] - c_u) / f and b in ([v] - c_v) / f interval constants: for
// Z_c > 0 the same set as the pinhole equations of eq. 14 with eq. 15's
// intersection. The two equalities are written twice: on the cone, with
// D = c - (x, y, height) + d m linear in d and d once (which bounds d by
// parallax: with d's several occurrences in X_c / Z_c, HC4 never bounded it
// in 400 random two-view scenes, camera_model_test), and on the position,
// with D = L - (x, y, height) linear in L (two planes through the camera
// centre, which HC4 intersects across views but cannot bound alone).
// Z_c >= 0: a point is seen only in front of the camera (without it the
// mirror point behind the camera also fits). Five constraints, sound for
// any domains, Z_c's holding 0 and d or L unbounded included. The paper's
// observation ICSP is this with AddConeDefinition.
// With on_position false, only the cone's form and Z_c >= 0 (three
// constraints: the observation as the paper writes it, for comparison).
void AddObservation(ConstraintSystem& csp, const PoseExprs& pose, const LandmarkExprs& landmark,
                    const Interval& u, const Interval& v, const CameraIntrinsics& camera,
                    bool on_position = true);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_CAMERA_MODEL_H_
