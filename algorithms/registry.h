// The algorithm registry: one explicit table (algorithms/registry.cc), one
// line per plugin, plus those a --plugin library adds (RegisterAlgorithm).
// The CLI, the harness, the reports and the figures read plugins, their
// parameters and their display data from here and nowhere else.
#ifndef ICPBENCH_ALGORITHMS_REGISTRY_H_
#define ICPBENCH_ALGORITHMS_REGISTRY_H_

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/estimator.h"
#include "algorithms/window/window_estimator.h"
#include "core/params.h"
#include "core/view.h"

namespace icp {

using EstimatorFactory = std::unique_ptr<Estimator> (*)(const ParamMap&, std::uint64_t seed);
using ParamLister = std::vector<ParamInfo> (*)(const std::string& owner);
// The effective parameters: every declared one, defaults filled in, each in
// its canonical spelling (the run key); throws ParamError on bad values.
using ParamResolver = ParamMap (*)(const std::string& owner, const ParamMap& values);

// How tables and figures show a plugin.
struct Display {
  std::string label;   // "HC4", "3B-BC4"
  int order = 1000;    // tables and legends sort by it, then by name
  std::string colour;  // gnuplot colour, "#rrggbb"
};

struct AlgorithmInfo {
  std::string name;         // registry key, lower case ("hc4", "3b-bc4")
  std::string description;  // one line
  EstimatorFactory make;    // throws ParamError on bad parameters
  ParamLister params;       // declared parameters with their defaults
  ParamResolver resolve;
  View needs = View::kCsp;  // what it needs of a problem
  Display display;
  // For a CSP contractor (`solve`, the property suites, the benchmarks): the
  // contractor alone, from its own parameters (without `carry`).
  ContractorFactory contractor = nullptr;
  // A fault-injection plugin for harness tests: skipped by the property
  // suites, the benchmarks and the default sweeps.
  bool test_only = false;
};

// The entry of a CSP contractor F with parameters P, run as a WindowEstimator.
template <class P, ContractorFactory F>
AlgorithmInfo CspAlgorithm(std::string name, std::string description, Display display) {
  return {std::move(name), std::move(description), &MakeWindowEstimator<P, F>,
          &DefaultParams<WindowParams<P>>, &ResolveParams<WindowParams<P>>, View::kCsp,
          std::move(display), F};
}

// A deque: a registration (a --plugin library, Python) keeps references to
// the algorithms already found valid.
const std::deque<AlgorithmInfo>& Algorithms();
// The algorithm called name; throws std::invalid_argument listing the known
// names if there is none.
const AlgorithmInfo& FindAlgorithm(const std::string& name);
// The factory of the CSP contractor called inner, for an estimator that
// nests one (its parameter owner.inner); throws ParamError naming
// owner.inner when inner is unknown or not a plain CSP contractor.
ContractorFactory InnerContractorFactory(const std::string& owner, const std::string& inner);
// Adds a plugin's algorithm; throws std::invalid_argument if the name is taken.
void RegisterAlgorithm(AlgorithmInfo info);
// A registered algorithm's new one-line description (a Python class
// registered again under its name); throws as FindAlgorithm.
void DescribeAlgorithm(const std::string& name, std::string description);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_REGISTRY_H_
