// libFuzzer target: ParseSpec on arbitrary YAML text. A SpecError is the
// documented answer to a bad spec; anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "harness/spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    icp::ParseSpec(text, "<fuzz>");
  } catch (const icp::SpecError&) {
  }
  return 0;
}
