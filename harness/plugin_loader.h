// `icpbench --plugin LIB.so`: loads a shared library and lets its entry point
// (core/plugin.h) add algorithms and problems to the registries.
#ifndef ICPBENCH_HARNESS_PLUGIN_LOADER_H_
#define ICPBENCH_HARNESS_PLUGIN_LOADER_H_

#include <stdexcept>
#include <string>

namespace icp {

// A plugin that cannot be loaded: bad input (exit code 2). The message names
// the library and the cause.
class PluginError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Loads the library at path and runs its entry point; throws PluginError if
// the file is missing, not a regular file or not loadable, has no entry
// point, the entry point fails or throws, or it registers a name that is
// taken or breaks the naming rule (core/plugin.h). A library already loaded
// (by any path) is not loaded again. The library stays loaded for the life
// of the process (the registries point into it), and so is inherited by the
// forked workers of `icpbench run`.
void LoadPlugin(const std::string& path);

// What is wrong with a name a plugin (or Python's register_algorithm) gives
// an algorithm, problem or parameter: "" when it follows the naming rule
// (lower-case letters, digits, '-' and '_', starting with a letter or digit,
// at most 64 characters), else the rule.
std::string NameRuleViolation(const std::string& name);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_PLUGIN_LOADER_H_
