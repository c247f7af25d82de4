// A plugin that adds the chain problem under the name PROBLEM_NAME, built
// twice (tests/CMakeLists.txt): as "chain-copy", a new name, and as "chain",
// a name the tree already has (tests/plugin_test.cc).
#include "core/plugin.h"
#include "problems/chain/chain.h"
#include "problems/registry.h"

extern "C" int icpbench_register_v1(icp::PluginRegistrar* registrar) {
  return registrar->AddProblem({PROBLEM_NAME, "the chain problem, from a plugin", &icp::MakeChain,
                                &icp::DefaultParams<icp::ChainParams>,
                                &icp::ResolveParams<icp::ChainParams>, {icp::View::kCsp}})
             ? 0
             : 1;
}
