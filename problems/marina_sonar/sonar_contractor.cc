#include "problems/marina_sonar/sonar_contractor.h"

#include <stdexcept>
#include <utility>

namespace icp {

Interval SonarRangeInterval(double range, double range_error) {
  return Intersect(Interval(range) + Interval(-range_error, range_error), Interval(0, kInf));
}

Interval SonarAngleInterval(double heading, double heading_error, double beam_angle,
                            double beam_half_width) {
  return Interval(heading) + Interval(-heading_error, heading_error) + Interval(beam_angle) +
         Interval(-beam_half_width, beam_half_width);
}

SonarContractor::SonarContractor(std::shared_ptr<const BinaryImage> map, Interval range,
                                 Interval angle, Interval carried_x, Interval carried_y,
                                 int x_index, int y_index)
    : map_(std::move(map)), range_(range), angle_(angle), x_index_(x_index), y_index_(y_index) {
  if (!map_) throw std::invalid_argument("SonarContractor: no map");
  if (range_.IsEmpty() || !range_.IsBounded() || angle_.IsEmpty() || !angle_.IsBounded())
    throw std::invalid_argument("SonarContractor: the range and angle intervals must be bounded and non-empty");
  if (carried_x.IsEmpty() || !carried_x.IsBounded() || carried_y.IsEmpty() || !carried_y.IsBounded())
    throw std::invalid_argument("SonarContractor: the carried displacement must be bounded and non-empty");
  px_ = range_ * Cos(angle_) - carried_x;
  py_ = range_ * Sin(angle_) - carried_y;
}

ContractSummary SonarContractor::Contract(Box& box, ContractContext&) {
  ContractSummary summary;
  summary.work.revise_calls = 1;
  if (box.IsEmpty()) {
    summary.status = ContractStatus::kEmpty;
    return summary;
  }
  const Interval x = box[x_index_], y = box[y_index_];
  const Box h = map_->Contract(Box({x + px_, y + py_}));
  const Interval nx = h.IsEmpty() ? Interval::Empty() : Intersect(x, h[0] - px_);
  const Interval ny = h.IsEmpty() ? Interval::Empty() : Intersect(y, h[1] - py_);
  if (nx.IsEmpty() || ny.IsEmpty()) {
    box.SetEmpty();
    summary.status = ContractStatus::kEmpty;
    return summary;
  }
  const bool shrank = !(nx == x) || !(ny == y);
  box[x_index_] = nx;
  box[y_index_] = ny;
  summary.status = shrank ? ContractStatus::kContracted : ContractStatus::kFixpoint;
  return summary;
}

}  // namespace icp
