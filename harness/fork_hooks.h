// Calls around the fork that starts each sweep worker (harness/worker_pool.cc),
// for a host that must prepare its own state for fork: the Python module
// (python/module_algorithms.cc) takes the GIL and resets the interpreter in
// the child, so a worker may run an estimator written in Python. None by
// default; the command line sets none.
#ifndef ICPBENCH_HARNESS_FORK_HOOKS_H_
#define ICPBENCH_HARNESS_FORK_HOOKS_H_

#include <functional>

namespace icp {

struct ForkHooks {
  std::function<void()> before;           // in the parent, before fork()
  std::function<void()> after_in_parent;  // in the parent, after fork() (whether it failed or not)
  std::function<void()> after_in_child;   // in the worker, first thing
};

// Replaces the hooks (empty functions: none).
void SetForkHooks(ForkHooks hooks);
const ForkHooks& CurrentForkHooks();

}  // namespace icp

#endif  // ICPBENCH_HARNESS_FORK_HOOKS_H_
