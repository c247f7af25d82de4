// µs per CSP for HC4 on car-track-shaped windows (3 constraints per step),
// w in {5, 10, 20, 40}. Paper 000 Table 1 reports 0.52 ms at w = 20.
#include <benchmark/benchmark.h>

#include "algorithms/hc4/hc4.h"
#include "problems/chain/chain.h"

namespace icp {
namespace {

void BM_HC4Chain(benchmark::State& state) {
  ChainParams p;
  p.w = static_cast<int>(state.range(0));
  Step step = MakeChainStep(p, 7);
  HC4Contractor hc4(std::make_shared<CompiledSystem>(step.csp), HC4Params());
  std::int64_t revises = 0;
  for (auto _ : state) {
    Box box = step.csp.domains();
    revises += hc4.Contract(box, StopCondition()).work.revise_calls;
    benchmark::DoNotOptimize(box);
  }
  state.counters["revise_calls"] =
      benchmark::Counter(static_cast<double>(revises), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_HC4Chain)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace icp
