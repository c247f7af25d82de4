// libFuzzer target: ReadMarinaLog on an arbitrary CSV text. The documented
// answer to a bad log is std::invalid_argument; anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "problems/marina_sonar/marina_sonar.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    icp::ReadMarinaLog(in, "<fuzz>");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
