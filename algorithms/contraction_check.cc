#include "algorithms/contraction_check.h"

namespace icp {

std::string InvalidContractionReason(const Box& initial, const Box& box,
                                     const std::vector<std::string>& names) {
  if (const int nan = FirstNaNComponent(box); nan >= 0) return ComponentName(names, nan) + " has a NaN bound";
  if (box.size() != initial.size())
    return "the box has " + std::to_string(box.size()) + " components, the CSP " +
           std::to_string(initial.size());
  if (box.IsEmpty()) return "";
  for (std::size_t i = 0; i < box.size(); ++i)
    if (!box[i].IsSubsetOf(initial[i])) return ComponentName(names, i) + " grew beyond its initial domain";
  return "";
}

}  // namespace icp
