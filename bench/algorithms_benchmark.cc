// µs per CSP for every registered algorithm on car-track-shaped windows
// (paper 000 eq. 14: 3 constraints per step), w in {5, 10, 20, 40}.
// Paper 000 Table 1 (a 2009 desktop, w = 20): HC4 0.52 ms, BC3 1.02 ms,
// BC4 0.58 ms, 3B-BC4 1400 ms. Counters report the work per contraction.
#include <benchmark/benchmark.h>

#include "algorithms/registry.h"
#include "problems/chain/chain.h"

namespace icp {
namespace {

void ContractChain(benchmark::State& state, const AlgorithmInfo* info) {
  ChainParams p;
  p.w = static_cast<int>(state.range(0));
  const Step step = MakeChainStep(p, 7);
  const ConstraintSystem& csp = step.views.csp->csp;
  auto contractor = info->contractor({}, csp);
  WorkCounters work;
  double area = 0;
  ContractContext context;
  for (auto _ : state) {
    Box box = csp.domains();
    ContractContext context;
    work += contractor->Contract(box, context).work;
    benchmark::DoNotOptimize(box);
    area = box[3 * p.w].Width() * box[3 * p.w + 1].Width();
  }
  auto per_iteration = [](std::int64_t n) {
    return benchmark::Counter(static_cast<double>(n), benchmark::Counter::kAvgIterations);
  };
  state.counters["revise_calls"] = per_iteration(work.revise_calls);
  state.counters["inner_calls"] = per_iteration(work.inner_calls);
  state.counters["newton_steps"] = per_iteration(work.newton_steps);
  state.counters["bisections"] = per_iteration(work.bisections);
  state.counters["last_xy_area_m2"] = area;
}

const bool kRegistered = [] {
  for (const AlgorithmInfo& info : Algorithms()) {
    if (info.test_only || info.contractor == nullptr) continue;
    auto* b = benchmark::RegisterBenchmark(("chain/" + info.name).c_str(), ContractChain, &info);
    b->ArgName("w")->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace
}  // namespace icp
