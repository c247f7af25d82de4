// A run's parameters without the values that are their plugin's defaults
// (spec.h): the spelling keys, progress lines and the page show.
#include <string>

#include "algorithms/registry.h"
#include "harness/spec.h"
#include "problems/registry.h"

namespace icp {

ParamMap NonDefaultParams(const ParamMap& defaults, const ParamMap& params) {
  ParamMap out;
  for (const auto& [key, value] : params) {
    const auto it = defaults.find(key);
    if (it == defaults.end() || it->second != value) out[key] = value;
  }
  return out;
}

namespace {
// The current defaults of a plugin's parameters ({} for one not registered).
template <class Registry>
ParamMap DefaultsOf(const Registry& registry, const std::string& name) {
  ParamMap out;
  for (const auto& info : registry)
    if (info.name == name)
      for (const ParamInfo& p : info.params(info.name)) out[p.name] = p.default_value;
  return out;
}
}  // namespace

ParamMap AlgorithmDefaults(const std::string& name) { return DefaultsOf(Algorithms(), name); }
ParamMap ProblemDefaults(const std::string& name) { return DefaultsOf(Problems(), name); }

RunSpec WithoutDefaults(RunSpec spec) {
  spec.algorithm_params = NonDefaultParams(AlgorithmDefaults(spec.algorithm), spec.algorithm_params);
  spec.problem_params = NonDefaultParams(ProblemDefaults(spec.problem), spec.problem_params);
  return spec;
}

}  // namespace icp
