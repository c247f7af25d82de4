#include "core/box.h"

#include <algorithm>

namespace icp {

bool Box::IsSubsetOf(const Box& other) const {
  if (IsEmpty()) return true;
  if (size() != other.size()) return false;
  for (std::size_t i = 0; i < size(); ++i)
    if (!v_[i].IsSubsetOf(other[i])) return false;
  return true;
}

bool Box::Contains(const std::vector<double>& point) const {
  if (point.size() != size()) return false;
  for (std::size_t i = 0; i < size(); ++i)
    if (!v_[i].Contains(point[i])) return false;
  return true;
}

double Box::MaxWidth() const {
  double w = 0;
  for (const Interval& x : v_) w = std::max(w, x.Width());
  return w;
}

}  // namespace icp
