// What a size a user controls (an accumulator's grid, ...) may allocate:
// the memory left under this process's data limit (RLIMIT_DATA, which a
// worker's memory_limit_mb sets; ulimit -d in a shell), so that a size too
// large fails before it is allocated, with the size and the limit in the
// message, instead of deep inside a library with its own wording.
#ifndef ICPBENCH_CORE_MEMORY_BUDGET_H_
#define ICPBENCH_CORE_MEMORY_BUDGET_H_

#include <cstddef>
#include <new>
#include <optional>
#include <string>

namespace icp {

// A std::bad_alloc, so whoever reports running out of memory reports this
// too, that says what needed how much and what the limit left.
class MemoryBudgetError : public std::bad_alloc {
 public:
  explicit MemoryBudgetError(std::string message) : message_(std::move(message)) {}
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  std::string message_;
};

struct MemoryBudget {
  std::size_t limit = 0;      // the data limit, bytes
  std::size_t available = 0;  // what is left of it (the limit minus VmData)
};

// The data limit and what is left of it; nullopt when there is none.
std::optional<MemoryBudget> DataMemoryBudget();

// Throws MemoryBudgetError "<what> needs N MiB, more than the M MiB left of
// this process's data limit of L MiB" when bytes do not fit the budget.
void CheckMemory(std::size_t bytes, const std::string& what,
                 const std::optional<MemoryBudget>& budget = DataMemoryBudget());

// Bytes as MiB, rounded up, for messages.
std::string MiB(std::size_t bytes);

}  // namespace icp

#endif  // ICPBENCH_CORE_MEMORY_BUDGET_H_
