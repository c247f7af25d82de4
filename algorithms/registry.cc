#include "algorithms/registry.h"

#include <stdexcept>

#include "algorithms/hc3/hc3.h"
#include "algorithms/hc4/hc4.h"

namespace icp {

const std::vector<AlgorithmInfo>& Algorithms() {
  static const std::vector<AlgorithmInfo> kAlgorithms = {
      {"hc3", "HC3: constraints decomposed into primitives with auxiliary variables, AC3 queue",
       &MakeHC3, &DefaultParams<HC3Params>},
      {"hc4", "HC4: HC4Revise (forward-backward on each constraint's tree) propagated to a fixpoint",
       &MakeHC4, &DefaultParams<HC4Params>},
  };
  return kAlgorithms;
}

const AlgorithmInfo& FindAlgorithm(const std::string& name) {
  std::string known;
  for (const AlgorithmInfo& a : Algorithms()) {
    if (a.name == name) return a;
    known += (known.empty() ? "" : ", ") + a.name;
  }
  throw std::invalid_argument("unknown algorithm '" + name + "' (known: " + known + ")");
}

}  // namespace icp
