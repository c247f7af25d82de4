// GoogleTest parameter names from registry names ("3b-bc4" -> "3b_bc4"), and
// the registered algorithms a suite runs over.
#ifndef ICPBENCH_TESTS_TEST_NAMES_H_
#define ICPBENCH_TESTS_TEST_NAMES_H_

#include <cctype>
#include <string>
#include <vector>

#include "algorithms/registry.h"

namespace icp::testing {

struct RegistryName {
  template <class ParamInfo>
  std::string operator()(const ParamInfo& info) const {
    std::string name = info.param;
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
  }
};

// The registered algorithms that need the given view, test-only ones left out.
inline std::vector<std::string> AlgorithmsNeeding(View view) {
  std::vector<std::string> names;
  for (const AlgorithmInfo& a : Algorithms())
    if (!a.test_only && a.needs == view) names.push_back(a.name);
  return names;
}

}  // namespace icp::testing

#endif  // ICPBENCH_TESTS_TEST_NAMES_H_
