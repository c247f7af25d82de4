// A plugin whose entry point fails, with a reason (tests/plugin_test.cc).
#include "core/plugin.h"

extern "C" int icpbench_register_v1(icp::PluginRegistrar* registrar) {
  registrar->SetError("the fixture always fails");
  return 3;
}
