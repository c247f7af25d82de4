#include "core/memory_budget.h"

#include <sys/resource.h>

#include <fstream>

namespace icp {

namespace {
// VmData of /proc/self/status, bytes: what RLIMIT_DATA is checked against
// (private writable mappings, Linux >= 4.7); 0 when unreadable.
std::size_t DataInUse() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmData:", 0) == 0) return std::stoull(line.substr(7)) * 1024;
  return 0;
}
}  // namespace

std::optional<MemoryBudget> DataMemoryBudget() {
  rlimit limit{};
  if (getrlimit(RLIMIT_DATA, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  MemoryBudget budget;
  budget.limit = static_cast<std::size_t>(limit.rlim_cur);
  const std::size_t used = DataInUse();
  budget.available = used < budget.limit ? budget.limit - used : 0;
  return budget;
}

std::string MiB(std::size_t bytes) {
  return std::to_string((bytes + (std::size_t{1} << 20) - 1) >> 20);
}

void CheckMemory(std::size_t bytes, const std::string& what,
                 const std::optional<MemoryBudget>& budget) {
  if (!budget || bytes <= budget->available) return;
  // What is left rounds down, so that it never reads as enough.
  throw MemoryBudgetError(what + " needs " + MiB(bytes) + " MiB, more than the " +
                          std::to_string(budget->available >> 20) +
                          " MiB left of this process's data limit of " + MiB(budget->limit) +
                          " MiB");
}

}  // namespace icp
