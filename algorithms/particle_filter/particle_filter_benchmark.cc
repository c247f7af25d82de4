// Time per step of particle-filter on the car track (a 500-step drive, GPS
// at every step), and of MRPT's particle filter with the same particle
// count and models (mrpt_filter.h) when MRPT was found at configure time;
// without MRPT its benchmark is not registered. Counter `step_time`: seconds
// per step. particle-filter's step includes what the harness records (the
// region, the covariance, the estimate); MRPT's, its executeOn and the mean.
#include <benchmark/benchmark.h>

#include <vector>

#include "algorithms/particle_filter/particle_filter.h"
#include "problems/registry.h"

#ifdef ICPBENCH_HAVE_MRPT
#include "algorithms/particle_filter/mrpt_filter.h"
#endif

namespace icp {
namespace {

const std::vector<Step>& Drive() {
  static const std::vector<Step> steps = ProblemSteps("car-track", {{"steps", "500"}}, 1);
  return steps;
}

void SetStepTime(benchmark::State& state) {
  state.counters["step_time"] =
      benchmark::Counter(static_cast<double>(state.iterations() * Drive().size()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_ParticleFilterCarTrack(benchmark::State& state) {
  const std::vector<Step>& steps = Drive();
  std::uint64_t seed = 1;
  for (auto _ : state) {
    std::unique_ptr<Estimator> filter = MakeParticleFilter(
        {{"particles", std::to_string(state.range(0))}, {"inject", "0"}}, seed++);
    for (const Step& s : steps) benchmark::DoNotOptimize(filter->Step(s.views, StopCondition()));
  }
  SetStepTime(state);
}
BENCHMARK(BM_ParticleFilterCarTrack)->Arg(600)->Unit(benchmark::kMillisecond);

#ifdef ICPBENCH_HAVE_MRPT
void BM_MrptParticleFilterCarTrack(benchmark::State& state) {
  const std::vector<Step>& steps = Drive();
  std::uint64_t seed = 1;
  for (auto _ : state) {
    MrptFilter filter(static_cast<int>(state.range(0)), 0.5, seed++);
    for (const Step& s : steps) benchmark::DoNotOptimize(filter.Step(*s.views.probabilistic));
  }
  SetStepTime(state);
}
BENCHMARK(BM_MrptParticleFilterCarTrack)->Arg(600)->Unit(benchmark::kMillisecond);
#endif

}  // namespace
}  // namespace icp
