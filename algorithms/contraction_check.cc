#include "algorithms/contraction_check.h"

#include <cmath>

namespace icp {

int FirstNaNComponent(const Box& box) {
  for (std::size_t i = 0; i < box.size(); ++i)
    if (std::isnan(box[i].lo()) || std::isnan(box[i].hi())) return static_cast<int>(i);
  return -1;
}

std::string InvalidContractionReason(const Box& initial, const Box& box,
                                     const std::vector<std::string>& names) {
  auto name = [&](std::size_t i) { return i < names.size() ? names[i] : "component " + std::to_string(i); };
  if (const int nan = FirstNaNComponent(box); nan >= 0) return name(nan) + " has a NaN bound";
  if (box.size() != initial.size())
    return "the box has " + std::to_string(box.size()) + " components, the CSP " +
           std::to_string(initial.size());
  if (box.IsEmpty()) return "";
  for (std::size_t i = 0; i < box.size(); ++i)
    if (!box[i].IsSubsetOf(initial[i])) return name(i) + " grew beyond its initial domain";
  return "";
}

}  // namespace icp
