#include "core/box.h"

#include <algorithm>
#include <cmath>

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

Box Hull(const Box& a, const Box& b) {
  if (a.IsEmpty()) return b;
  if (b.IsEmpty()) return a;
  Box out(a.size());
  for (std::size_t d = 0; d < a.size(); ++d) out[d] = Hull(a[d], b[d]);
  return out;
}

Box Intersect(const Box& a, const Box& b) {
  Box out(a.size());
  for (std::size_t d = 0; d < a.size(); ++d) out[d] = Intersect(a[d], b[d]);
  if (out.IsEmpty()) out.SetEmpty();
  return out;
}

int FirstNaNComponent(const Box& box) {
  for (std::size_t i = 0; i < box.size(); ++i)
    if (std::isnan(box[i].lo()) || std::isnan(box[i].hi())) return static_cast<int>(i);
  return -1;
}

std::string ComponentName(const std::vector<std::string>& names, std::size_t i) {
  return i < names.size() ? names[i] : "component " + std::to_string(i);
}

}  // namespace icp
