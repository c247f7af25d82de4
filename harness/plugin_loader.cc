#include "harness/plugin_loader.h"

#include <dlfcn.h>

#include <exception>
#include <filesystem>
#include <string>
#include <utility>

#include "algorithms/registry.h"
#include "core/plugin.h"
#include "problems/registry.h"

namespace icp {

namespace {

// What is missing from an entry for the registry to use it ("" if nothing).
template <class Info>
std::string Missing(const Info& info) {
  if (info.name.empty()) return "no name";
  if (info.make == nullptr) return "no factory (make)";
  if (info.params == nullptr) return "no parameter list (params)";
  if (info.resolve == nullptr) return "no parameter resolver (resolve)";
  return "";
}

// Forwards to the registries. Failures are kept, not thrown: an exception
// should not have to cross the plugin's extern "C" entry point.
class Registrar final : public PluginRegistrar {
 public:
  bool AddAlgorithm(AlgorithmInfo info) override {
    return Add("algorithm", std::move(info), &RegisterAlgorithm);
  }
  bool AddProblem(ProblemInfo info) override {
    return Add("problem", std::move(info), &RegisterProblem);
  }
  void SetError(std::string message) override {
    if (error_.empty()) error_ = std::move(message);
  }

  bool failed() const { return failed_; }
  const std::string& error() const { return error_; }

 private:
  template <class Info>
  bool Add(const std::string& kind, Info info, void (*add)(Info)) {
    const std::string missing = Missing(info);
    if (!missing.empty()) return Fail(kind + " '" + info.name + "' has " + missing);
    try {
      add(std::move(info));  // throws std::invalid_argument for a taken name
      return true;
    } catch (const std::exception& e) {
      return Fail(e.what());
    }
  }
  bool Fail(std::string message) {
    failed_ = true;
    SetError(std::move(message));
    return false;
  }

  bool failed_ = false;
  std::string error_;
};

}  // namespace

void LoadPlugin(const std::string& path) {
  const auto fail = [&path](const std::string& cause) {
    throw PluginError("plugin " + path + ": " + cause);
  };
  std::error_code error;
  if (!std::filesystem::exists(path, error)) fail("no such file");
  // dlopen searches the library path for a name without a slash; a path is
  // a path.
  const std::string absolute = std::filesystem::absolute(path).string();
  // RTLD_NOW: a symbol the executable lacks fails the load here, by name,
  // rather than the first run that calls it. Never closed (see the header).
  void* handle = dlopen(absolute.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const std::string cause = dlerror();
    fail("cannot load it: " + cause +
         (cause.find("undefined symbol") != std::string::npos
              ? " (the icpbench executable lacks it: build the plugin against this icpbench)"
              : ""));
  }
  using EntryPoint = int (*)(PluginRegistrar*);
  const auto entry = reinterpret_cast<EntryPoint>(dlsym(handle, ICPBENCH_PLUGIN_ENTRY_POINT));
  if (entry == nullptr)
    fail("no entry point: a plugin defines extern \"C\" int " ICPBENCH_PLUGIN_ENTRY_POINT
         "(icp::PluginRegistrar*) (core/plugin.h)");

  Registrar registrar;
  int status = 0;
  try {
    status = entry(&registrar);
  } catch (const std::exception& e) {
    fail(ICPBENCH_PLUGIN_ENTRY_POINT " threw: " + std::string(e.what()));
  } catch (...) {
    fail(ICPBENCH_PLUGIN_ENTRY_POINT " threw a non-standard exception");
  }
  // A registration that failed is the cause, whatever the entry point returned.
  if (registrar.failed()) fail(registrar.error());
  if (status != 0)
    fail(ICPBENCH_PLUGIN_ENTRY_POINT " failed (returned " + std::to_string(status) + ")" +
         (registrar.error().empty() ? "" : ": " + registrar.error()));
}

}  // namespace icp
