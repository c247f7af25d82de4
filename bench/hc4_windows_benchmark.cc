// µs per contraction of single car-track windows from scratch (bench/
// chain_windows.h: w = 5, 10, 20, the oldest heading with a prior or cold),
// for HC4 and 3B-BC4: the numbers issue 32 pins. Each iteration contracts
// the next of the 12 windows, so the time is the mean over the windows.
//   build/bench/hc4_windows_benchmark --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "algorithms/registry.h"
#include "bench/chain_windows.h"

namespace icp {
namespace {

void ContractWindows(benchmark::State& state, const char* algorithm, bool heading_known) {
  const std::vector<ConstraintSystem> windows =
      ChainWindows(static_cast<int>(state.range(0)), heading_known);
  std::vector<std::unique_ptr<Contractor>> contractors;
  for (const ConstraintSystem& csp : windows)
    contractors.push_back(FindAlgorithm(algorithm).contractor({}, csp));
  std::size_t i = 0;
  std::int64_t revise_calls = 0;
  for (auto _ : state) {
    Box box = windows[i].domains();
    ContractContext context;
    revise_calls += contractors[i]->Contract(box, context).work.revise_calls;
    benchmark::DoNotOptimize(box);
    if (++i == windows.size()) i = 0;
  }
  state.counters["revise_calls"] =
      benchmark::Counter(static_cast<double>(revise_calls), benchmark::Counter::kAvgIterations);
}

const bool kRegistered = [] {
  for (const char* algorithm : {"hc4", "3b-bc4"}) {
    for (bool known : {true, false}) {
      const std::string name = std::string(algorithm) + "/" + HeadingName(known);
      auto* b = benchmark::RegisterBenchmark(name.c_str(), ContractWindows, algorithm, known);
      b->ArgName("w")->Unit(benchmark::kMicrosecond);
      for (int w : kChainWindowLengths) b->Arg(w);
    }
  }
  return true;
}();

}  // namespace
}  // namespace icp
