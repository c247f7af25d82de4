#include "problems/registry.h"

#include <stdexcept>

#include "problems/chain/chain.h"
#include "problems/minibex_file/minibex_file.h"

namespace icp {

const std::vector<ProblemInfo>& Problems() {
  static const std::vector<ProblemInfo> kProblems = {
      {"chain", "car-track-shaped window CSP (paper 000 eq. 14) with a simulated truth",
       &MakeChain, &DefaultParams<ChainParams>},
      {"minibex-file", "one CSP read from a Minibex file (IBEX benchmark syntax)",
       &MakeMinibexFile, &DefaultParams<MinibexFileParams>},
  };
  return kProblems;
}

const ProblemInfo& FindProblem(const std::string& name) {
  std::string known;
  for (const ProblemInfo& p : Problems()) {
    if (p.name == name) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw std::invalid_argument("unknown problem '" + name + "' (known: " + known + ")");
}

}  // namespace icp
