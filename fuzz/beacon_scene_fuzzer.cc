// libFuzzer target: ReadBeaconScene on an arbitrary scene text. The
// documented answer to a bad scene is std::invalid_argument; anything else
// is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "problems/beacon_ranges/beacon_ranges.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    icp::ReadBeaconScene(in, "<fuzz>");
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
