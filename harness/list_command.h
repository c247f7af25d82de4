// `icpbench list algorithms|problems [--format text|json]`: the registries.
#ifndef ICPBENCH_HARNESS_LIST_COMMAND_H_
#define ICPBENCH_HARNESS_LIST_COMMAND_H_

#include <string>

namespace icp {

// what: "algorithms" or "problems"; format: "text" or "json". Throws
// std::invalid_argument on anything else.
std::string ListPlugins(const std::string& what, const std::string& format);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_LIST_COMMAND_H_
