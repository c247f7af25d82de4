// GoogleTest parameter names from registry names ("3b-bc4" -> "3b_bc4").
#ifndef ICPBENCH_TESTS_TEST_NAMES_H_
#define ICPBENCH_TESTS_TEST_NAMES_H_

#include <cctype>
#include <string>

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

}  // namespace icp::testing

#endif  // ICPBENCH_TESTS_TEST_NAMES_H_
