// libFuzzer target: the marina map reader from bytes. The input is the frame
// sidecar's text, a NUL byte, then the PNG image's bytes (without a NUL, the
// text alone): ReadMapFrame reads the text, DecodeMapWalls the image (its
// size bounded from the PNG header before decoding), and when both are good
// MakeMarinaMap derives the map as LoadMarinaMap does.
// The documented answer to a bad map is std::invalid_argument; anything
// else is a bug.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "problems/marina_sonar/marina_map.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = input.find('\0');
  const std::string_view text = input.substr(0, nul);
  const std::string_view image = nul == std::string_view::npos ? "" : input.substr(nul + 1);
  std::optional<icp::ImageFrame> frame;
  try {
    std::istringstream in{std::string(text)};
    frame = icp::ReadMapFrame(in, "<fuzz>.yaml");
  } catch (const std::invalid_argument&) {
  }
  cv::Mat walls;
  try {
    walls = icp::DecodeMapWalls(image, "<fuzz>.png");
  } catch (const std::invalid_argument&) {
  }
  if (frame && !walls.empty()) {
    try {
      icp::MakeMarinaMap(walls, *frame);
    } catch (const std::invalid_argument&) {
    }
  }
  return 0;
}
