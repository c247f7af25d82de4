// The relaxed solvers' speed targets (issue: relaxed CSPs), on random lines
// of the plane (algorithms/relaxed/relaxed_testing.h):
//   BM_AccumulatorLines/1000     20 lines, 1000 x 1000 cells (target <= 50 ms on 2 cores)
//   BM_RelaxedIntersectionBoxes  q-relaxed intersection of m 2-D boxes, m up to 10^4
//                                (the exact hull, O(m log m))
//   BM_PolynomialHorner vs BM_PolynomialBruteForce: the Horner scheme (m(m+1)/2
//                                contractions) against the union over all subsets (2^m)
//   BM_LineContractorOnACell     one measurement contractor on one grid cell
#include <benchmark/benchmark.h>

#include "algorithms/relaxed/relaxed_testing.h"
#include "core/accumulate.h"
#include "core/box_polynomial.h"
#include "core/box_polynomial_testing.h"
#include "core/random.h"
#include "core/relaxed_intersection.h"

namespace icp {
namespace {

void BM_AccumulatorLines(benchmark::State& state) {
  const auto c = testing::Lines(1, 20, 7);
  const int cells = static_cast<int>(state.range(0));
  const Grid grid(c.views.measurement_set->prior, 0, 1, cells, cells);
  WorkCounters work;
  for (auto _ : state)
    benchmark::DoNotOptimize(Accumulate(grid, c.views.measurement_set->measurements, StopCondition(), &work));
  state.counters["cells"] = static_cast<double>(cells) * cells;
  state.counters["contractions"] =
      benchmark::Counter(static_cast<double>(work.revise_calls), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_AccumulatorLines)->Arg(250)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RelaxedIntersectionBoxes(benchmark::State& state) {
  const int m = static_cast<int>(state.range(0));
  RandomEngine rng(2);
  std::vector<Box> boxes;
  for (int i = 0; i < m; ++i) {
    const double x = UniformReal(rng, -10, 10), y = UniformReal(rng, -10, 10);
    boxes.push_back(Box{{x - 1, x + 1}, {y - 1, y + 1}});
  }
  for (auto _ : state) benchmark::DoNotOptimize(RelaxedIntersection(boxes, m / 3, 2));
  state.SetComplexityN(m);
}
BENCHMARK(BM_RelaxedIntersectionBoxes)->RangeMultiplier(10)->Range(10, 10000)->Complexity(benchmark::oNLogN);

void BM_PolynomialHorner(benchmark::State& state) {
  const auto c = testing::Lines(3, static_cast<int>(state.range(0)), 2);
  for (auto _ : state)
    benchmark::DoNotOptimize(HornerSortTransform(c.views.measurement_set->prior,
                                                 c.views.measurement_set->measurements, StopCondition()));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_PolynomialHorner)->DenseRange(4, 16, 4)->Arg(64)->Complexity(benchmark::oNSquared);

// Coefficient j as the hull, over the subsets of j measurements, of their
// composition applied to the prior: what the Horner scheme avoids.
void BM_PolynomialBruteForce(benchmark::State& state) {
  const auto c = testing::Lines(3, static_cast<int>(state.range(0)), 2);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        testing::ExpandedSortTransform(c.views.measurement_set->prior, c.views.measurement_set->measurements));
}
BENCHMARK(BM_PolynomialBruteForce)->DenseRange(4, 16, 4);

// One measurement contractor on a grid cell's box, the unit of the
// accumulator's cost: /0 a cell around the line, /1 one its band's edge
// crosses (the backward sweep narrows).
void BM_LineContractorOnACell(benchmark::State& state) {
  const auto c = testing::Lines(1, 1, 0);
  Contractor& line = *c.views.measurement_set->measurements[0];
  const double offset = state.range(0) == 0 ? 0 : 0.05;
  const Box cell{{c.truth[0] + offset - 0.01, c.truth[0] + offset + 0.01},
                 {c.truth[1] + offset - 0.01, c.truth[1] + offset + 0.01}};
  Box box = cell;
  for (auto _ : state) {
    box = cell;
    ContractContext context;
    benchmark::DoNotOptimize(line.Contract(box, context));
  }
}
BENCHMARK(BM_LineContractorOnACell)->Arg(0)->Arg(1);

}  // namespace
}  // namespace icp
