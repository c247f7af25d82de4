// The problem registry: one explicit table (problems/registry.cc), one line
// per plugin, read by the CLI, the harness and the docs.
#ifndef ICPBENCH_PROBLEMS_REGISTRY_H_
#define ICPBENCH_PROBLEMS_REGISTRY_H_

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/params.h"
#include "problems/problem.h"

namespace icp {

using ProblemFactory = std::unique_ptr<Problem> (*)(const ParamMap&, std::uint64_t seed);

struct ProblemInfo {
  std::string name;
  std::string description;
  ProblemFactory make;  // throws ParamError on bad parameters
  std::vector<ParamInfo> (*params)(const std::string& owner);
  void (*validate)(const std::string& owner, const ParamMap& values);  // throws ParamError
  std::vector<View> views;  // what the problem offers to algorithms
};

const std::vector<ProblemInfo>& Problems();
// Throws std::invalid_argument listing the known names if there is none.
const ProblemInfo& FindProblem(const std::string& name);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_REGISTRY_H_
