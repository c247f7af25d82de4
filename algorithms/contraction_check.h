// What every contraction's result must be, checked where the harness and
// `icpbench solve` take one from an algorithm (a plugin's included): a
// contractor may only narrow its box.
#ifndef ICPBENCH_ALGORITHMS_CONTRACTION_CHECK_H_
#define ICPBENCH_ALGORITHMS_CONTRACTION_CHECK_H_

#include <string>
#include <vector>

#include "core/box.h"

namespace icp {

// Why box cannot be what a contractor made of initial (names: the
// components'): a NaN bound (which would read as empty, !(lo <= hi)),
// another number of components, or a component outside initial's; "" when
// it can be. An empty box always can.
std::string InvalidContractionReason(const Box& initial, const Box& box,
                                     const std::vector<std::string>& names);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_CONTRACTION_CHECK_H_
