#include "algorithms/registry.h"

#include <stdexcept>

#include "algorithms/bc3/bc3.h"
#include "algorithms/bc4/bc4.h"
#include "algorithms/fault/fault.h"
#include "algorithms/hc3/hc3.h"
#include "algorithms/hc4/hc4.h"
#include "algorithms/three_b/three_b.h"

namespace icp {

const std::vector<AlgorithmInfo>& Algorithms() {
  static const std::vector<AlgorithmInfo> kAlgorithms = {
      {"hc3", "HC3: constraints decomposed into primitives with auxiliary variables, AC3 queue",
       &MakeHC3, &DefaultParams<HC3Params>, &ValidateParams<HC3Params>},
      {"hc4", "HC4: HC4Revise (forward-backward on each constraint's tree) propagated to a fixpoint",
       &MakeHC4, &DefaultParams<HC4Params>, &ValidateParams<HC4Params>},
      {"bc3", "BC3: box consistency per (constraint, variable) by interval Newton and bisection",
       &MakeBC3, &DefaultParams<BC3Params>, &ValidateParams<BC3Params>},
      {"bc4", "BC4: HC4Revise for single occurrences, BC3 narrowing for multiple ones",
       &MakeBC4, &DefaultParams<BC4Params>, &ValidateParams<BC4Params>},
      {"3b-bc4", "3B consistency: bounds shaved in slices refuted by BC4 (the paper's 3B-BC4)",
       &MakeThreeBBC4, &DefaultParams<ThreeBParams<BC4Params>>, &ValidateParams<ThreeBParams<BC4Params>>},
      {"3b-hc4", "3B consistency: bounds shaved in slices refuted by HC4",
       &MakeThreeBHC4, &DefaultParams<ThreeBParams<HC4Params>>, &ValidateParams<ThreeBParams<HC4Params>>},
      {"fault", "not an algorithm: injects a crash, hang, exception or bad box (harness tests)",
       &MakeFault, &DefaultParams<FaultParams>, &ValidateParams<FaultParams>, View::kCsp, true},
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
