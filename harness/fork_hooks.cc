#include "harness/fork_hooks.h"

#include <utility>

namespace icp {
namespace {
ForkHooks& Hooks() {
  static ForkHooks hooks;
  return hooks;
}
}  // namespace

void SetForkHooks(ForkHooks hooks) { Hooks() = std::move(hooks); }
const ForkHooks& CurrentForkHooks() { return Hooks(); }

}  // namespace icp
