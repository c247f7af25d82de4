// The single car-track windows that the HC4 benchmarks and the side-by-side
// check with other binaries share: chain windows (paper 000 eq. 14, see
// problems/chain) of w steps for seeds 1..n, "prior" with the oldest heading
// known to ±0.1 rad, "cold" with it in [-pi, pi].
#ifndef ICPBENCH_BENCH_CHAIN_WINDOWS_H_
#define ICPBENCH_BENCH_CHAIN_WINDOWS_H_

#include <string>
#include <vector>

#include "core/constraint_system.h"
#include "problems/chain/chain.h"

namespace icp {

inline constexpr int kChainWindowSeeds = 12;
inline constexpr int kChainWindowLengths[] = {5, 10, 20};

// "prior" or "cold".
inline std::string HeadingName(bool heading_known) { return heading_known ? "prior" : "cold"; }

inline std::vector<ConstraintSystem> ChainWindows(int w, bool heading_known,
                                                  int seeds = kChainWindowSeeds) {
  ChainParams p;
  p.w = w;
  p.heading_known = heading_known;
  std::vector<ConstraintSystem> windows;
  for (int seed = 1; seed <= seeds; ++seed) windows.push_back(MakeChainStep(p, seed).views.csp->csp);
  return windows;
}

}  // namespace icp

#endif  // ICPBENCH_BENCH_CHAIN_WINDOWS_H_
