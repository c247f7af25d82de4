// `icpbench solve FILE --algorithm NAME [--param k=v ...] [--format text|json]
// [--repeat N]`: contracts the initial box of a Minibex file.
#ifndef ICPBENCH_HARNESS_SOLVE_COMMAND_H_
#define ICPBENCH_HARNESS_SOLVE_COMMAND_H_

#include <iosfwd>
#include <string>
#include <vector>

#include "core/box.h"
#include "core/constraint_system.h"
#include "core/contractor.h"

namespace icp {

struct SolveOptions {
  std::string file;
  std::string algorithm = "hc4";
  std::vector<std::string> params;  // "key=value"
  std::string format = "text";      // text | json
  int repeat = 1;
};

struct SolveResult {
  std::string algorithm;
  ConstraintSystem csp;
  Box box;
  ContractSummary summary;
  double time_s = 0;  // median over the repeats
};

// Runs the contraction. Throws std::invalid_argument (bad algorithm,
// parameter or option), ParamError or MinibexError: all are usage errors.
SolveResult Solve(const SolveOptions& options);

// The JSON contract: {"algorithm", "status": "empty"|"nonempty", "box":
// {name: [lo, hi]}, "time_s"}; infinite bounds are null, an empty box is {}.
std::string SolveResultToJson(const SolveResult& result);
std::string SolveResultToText(const SolveResult& result);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_SOLVE_COMMAND_H_
