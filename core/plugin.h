// The plugin interface: a shared library that `icpbench --plugin LIB.so`
// loads adds algorithms and problems to the executable's registries
// (algorithms/registry.h, problems/registry.h) through ONE entry point,
//
//   extern "C" int icpbench_register_v1(icp::PluginRegistrar* registrar);
//
// which returns 0 on success. A complete example, built out of the tree
// against an installed icpbench: examples/plugin/.
//
// A plugin is compiled against the installed headers (CMake target
// icpbench::plugin) but links none of icpbench's code: every icp:: symbol it
// uses (the registries among them) is resolved when it is loaded, from the
// icpbench executable, which exports them. So there is one registry, and
// the plugin must be built from the same icpbench version as the executable
// that loads it: these C++ types are not a stable ABI.
#ifndef ICPBENCH_CORE_PLUGIN_H_
#define ICPBENCH_CORE_PLUGIN_H_

#include <string>

namespace icp {

// Complete in algorithms/registry.h and problems/registry.h, which a plugin
// includes for what it registers; core needs only their names.
struct AlgorithmInfo;
struct ProblemInfo;

// What an entry point registers through. Implemented by the executable and
// reached through the vtable, so a plugin never links a copy of it.
class PluginRegistrar {
 public:
  // Adds to the registry. Returns false, and the load fails with the reason
  // (a name already taken, a missing name or factory, a name other than
  // lower-case letters, digits, '-' and '_' starting with a letter or digit,
  // at most 64 characters), when it cannot; the entry point may stop there
  // or go on, the load fails either way.
  virtual bool AddAlgorithm(AlgorithmInfo info) = 0;
  virtual bool AddProblem(ProblemInfo info) = 0;
  // Why the entry point is about to return nonzero, for the error message.
  virtual void SetError(std::string message) = 0;

 protected:
  ~PluginRegistrar() = default;  // owned by the loader, never by a plugin
};

}  // namespace icp

// The entry point's name, for dlsym.
#define ICPBENCH_PLUGIN_ENTRY_POINT "icpbench_register_v1"

// Declared here so that a plugin's definition is checked against it; exported
// even from a library built with -fvisibility=hidden.
extern "C" __attribute__((visibility("default"))) int icpbench_register_v1(
    icp::PluginRegistrar* registrar);

#endif  // ICPBENCH_CORE_PLUGIN_H_
