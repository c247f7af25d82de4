// The tape's forward and backward sweeps on one car-track constraint
// x_k = x_{k-1} + ds cos(th_{k-1} + dth / 2); and compiling m lines over
// one graph, whose time per line must not grow with m (it once scanned the
// whole graph below each constraint: 100,000 lines took 33 s to compile).
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/tape.h"

namespace icp {
namespace {

ConstraintSystem OdometryConstraint() {
  ConstraintSystem csp;
  Expr xp = csp.AddVariable("xp", {-10, 10});
  Expr thp = csp.AddVariable("thp", {0.1, 0.3});
  Expr xk = csp.AddVariable("xk", {-8, 12});
  Expr ds = csp.Constant(Interval(2.7, 2.8));
  Expr dth = csp.Constant(Interval(0.01, 0.02));
  csp.AddConstraint(xk, Relation::kEq, xp + ds * Cos(thp + dth / 2.0));
  return csp;
}

void BM_TapeForward(benchmark::State& state) {
  ConstraintSystem csp = OdometryConstraint();
  Tape tape(csp.graph(), csp.constraints()[0]);
  std::vector<Interval> slots;
  Box box = csp.domains();
  for (auto _ : state) benchmark::DoNotOptimize(tape.Forward(box, slots));
}
BENCHMARK(BM_TapeForward);

void BM_TapeRevise(benchmark::State& state) {
  ConstraintSystem csp = OdometryConstraint();
  Tape tape(csp.graph(), csp.constraints()[0]);
  std::vector<Interval> slots;
  for (auto _ : state) {
    Box box = csp.domains();
    benchmark::DoNotOptimize(tape.Revise(box, slots));
  }
}
BENCHMARK(BM_TapeRevise);

void BM_CompileLines(benchmark::State& state) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-10, 10});
  Expr y = csp.AddVariable("y", {-10, 10});
  for (int i = 0; i < state.range(0); ++i)
    csp.AddConstraint(std::cos(i) * x + std::sin(i) * y, Relation::kEq, csp.Constant(Interval(0.1, 0.2)));
  for (auto _ : state) benchmark::DoNotOptimize(CompiledSystem(csp));
  state.SetItemsProcessed(state.iterations() * state.range(0));  // per line: flat in m
}
BENCHMARK(BM_CompileLines)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace icp
