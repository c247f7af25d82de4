// The problem registry: one explicit table (problems/registry.cc), one line
// per plugin, plus those a --plugin library adds (RegisterProblem); read by
// the CLI, the harness and the docs.
#ifndef ICPBENCH_PROBLEMS_REGISTRY_H_
#define ICPBENCH_PROBLEMS_REGISTRY_H_

#include <cstdint>
#include <deque>
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
  // The effective parameters (defaults filled in, canonical spelling: the
  // run key); throws ParamError, or std::invalid_argument for a bad file.
  ParamMap (*resolve)(const std::string& owner, const ParamMap& values);
  std::vector<View> offers;  // the views of its steps
  // What a user should know of these effective parameters before the runs
  // (a log longer than `steps` is cut), or empty; optional.
  std::string (*note)(const ParamMap& resolved) = nullptr;
};

// A deque: a registration keeps references to the problems already found
// valid.
const std::deque<ProblemInfo>& Problems();
// Throws std::invalid_argument listing the known names if there is none.
const ProblemInfo& FindProblem(const std::string& name);
// Every step of problem `name` made with params and seed, in order (tests
// and tools); throws as its factory does.
std::vector<Step> ProblemSteps(const std::string& name, const ParamMap& params, std::uint64_t seed);
// Adds a plugin's problem; throws std::invalid_argument if the name is taken.
void RegisterProblem(ProblemInfo info);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_REGISTRY_H_
