// A plugin that adds the chain problem under the name in the environment
// variable ICPBENCH_TEST_PLUGIN_NAME (tests/plugin_test.cc tries names the
// registries must refuse).
#include <cstdlib>

#include "core/plugin.h"
#include "problems/chain/chain.h"
#include "problems/registry.h"

extern "C" int icpbench_register_v1(icp::PluginRegistrar* registrar) {
  const char* name = std::getenv("ICPBENCH_TEST_PLUGIN_NAME");
  return registrar->AddProblem({name != nullptr ? name : "", "the chain problem, renamed",
                                &icp::MakeChain, &icp::DefaultParams<icp::ChainParams>,
                                &icp::ResolveParams<icp::ChainParams>, {icp::View::kCsp}})
             ? 0
             : 1;
}
