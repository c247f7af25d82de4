// The marina-sonar problem under extreme and malformed input (issue 31): a
// map image is bounded in size before it is decoded; every speed and time
// step in range drives the route, and the rest is rejected with the rule.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "problems/marina_sonar/marina_map.h"
#include "problems/marina_sonar/marina_sonar.h"
#include "problems/registry.h"

namespace icp {
namespace {

const MarinaMap& ShippedMap() {
  static const MarinaMap map = LoadMarinaMap(ShippedMarinaMapPath());
  return map;
}

std::string TempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("marina_inputs_test_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

// Writes bytes to path and the shipped frame beside it (path's .yaml).
void WriteMap(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
  WriteMapFrame(MarinaMapFrame(), MapFramePath(path), "test");
}

void RemoveMap(const std::string& path) {
  std::filesystem::remove(path);
  std::filesystem::remove(MapFramePath(path));
}

// A valid 1-bit PNG of rows x cols pixels, one of them a wall: small on
// disk whatever its size.
std::string BilevelPng(int rows, int cols) {
  cv::Mat image(rows, cols, CV_8UC1, cv::Scalar(0));
  image.at<unsigned char>(rows / 2, cols / 2) = 255;
  std::vector<unsigned char> bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_BILEVEL, 1}));
  return std::string(bytes.begin(), bytes.end());
}

// The PNG signature and an IHDR chunk declaring width x height (1-bit grey),
// then nothing: the header alone.
std::string PngHeader(std::uint32_t width, std::uint32_t height) {
  std::string head("\x89PNG\r\n\x1a\n", 8);
  auto be32 = [&head](std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) head += static_cast<char>(v >> shift & 0xff);
  };
  be32(13);
  head += "IHDR";
  be32(width);
  be32(height);
  head += std::string("\x01\x00\x00\x00\x00", 5);
  be32(0);  // CRC, not checked before the size
  return head;
}

std::string LoadError(const std::string& path) {
  try {
    LoadMarinaMap(path);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(loaded)";
}

// --- the map's size ------------------------------------------------------------

TEST(MarinaInputsTest, MapBeyondThePixelLimitIsRejectedBeforeDecoding) {
  // 6000 x 5000 = 3e7 pixels: a valid PNG of a few kilobytes.
  const std::string big = TempPath("big.png");
  WriteMap(big, BilevelPng(5000, 6000));
  const std::string error = LoadError(big);
  EXPECT_NE(error.find("6000 x 5000 = 30000000 pixels, beyond the limit of 25000000"),
            std::string::npos)
      << error;
  EXPECT_THROW(CheckMarinaMap(big), std::invalid_argument);
  RemoveMap(big);
  // 15000 x 15000 declared by the header alone: rejected without reading on.
  const std::string huge = TempPath("huge.png");
  WriteMap(huge, PngHeader(15000, 15000));
  EXPECT_NE(LoadError(huge).find("15000 x 15000 = 225000000 pixels"), std::string::npos)
      << LoadError(huge);
  RemoveMap(huge);
  // At the limit, accepted.
  const std::string edge = TempPath("edge.png");
  WriteMap(edge, BilevelPng(5000, 5000));
  EXPECT_NO_THROW(CheckMarinaMap(edge));
  RemoveMap(edge);
}

TEST(MarinaInputsTest, ValidationRejectsABigMapWithItsLimit) {
  const std::string big = TempPath("validate.png");
  WriteMap(big, PngHeader(15000, 15000));
  const std::string log = TempPath("validate.csv");
  std::ofstream(log) << "step,0,0.5,0,0.02,1.5,0.01,10,10\n";
  try {
    FindProblem("marina-sonar").resolve("marina-sonar", {{"map", big}, {"log", log}});
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("beyond the limit of 25000000"), std::string::npos)
        << e.what();
  }
  RemoveMap(big);
  std::filesystem::remove(log);
}

TEST(MarinaInputsTest, MapMustBeAPng) {
  const std::string bmp = TempPath("map.bmp");
  cv::Mat image(10, 10, CV_8UC1, cv::Scalar(255));
  ASSERT_TRUE(cv::imwrite(bmp, image));
  WriteMapFrame(MarinaMapFrame(), MapFramePath(bmp), "test");
  EXPECT_NE(LoadError(bmp).find("not a PNG map image"), std::string::npos) << LoadError(bmp);
  RemoveMap(bmp);
  for (const std::string& bytes : {std::string(), std::string("\x89PNG\r\n\x1a\n", 8),
                                   PngHeader(0, 10), PngHeader(0x80000000u, 1)})
    EXPECT_THROW(DecodeMapWalls(bytes, "mem"), std::invalid_argument);
  // A truncated image after a good header: undecodable, the documented error.
  const std::string png = BilevelPng(20, 30);
  EXPECT_THROW(DecodeMapWalls(png.substr(0, png.size() / 2), "mem"), std::invalid_argument);
  EXPECT_EQ(DecodeMapWalls(png, "mem").size(), cv::Size(30, 20));
}

TEST(MarinaInputsTest, CheckedBoundsAreTheLoadedMapsBounds) {
  EXPECT_EQ(CheckMarinaMap(ShippedMarinaMapPath()), ShippedMap().bounds);
  const std::string odd = TempPath("odd.png");
  std::ofstream(odd, std::ios::binary) << BilevelPng(7, 13);
  WriteMapFrame(ImageFrame{-3.1, 0.7, 0.3}, MapFramePath(odd), "test");
  EXPECT_EQ(CheckMarinaMap(odd), LoadMarinaMap(odd).bounds);
  RemoveMap(odd);
}

// --- the text files --------------------------------------------------------------

std::string LogError(const std::string& text) {
  std::istringstream in(text);
  try {
    ReadMarinaLog(in, "drive.csv");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(MarinaLogTest, ReaderNamesTheLineAndField) {
  const std::string step = "step,0,0.5,0,0.02,1.5,0.01,100,100\n";
  const std::string ret = "return,0.3,12.5,0.3,0.015,0,,\n";
  auto fails_with = [](const std::string& text, const std::string& what) {
    std::istringstream in(text);
    try {
      ReadMarinaLog(in, "drive.csv");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  fails_with("# nothing\n", "drive.csv: no step rows");
  fails_with(ret, "drive.csv:1: a return before the first step row");
  fails_with(step + "stepp,1\n", "drive.csv:2: unknown row kind 'stepp' (step, return)");
  fails_with("step,0,abc,0,0.02,1.5,0.01,,\n", "drive.csv:1: field 3 (dvl_u): 'abc' is not a finite number");
  fails_with("step,0,0.5,0,0.02,1.5,0.01\n", "drive.csv:1: a step row takes 8 fields after its kind; this one has 6");
  fails_with(step + step, "drive.csv:2: field 2 (t): 0 is not after the previous step's 0");
  fails_with("step,0,0.5,0,-1,1.5,0.01,,\n", "field 5 (dvl_error): -1 must be >= 0");
  fails_with("step,0,0.5,0,0.02,1.5,0.01,3,\n", "truth_x and truth_y must be both given or both empty");
  fails_with(step + "return,0.3,12.5,0.3,0.015,2,,\n", "drive.csv:2: field 6 (outlier): '2' must be 0, 1 or empty");
  fails_with(step + "return,0.3,-1,0.3,0.015,0,,\n", "field 3 (range): -1 must be >= 0");
  fails_with(step + "return,0.3,1e7,0.3,0.015,0,,\n", "field 3 (range): 1e+07 is beyond +-1e+06");
  fails_with(step + "return,0.3,12.5,0.3,0.015,0,1,\n", "hit_x and hit_y must be both given or both empty");
  std::istringstream good("# a log\n" + step + ret + "\nstep,1,0.5,0,0.02,1.5,0.01,,\r\n" + ret);
  const std::vector<MarinaRecord> r = ReadMarinaLog(good, "ok");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_TRUE(r[0].has_truth);
  EXPECT_FALSE(r[1].has_truth);
  ASSERT_EQ(r[1].returns.size(), 1u);
  EXPECT_EQ(r[1].returns[0].range, 12.5);
  EXPECT_TRUE(r[1].returns[0].has_outlier_flag);
  EXPECT_FALSE(r[1].returns[0].has_hit);
}

// A UTF-8 byte-order mark at the start is skipped; file content quoted in a
// message has its control and non-ASCII bytes escaped.
TEST(MarinaInputsTest, LogByteOrderMarkSkippedAndQuotedBytesEscaped) {
  const std::string step = "step,0,0.5,0,0.02,1.5,0.01,10,10\n";
  std::istringstream bom("\xEF\xBB\xBF" + step);
  EXPECT_EQ(ReadMarinaLog(bom, "bom.csv").size(), 1u);
  const std::string nul = LogError(std::string("step,0,0.5\0,0,0.02,1.5,0.01,,\n", 30));
  EXPECT_NE(nul.find("drive.csv:1: field 3 (dvl_u): '0.5\\x00' is not a finite number"),
            std::string::npos)
      << nul;
  const std::string kind = LogError(step + "\x7fret\xc3\xa9,1\n");
  EXPECT_NE(kind.find("unknown row kind '\\x7fret\\xc3\\xa9'"), std::string::npos) << kind;
  const std::string flag = LogError(step + "return,0,1,0.3,0.01,\x02,,\n");
  EXPECT_NE(flag.find("'\\x02' must be 0, 1 or empty"), std::string::npos) << flag;
  // A long field is cut in the message.
  const std::string long_kind = LogError(std::string(1000, 'z') + "\n");
  EXPECT_NE(long_kind.find(std::string(80, 'z') + "...'"), std::string::npos) << long_kind;
  EXPECT_LT(long_kind.size(), 200u);
}

TEST(MarinaInputsTest, FrameByteOrderMarkSkippedAndQuotedBytesEscaped) {
  std::istringstream bom("\xEF\xBB\xBForigin_x: 1\norigin_y: 2\npixel_size: 0.5\n");
  EXPECT_EQ(ReadMapFrame(bom, "frame.yaml").origin_x, 1);
  std::istringstream nul(std::string("origin\0x: 1\n", 12));
  try {
    ReadMapFrame(nul, "frame.yaml");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown key 'origin\\x00x'"), std::string::npos)
        << e.what();
  }
}

// --- the simulator ------------------------------------------------------------

// Each straight step of the drive stays in the water, clear of the walls,
// and the drive reaches the canal's end when it has the steps for it.
void ExpectFollowsTheRoute(double speed, double dt) {
  SCOPED_TRACE("speed " + std::to_string(speed) + " dt " + std::to_string(dt));
  MarinaSonarParams p;
  p.speed = speed;
  p.dt = dt;
  p.returns_per_step = 1;
  // About 600 m of route in steps of at least 0.9 speed dt; a slow drive is
  // cut short to keep the test fast.
  constexpr double kMaxSteps = 20000;
  const double needed = 700 / (0.9 * speed * dt);
  p.steps = static_cast<int>(std::min(needed, kMaxSteps));
  const std::vector<MarinaRecord> drive = SimulateMarinaSonar(p, ShippedMap(), 7);
  ASSERT_FALSE(drive.empty());
  for (std::size_t k = 0; k < drive.size(); ++k) {
    const MarinaRecord& r = drive[k];
    ASSERT_GT(WallDistance(ShippedMap(), r.truth_x, r.truth_y), 2) << "step " << k;
    if (k == 0) continue;
    const MarinaRecord& q = drive[k - 1];
    const double dx = r.truth_x - q.truth_x, dy = r.truth_y - q.truth_y;
    const double length = std::hypot(dx, dy);
    ASSERT_FALSE(CastRay(*ShippedMap().image, q.truth_x, q.truth_y, std::atan2(dy, dx), length))
        << "step " << k << " crosses a wall";
  }
  if (needed <= kMaxSteps) {
    EXPECT_GT(drive.back().truth_x, 380) << "the canal's end not reached";
  }
}

TEST(MarinaInputsTest, EverySpeedAndTimeStepInRangeFollowsTheRoute) {
  // The ends of both ranges and interior values, up to speed x dt = 20 m.
  for (double speed : {0.05, 0.5, 1.0, 2.5, 5.0})
    for (double dt : {0.05, 0.5, 1.0, 4.0, 20 / speed, 40.0})
      if (dt <= 40 && speed * dt <= 20) ExpectFollowsTheRoute(speed, dt);
}

// The turn rate and waypoint radius that make every speed and dt work leave
// the default drive as it was, to the last bit (the values below are those of
// the simulator before the change).
TEST(MarinaInputsTest, DefaultDriveIsUnchanged) {
  const std::vector<MarinaRecord> drive = SimulateMarinaSonar(MarinaSonarParams{}, ShippedMap(), 1);
  ASSERT_EQ(drive.size(), 1188u);
  EXPECT_EQ(drive.back().truth_x, 426.945866334398);
  EXPECT_EQ(drive.back().truth_y, 140.17652037938896);
  EXPECT_EQ(drive.back().heading, -6.341382914085718);
}

TEST(MarinaInputsTest, StepsLongerThanTheCanalIsWideAreRejected) {
  const ProblemInfo& info = FindProblem("marina-sonar");
  // Each range's end works with the other parameter at its default.
  EXPECT_NO_THROW(info.resolve("marina-sonar", {{"dt", "40"}}));
  EXPECT_NO_THROW(info.resolve("marina-sonar", {{"speed", "5"}}));
  EXPECT_THROW(info.resolve("marina-sonar", {{"dt", "60"}}), ParamError);
  for (const auto& [speed, dt] : std::vector<std::pair<std::string, std::string>>{
           {"1", "40"}, {"5", "4.5"}, {"1", "20.5"}}) {
    try {
      info.resolve("marina-sonar", {{"speed", speed}, {"dt", dt}});
      ADD_FAILURE() << "speed " << speed << " dt " << dt << " accepted";
    } catch (const ParamError& e) {
      EXPECT_NE(std::string(e.what()).find("speed x dt <= 20 m"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(info.resolve("marina-sonar", {{"speed", "5"}, {"dt", "4"}}));
  EXPECT_NO_THROW(info.resolve("marina-sonar", {{"speed", "0.05"}, {"dt", "40"}}));
}

}  // namespace
}  // namespace icp
