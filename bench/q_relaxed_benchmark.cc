// q-relaxed (mode=contract, q = the true outlier count) against the
// reference fixpoint it must be at least as tight as (IBEX's
// CtcFixPoint(CtcQInter) written plainly: algorithms/q_relaxed/
// q_relaxed_testing.h), one benchmark per measurement set of
// tests/q_relaxed_cases.h (48 line, range and Minibex sets, 8 to 38
// measurements). scripts/bench_qrelaxed.sh runs both and prints the
// median, over the sets, of the reference's time over q-relaxed's.
#include <benchmark/benchmark.h>

#include <string>

#include "algorithms/q_relaxed/q_relaxed.h"
#include "algorithms/q_relaxed/q_relaxed_testing.h"
#include "tests/q_relaxed_cases.h"

namespace icp {
namespace {

const std::vector<testing::QRelaxedCase>& Cases() {
  static const auto* cases = new std::vector<testing::QRelaxedCase>(testing::QRelaxedCases());
  return *cases;
}

void BM_QRelaxed(benchmark::State& state) {
  const testing::QRelaxedCase& c = Cases().at(state.range(0));
  auto solver = MakeQRelaxed({{"q", std::to_string(c.outliers)}, {"auto_q", "false"}, {"filter", "false"}}, 0);
  for (auto _ : state) benchmark::DoNotOptimize(solver->Step(c.views, StopCondition()));
  state.SetLabel(c.name);
}
BENCHMARK(BM_QRelaxed)->DenseRange(0, 47)->Unit(benchmark::kMicrosecond);

void BM_ReferenceFixpoint(benchmark::State& state) {
  const testing::QRelaxedCase& c = Cases().at(state.range(0));
  const MeasurementSetView& set = *c.views.measurement_set;
  for (auto _ : state)
    benchmark::DoNotOptimize(testing::ReferenceQRelaxedFixpoint(set.prior, set.measurements, c.outliers));
  state.SetLabel(c.name);
}
BENCHMARK(BM_ReferenceFixpoint)->DenseRange(0, 47)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace icp
