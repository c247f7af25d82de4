#include "harness/provenance.h"

#include <unistd.h>

#include <ctime>
#include <fstream>

#include "build_revision.h"

namespace icp {

namespace {
std::string Trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

// The revision of the source tree the binary was built from, written by
// the build (cmake/build_revision.cmake): later commits do not change it.
std::string GitRevision() { return ICPBENCH_BUILD_REVISION; }

std::string CpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  int cores = 0;
  std::string model;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      ++cores;
      if (model.empty()) model = Trim(line.substr(line.find(':') + 2));
    }
  }
  return model.empty() ? "unknown cpu" : model + " x" + std::to_string(cores);
}
}  // namespace

std::string UtcNow() {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

Provenance CurrentProvenance() {
  static const Provenance fixed = [] {
    Provenance p;
    p.git_revision = GitRevision();
    char host[256] = "unknown";
    gethostname(host, sizeof host - 1);
    p.machine = std::string(host) + " (" + CpuModel() + ")";
    p.compiler = ICPBENCH_COMPILER;
    p.flags = ICPBENCH_FLAGS;
    return p;
  }();
  Provenance p = fixed;
  p.date = UtcNow();
  return p;
}

}  // namespace icp
