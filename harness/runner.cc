#include "harness/runner.h"

#include <chrono>
#include <deque>
#include <memory>
#include <ostream>

#include "algorithms/registry.h"
#include "core/memory_budget.h"
#include "harness/environment_error.h"
#include "harness/metrics.h"
#include "harness/step_judges.h"
#include "harness/sweep_recorder.h"
#include "harness/worker_pool.h"
#include "problems/registry.h"

namespace icp {

namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// --- One run -------------------------------------------------------------

}  // namespace

TakenStep TakeStep(Estimator& estimator, View needs, const Step& step, const StopCondition& stop) {
  if (!step.views.Offers(needs))
    throw std::invalid_argument("step " + std::to_string(step.views.step) + " offers no " +
                                std::string(ToString(needs)) + " view");
  TakenStep taken;
  const auto t0 = Clock::now();
  taken.result = estimator.Step(step.views, stop);
  const double solve_time = Seconds(Clock::now() - t0);
  const StepResult& result = taken.result;
  if (!result.estimate) throw InvalidResult("no estimate");
  if (std::string why = InvalidEstimateReason(step.views, *result.estimate); !why.empty())
    throw InvalidResult(why);
  // The store keeps one value per name: the annotation's would replace it.
  for (const Property& p : result.properties)
    for (const Property& a : step.annotations)
      if (p.name == a.name)
        throw InvalidResult("the estimator's property '" + p.name +
                            "' has the name of one of the problem's annotations: rename it");
  taken.record = MeasureStep(step, *result.estimate);
  taken.record.status = std::string(ToString(result.summary.status));
  taken.record.solve_time_s = result.solve_time_s >= 0 ? result.solve_time_s : solve_time;
  return taken;
}

RunRecord ExecuteRun(const RunSpec& spec) {
  std::vector<StepRecord> steps;
  RunRecord record = ExecuteRun(spec, [&](const StepRecord& s) { steps.push_back(s); });
  record.steps = std::move(steps);
  return record;
}

RunRecord ExecuteRun(const RunSpec& spec, const StepSink& sink) {
  RunRecord record;
  MetricsAccumulator metrics;
  StepJudges judges;
  record.spec = spec;
  const auto start = Clock::now();
  int step_index = 0;
  std::unique_ptr<Estimator> estimator;
  try {
    const AlgorithmInfo& algorithm = FindAlgorithm(spec.algorithm);
    std::unique_ptr<Problem> problem = FindProblem(spec.problem).make(spec.problem_params, spec.seed);
    problem->ServeOnly(algorithm.needs);
    estimator = algorithm.make(spec.algorithm_params, spec.seed);
    StopCondition stop = spec.timeout_s > 0
                             ? StopCondition::After(std::chrono::duration<double>(spec.timeout_s))
                             : StopCondition();
    Step step;
    int limit_reached_at = -1;  // the step after which the time limit had passed
    auto timed_out = [&](const std::string& when) {
      record.status = RunStatus::kTimeout;
      record.reason = "time limit of " + FormatDouble(spec.timeout_s) + " s reached " + when;
    };
    while (problem->Next(&step)) {
      // The limit is checked between steps too: an algorithm whose steps are
      // each short never sees it inside one. Only when a step is left to
      // do: a run whose last step ends past the limit is complete.
      if (limit_reached_at >= 0) {
        timed_out("at step " + std::to_string(limit_reached_at));
        break;
      }
      step_index = step.views.step;
      TakenStep taken = TakeStep(*estimator, algorithm.needs, step, stop);
      judges.Judge(step, &taken);
      const StepResult& result = taken.result;
      const StepRecord& r = taken.record;
      sink(r);  // first: a step the sink could not take is not counted
      metrics.Add(r);
      if (stop.ShouldStop()) {
        limit_reached_at = step_index;
        // A step the limit cut short is incomplete, last or not.
        if (result.summary.status == ContractStatus::kStopped) {
          timed_out("during step " + std::to_string(step_index));
          break;
        }
      }
    }
  } catch (const InvalidResult& e) {
    record.status = RunStatus::kFailed;
    record.reason = "invalid result at step " + std::to_string(step_index) + ": " + e.what();
  } catch (const std::bad_alloc& e) {
    record.status = RunStatus::kFailed;
    // A size checked before it was allocated says what needed how much.
    const auto* budget = dynamic_cast<const MemoryBudgetError*>(&e);
    record.reason = "out of memory at step " + std::to_string(step_index) +
                    (budget != nullptr ? std::string(": ") + budget->what() : "") +
                    (spec.memory_limit_mb > 0
                         ? " (the worker's limit is memory_limit_mb = " +
                               FormatDouble(spec.memory_limit_mb) + " MiB: raise it in the spec)"
                         : "");
  } catch (const std::exception& e) {
    record.status = RunStatus::kFailed;
    record.reason = std::string("exception: ") + e.what();
  } catch (...) {
    record.status = RunStatus::kFailed;
    record.reason = "exception of unknown type";
  }
  if (estimator) record.properties = estimator->RunProperties();
  for (Property& p : judges.RunProperties()) record.properties.push_back(std::move(p));
  record.wall_time_s = Seconds(Clock::now() - start);
  record.metrics = metrics.Finish(spec.seed);
  // As a worker that died says (WorkerPool): what failed did not lose the steps before it.
  if (record.status == RunStatus::kFailed && spec.record_steps && record.metrics.steps > 0)
    record.reason += "; the " + std::to_string(record.metrics.steps) + " steps finished before are kept";
  return record;
}

SweepSummary RunSweep(const Spec& spec, const RunnerOptions& options, std::ostream& progress_out,
                      bool terminal) {
  SweepRecorder recorder(spec, options, progress_out, terminal);
  std::deque<PlannedRun>& queue = recorder.queue();
  WorkerPool pool(options.out_dir, options.jobs, options.kill_grace_s, {recorder.lock_fd()});
  const StopSignals signals;
  auto record = [&](FinishedRun& f) { recorder.Record(f.record, f.run.experiment, f.step_file); };
  bool start_failed = false;  // pipe() or fork() failed: start nothing more
  // The bar is drawn from the start and then every second, so that a sweep
  // of long runs shows its time and what is in flight before one ends.
  auto last_drawn = std::chrono::steady_clock::time_point();
  while ((!queue.empty() && !start_failed) || pool.Running() > 0) {
    if (StopSignals::Caught() != 0) break;
    while (pool.HasRoom() && !queue.empty() && !start_failed) {
      if (!queue.front().skip_reason.empty()) {
        recorder.RecordSkipped(queue.front());
      } else if (!pool.Start(queue.front())) {  // not recorded: it never started
        start_failed = true;
        break;
      }
      queue.pop_front();
    }
    if (std::chrono::steady_clock::now() - last_drawn >= std::chrono::seconds(1)) {
      recorder.progress().InFlight(recorder.summary(), std::to_string(pool.Running()));
      last_drawn = std::chrono::steady_clock::now();
    }
    pool.Poll(100, record);
  }
  // A run that finished before the stop is kept, not counted as in flight.
  if (StopSignals::Caught() != 0) pool.CollectExited(record);
  SweepSummary summary = recorder.summary();
  if (StopSignals::Caught() != 0) {
    summary.interrupted_by = StopSignals::Caught();
    summary.stopped = pool.Running();
    pool.Stop();
  }
  recorder.progress().Finish();
  if (start_failed && summary.interrupted_by == 0)
    ThrowErrno(pool.start_error() + " (" + std::to_string(summary.Finished()) + " finished runs kept, " +
                   std::to_string(queue.size()) + " not started)",
               pool.start_errno());
  return summary;
}

}  // namespace icp
