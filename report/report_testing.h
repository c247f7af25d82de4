// Synthetic runs and Markdown helpers for the tests of the report, the plots
// and the papers (report/report_test.cc, experiments/*/..._test.cc).
#ifndef ICPBENCH_REPORT_REPORT_TESTING_H_
#define ICPBENCH_REPORT_REPORT_TESTING_H_

#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "harness/metrics.h"
#include "harness/run_record.h"

namespace icp::testing {

// A car-track run whose steps take the given solve times (seconds); each
// step's box is [truth - 1, truth + 1] in x and y (area 4 m^2, centred on the
// truth) around a truth on a line.
inline RunRecord MakeRun(const std::string& algorithm, ParamMap algorithm_params,
                         ParamMap problem_params, std::uint64_t seed,
                         const std::vector<double>& times, RunStatus status = RunStatus::kOk,
                         const std::string& reason = "") {
  RunRecord r;
  r.spec.algorithm = algorithm;
  r.spec.algorithm_params = std::move(algorithm_params);
  r.spec.problem = "car-track";
  r.spec.problem_params = std::move(problem_params);
  r.spec.seed = seed;
  r.status = status;
  r.reason = reason;
  if (status != RunStatus::kOk) return r;
  for (std::size_t i = 0; i < times.size(); ++i) {
    StepRecord s;
    s.step = static_cast<int>(i);
    s.status = "fixpoint";
    const double t = static_cast<double>(i);
    s.vars = {{"x", t - 1, t + 1, t}, {"y", -1, 1, 0}, {"theta", -0.1, 0.1, 0}};
    s.contained = 1;
    s.area = 4;
    s.centre_error = 0;
    s.solve_time_s = times[i];
    r.steps.push_back(s);
  }
  r.metrics = ComputeMetrics(r.steps);
  return r;
}

// The run as planned by that experiment of a spec (RunRecord::spec_file).
inline RunRecord InExperiment(RunRecord run, const std::string& experiment) {
  run.spec_file = "specs/test.yaml#" + experiment;
  return run;
}

// A Markdown report without its closing performance profiles (whose rows
// name every configuration), so that a paper's tables can be searched.
inline std::string WithoutProfiles(const std::string& md) {
  return md.substr(0, md.find("## Performance profile"));
}

inline std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The Markdown row whose first cell is first; "" when none.
inline std::string MarkdownRow(const std::string& md, const std::string& first) {
  for (const std::string& line : Lines(md)) {
    if (line.rfind("| " + first + " |", 0) == 0) return line;
  }
  return "";
}

}  // namespace icp::testing

#endif  // ICPBENCH_REPORT_REPORT_TESTING_H_
