#include "harness/plugin_loader.h"

#include <dlfcn.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <set>
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

// Names a plugin may register, as the tree's are ("hc4", "3b-bc4",
// "car-track"): they are spec keys, command-line values, parts of a run's
// key and of the one-line progress, so no upper case, separators or control
// characters; not starting with '-' (read as an option).
constexpr std::size_t kMaxNameLength = 64;
constexpr char kNamingRule[] =
    "a name is lower-case letters, digits, '-' and '_', starting with a letter or digit, at most "
    "64 characters";

// The name as a message shows it: quoted, control characters escaped (a
// newline would break the message's line).
std::string Quoted(const std::string& name) {
  std::string out = "'";
  for (char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (byte < 0x20 || byte == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", byte);
      out += hex;
    } else {
      out += c;
    }
  }
  return out + "'";
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
    if (!missing.empty()) return Fail(kind + " " + Quoted(info.name) + " has " + missing);
    if (const std::string rule = NameRuleViolation(info.name); !rule.empty())
      return Fail(kind + " " + Quoted(info.name) + " is not a valid name: " + rule);
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

std::string FileKind(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::directory:
      return "a directory";
    case std::filesystem::file_type::fifo:
      return "a FIFO";
    case std::filesystem::file_type::socket:
      return "a socket";
    case std::filesystem::file_type::character:
      return "a character device";
    case std::filesystem::file_type::block:
      return "a block device";
    default:
      return "not a file a library can be loaded from";
  }
}

}  // namespace

void LoadPlugin(const std::string& path) {
  const auto fail = [&path](const std::string& cause) {
    throw PluginError("plugin " + path + ": " + cause);
  };
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // follows symbolic links
  if (!fs::exists(status)) fail("no such file");
  // dlopen would block on a FIFO (reading it) and fail later on others.
  if (!fs::is_regular_file(status)) fail("not a regular file (" + FileKind(status.type()) + ")");
  // dlopen searches the library path for a name without a slash; a path is
  // a path.
  const std::string absolute = fs::absolute(path).string();
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
  // The same file given again (by any path: dlopen knows it by device and
  // inode and returns the same handle): its names are registered already.
  static std::set<void*> registered;
  if (registered.count(handle) != 0) return;
  using EntryPoint = int (*)(PluginRegistrar*);
  const auto entry = reinterpret_cast<EntryPoint>(dlsym(handle, ICPBENCH_PLUGIN_ENTRY_POINT));
  if (entry == nullptr)
    fail("no entry point: a plugin defines extern \"C\" int " ICPBENCH_PLUGIN_ENTRY_POINT
         "(icp::PluginRegistrar*) (core/plugin.h)");

  Registrar registrar;
  int returned = 0;
  try {
    returned = entry(&registrar);
  } catch (const std::exception& e) {
    fail(ICPBENCH_PLUGIN_ENTRY_POINT " threw: " + std::string(e.what()));
  } catch (...) {
    fail(ICPBENCH_PLUGIN_ENTRY_POINT " threw a non-standard exception");
  }
  // A registration that failed is the cause, whatever the entry point returned.
  if (registrar.failed()) fail(registrar.error());
  if (returned != 0)
    fail(ICPBENCH_PLUGIN_ENTRY_POINT " failed (returned " + std::to_string(returned) + ")" +
         (registrar.error().empty() ? "" : ": " + registrar.error()));
  registered.insert(handle);
}

std::string NameRuleViolation(const std::string& name) {
  const auto allowed = [](char c, bool first) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (!first && (c == '-' || c == '_'));
  };
  bool valid = !name.empty() && name.size() <= kMaxNameLength;
  for (std::size_t i = 0; valid && i < name.size(); ++i) valid = allowed(name[i], i == 0);
  return valid ? "" : kNamingRule;
}

}  // namespace icp
