// libFuzzer target: ParseMinibex on arbitrary text. A MinibexError is the
// documented answer to bad input; anything else (another exception, a crash,
// a sanitizer report, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/minibex_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    icp::ParseMinibex(text, "<fuzz>");
  } catch (const icp::MinibexError&) {
  }
  return 0;
}
