// The sonar-return contractor of paper 003 §6.5.3: one return of a
// sector-scan sonar, a range [d] along a beam whose absolute angle lies in
// [a] (the beam's angle on the robot + the compass heading interval ± the
// beam's half-width), seen from the robot's position M = (x, y), is the
// constraint of eq. 6.8 with the slack point H on the map:
//   C1: |H - M| in [d],   C2: arg(H - M) in [a],   C3: H in the map.
// C1 and C2 together say H - M lies in the polar set {d (cos a, sin a) : d
// in [d], a in [a]}, enclosed by the box P = ([d] Cos [a], [d] Sin [a])
// computed once, outward rounded. Contract(M) runs the forward-backward
// projection of H = M + P through C3:
//   H = C3(M + P)            (the image contractor, core/image_contractor.h)
//   M = M ∩ (H - P)
// so it costs two interval additions, one image contraction (logarithmic in
// the image size) and two subtractions. Sound: a position M from which some
// map point H satisfies C1 and C2 keeps H in M + P, so in C3(M + P), and M in
// H - P. Not idempotent in general (a narrower M may give a narrower H).
#ifndef ICPBENCH_PROBLEMS_MARINA_SONAR_SONAR_CONTRACTOR_H_
#define ICPBENCH_PROBLEMS_MARINA_SONAR_SONAR_CONTRACTOR_H_

#include <memory>
#include <string_view>

#include "core/contractor.h"
#include "core/image_contractor.h"
#include "core/interval.h"

namespace icp {

// [reading - error, reading + error] ∩ [0, +oo[, outward rounded.
Interval SonarRangeInterval(double range, double range_error);
// The absolute beam angle: heading ± heading_error + beam_angle ±
// beam_half_width, outward rounded (rad, counterclockwise from the x axis).
Interval SonarAngleInterval(double heading, double heading_error, double beam_angle,
                            double beam_half_width);

class SonarContractor : public Contractor {
 public:
  // Contracts components x_index and y_index of a box (the robot's
  // position). A return made carried = (carried_x, carried_y) before the
  // position to contract (the robot moved by it since: the dead reckoning
  // of eq. 6.2) has H = M - carried + d (cos a, sin a): P is shifted by
  // -carried. Throws std::invalid_argument when range, angle or carried is
  // empty or unbounded.
  SonarContractor(std::shared_ptr<const BinaryImage> map, Interval range, Interval angle,
                  Interval carried_x = Interval(0), Interval carried_y = Interval(0),
                  int x_index = 0, int y_index = 1);
  std::string_view Name() const override { return "sonar"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

  const Interval& range() const { return range_; }
  const Interval& angle() const { return angle_; }
  // The box P enclosing H - M (carried included).
  const Interval& offset_x() const { return px_; }
  const Interval& offset_y() const { return py_; }

 private:
  std::shared_ptr<const BinaryImage> map_;
  Interval range_, angle_, px_, py_;
  int x_index_, y_index_;
};

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_MARINA_SONAR_SONAR_CONTRACTOR_H_
