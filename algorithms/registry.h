// The algorithm registry: one explicit table (algorithms/registry.cc), one
// line per plugin. The CLI, the harness and the docs list plugins from here
// and nowhere else.
#ifndef ICPBENCH_ALGORITHMS_REGISTRY_H_
#define ICPBENCH_ALGORITHMS_REGISTRY_H_

#include <memory>
#include <string>
#include <vector>

#include "core/constraint_system.h"
#include "core/contractor.h"
#include "core/params.h"
#include "core/view.h"

namespace icp {

using AlgorithmFactory = std::unique_ptr<Contractor> (*)(const ParamMap&, const ConstraintSystem&);
using ParamLister = std::vector<ParamInfo> (*)(const std::string& owner);
using ParamValidator = void (*)(const std::string& owner, const ParamMap& values);

struct AlgorithmInfo {
  std::string name;         // registry key, lower case ("hc4", "3b-bc4")
  std::string description;  // one line
  AlgorithmFactory make;    // throws ParamError on bad parameters
  ParamLister params;       // declared parameters with their defaults
  ParamValidator validate;  // throws ParamError on bad parameters
  View view = View::kCsp;   // what it needs of a problem
  // A fault-injection plugin for harness tests: skipped by the property
  // suites, the benchmarks and the default sweeps.
  bool test_only = false;
};

const std::vector<AlgorithmInfo>& Algorithms();
// The algorithm called name; throws std::invalid_argument listing the known
// names if there is none.
const AlgorithmInfo& FindAlgorithm(const std::string& name);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_REGISTRY_H_
