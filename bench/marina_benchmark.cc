// The marina issue's speed targets (thesis 003 ch. 6), on the full default
// drive of marina-sonar (about 1190 steps, 600 m):
//   BM_MarinaSetMembership   q-relaxed, paved (epsilon 2 m), as a filter that
//                            restarts globally when its track is lost
//                            (target: the whole run <= 60 s on 2 cores)
//   BM_MarinaParticleFilter  the particle filter, 600 particles (target:
//                            <= 10 s)
// Arg: the problem's start (0 known, 1 unknown). Times the estimator's
// steps and the problem's simulation together, as the harness's wall time.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "algorithms/registry.h"
#include "problems/registry.h"

namespace icp {
namespace {

void RunDrive(benchmark::State& state, const std::string& algorithm, const ParamMap& params) {
  const ParamMap problem_params = {{"start", state.range(0) ? "unknown" : "known"}};
  int steps = 0;
  for (auto _ : state) {
    std::unique_ptr<Problem> problem = FindProblem("marina-sonar").make(problem_params, 1);
    std::unique_ptr<Estimator> estimator = FindAlgorithm(algorithm).make(params, 1);
    Step step;
    steps = 0;
    while (problem->Next(&step)) {
      benchmark::DoNotOptimize(estimator->Step(step.views, StopCondition()));
      ++steps;
    }
  }
  state.counters["steps"] = steps;
}

void BM_MarinaSetMembership(benchmark::State& state) {
  RunDrive(state, "q-relaxed", {{"mode", "pave"}, {"epsilon", "2"}, {"outlier_share", "0.3"}});
}
BENCHMARK(BM_MarinaSetMembership)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_MarinaParticleFilter(benchmark::State& state) {
  RunDrive(state, "particle-filter", {{"particles", "600"}});
}
BENCHMARK(BM_MarinaParticleFilter)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace icp
