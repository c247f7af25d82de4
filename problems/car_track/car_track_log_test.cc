// The car-track CSV log: writing and reading back, the shipped example, and
// the reader's checks of every line and column (part of car_track_test).
#include "problems/car_track/car_track.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "problems/car_track/car_track_testing.h"

namespace icp {
namespace {

using testing::ErrorOf;
using testing::ExpectSameSteps;
using testing::Make;
using testing::RunHC4;

constexpr double kPi = std::numbers::pi;

std::vector<CarTrackRecord> ReadLogText(const std::string& text) {
  std::istringstream in(text);
  return ReadCarTrackLog(in, "log.csv");
}

TEST(CarTrackTest, CsvRoundTripGivesTheSameCsps) {
  CarTrackParams p;
  p.steps = 120;
  p.w = 6;
  p.gps_period = 2;
  const std::vector<CarTrackRecord> simulated = SimulateCarTrack(p, 9);
  std::stringstream csv;
  WriteCarTrackLog(simulated, csv, "seed 9\nsecond comment line");
  EXPECT_EQ(csv.str().rfind("# seed 9\n# second comment line\nt,odo_left_ticks,", 0), 0u);
  const std::vector<CarTrackRecord> read = ReadCarTrackLog(csv, "memory");
  ASSERT_EQ(read.size(), simulated.size());
  CarTrackProblem from_sim(p, simulated), from_log(p, read);
  ExpectSameSteps(from_sim, from_log);
}

// The shipped example: 50 rows of SimulateCarTrack with the default
// parameters, steps = 50 and seed 1. Regenerate with
//   ICPBENCH_UPDATE_GOLDEN=1 car_track_test --gtest_filter=*ShippedLog*
TEST(CarTrackTest, ShippedLogIsTheSimulatorsDriveAndKeepsTheTruth) {
  const std::string path = std::string(ICPBENCH_CAR_TRACK_DATA) + "/example_log.csv";
  CarTrackParams p;
  p.steps = 50;
  if (std::getenv("ICPBENCH_UPDATE_GOLDEN") != nullptr) {
    std::ofstream out(path);
    WriteCarTrackLog(SimulateCarTrack(p, 1), out,
                     "car-track example log: SimulateCarTrack, default parameters, steps=50, "
                     "seed 1\n(problems/car_track/README.md describes the format)");
  }
  CarTrackProblem from_sim(p, SimulateCarTrack(p, 1));
  auto from_log = Make({{"log", path}}, 12345);  // the seed plays no part
  EXPECT_EQ(from_log->NumSteps(), 50);
  ExpectSameSteps(from_sim, *from_log);
  RunHC4(*Make({{"log", path}, {"w", "10"}}, 0), [&](const Step& step, const Box& box) {
    ASSERT_EQ(step.truth.size(), box.size());
    ASSERT_TRUE(box.Contains(step.truth)) << "step " << step.views.step;
  });
  // steps caps the rows used.
  EXPECT_EQ(Make({{"log", path}, {"steps", "20"}}, 0)->NumSteps(), 20);
}

TEST(CarTrackTest, LogWithoutTruthOrFixesAndWithWrappedHeading) {
  const std::vector<CarTrackRecord> r = ReadLogText(
      "# a comment\n"
      "\n"
      "gyro_dtheta, t, odo_left_ticks, odo_right_ticks, gps_x, gps_y, gps_ex, gps_ey,"
      " truth_x, truth_y, truth_theta\r\n"
      "0, 0, 10, 12, 1, 2, 3, 3, 0, 0, 3.1\r\n"
      "0.1, 0.2, 150, 160, , , , , 2.7, 0.3, -3.1\n"
      "0.1, 0.4, 290, 305, 6, 0.5, 3, 4, , , \n"
      "0.1, 0.6, 430, 450, 6, 0.5, 3, 4, 8, 1, 9.6\n");
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[1].t, 0.2);
  EXPECT_EQ(r[1].gyro_dtheta, 0.1);
  EXPECT_EQ(r[1].odo_right_ticks, 160);
  EXPECT_FALSE(r[1].has_gps);
  EXPECT_TRUE(r[2].has_gps);
  EXPECT_EQ(r[2].gps_ey, 4);
  EXPECT_FALSE(r[2].has_truth);
  EXPECT_EQ(r[0].truth_theta, 3.1);
  EXPECT_NEAR(r[1].truth_theta, 2 * kPi - 3.1, 1e-12);  // unwrapped
  EXPECT_NEAR(r[3].truth_theta, 9.6 - 2 * kPi, 1e-12);  // within pi of the last known
  // Steps whose window holds a row without truth carry no truth.
  CarTrackParams p;
  p.w = 1;
  CarTrackProblem problem(p, r);
  Step step;
  std::vector<std::size_t> truth_sizes, csp_truth_sizes;
  while (problem.Next(&step)) {
    truth_sizes.push_back(step.truth.size());
    csp_truth_sizes.push_back(step.csp_truth.size());
  }
  EXPECT_EQ(truth_sizes, (std::vector<std::size_t>{3, 3, 0, 3}));
  EXPECT_EQ(csp_truth_sizes, (std::vector<std::size_t>{3, 6, 0, 0}));
  // Truth columns are optional.
  EXPECT_FALSE(ReadLogText("t,odo_left_ticks,odo_right_ticks,gyro_dtheta,gps_x,gps_y,gps_ex,"
                           "gps_ey\n0,0,0,0,,,,\n")[0]
                   .has_truth);
}

// A turn of more than pi between rows (a robot spinning 3.5 rad per row) is
// unwrapped along the gyro, not to the nearest turn, across a row without
// truth too (it was refused as a glitch).
TEST(CarTrackTest, TurnsOfMoreThanPiPerRowUnwrapAlongTheGyro) {
  std::string text = "t,odo_left_ticks,odo_right_ticks,gyro_dtheta,gps_x,gps_y,gps_ex,gps_ey,"
                     "truth_x,truth_y,truth_theta\n";
  const int rows = 8;
  for (int k = 0; k < rows; ++k) {
    const double heading = 3.5 * k;
    char wrapped[32];
    std::snprintf(wrapped, sizeof wrapped, "%.17g", std::remainder(heading, 2 * kPi));
    text += std::to_string(k) + ",0,0," + (k == 0 ? "0" : "3.5") + ",,,,," +
            (k == 4 ? ",," : std::string("0,0,") + wrapped) + "\n";
  }
  const std::vector<CarTrackRecord> r = ReadLogText(text);
  ASSERT_EQ(r.size(), static_cast<std::size_t>(rows));
  for (int k = 0; k < rows; ++k)
    if (k != 4) EXPECT_NEAR(r[k].truth_theta, 3.5 * k, 1e-9) << "row " << k;
}

TEST(CarTrackTest, BadLogsFailWithLineAndColumn) {
  const std::string header =
      "t,odo_left_ticks,odo_right_ticks,gyro_dtheta,gps_x,gps_y,gps_ex,gps_ey\n";
  struct Case {
    std::string text;
    std::string message;
  };
  const Case cases[] = {
      {"", "log.csv: no header line"},
      {header, "log.csv: no data rows"},
      {"t,odo_left_ticks,odo_right_ticks,gps_x,gps_y,gps_ex,gps_ey\n",
       "log.csv:1: header lacks column 'gyro_dtheta'"},
      {header.substr(0, header.size() - 1) + ",speed\n", "log.csv:1: header column 9: unknown"},
      {"t,t\n", "log.csv:1: header: column 't' repeated"},
      {header + "0,0,0,0,,,,\n0.2,1.5,2,0,,,,\n",
       "log.csv:3: column 2 (odo_left_ticks): '1.5' is not an integer"},
      {header + "0,0,0,abc,,,,\n", "log.csv:2: column 4 (gyro_dtheta): 'abc' is not a finite"},
      {header + "0,0,0,nan,,,,\n", "column 4 (gyro_dtheta): 'nan' is not a finite"},
      {header + "0,0,0,0,1,2,,\n", "log.csv:2: gps_x, gps_y, gps_ex, gps_ey columns must be"},
      {header + "0,0,0,0,1,2,0,1\n", "log.csv:2: column 7 (gps_ex): 0 must be > 0"},
      {header + "0,0,0,0,,,\n", "log.csv:2: the row has 7 fields, the header 8"},
      {header + "0,0,0,1e-400,,,,\n", "log.csv:2: column 4 (gyro_dtheta): '1e-400' is out of the range"},
      {header + "0,0,0,0,,,,\n0,1,1,0,,,,\n", "log.csv:3: column 1 (t): 0 is not after"},
      {header + ",0,0,0,,,,\n", "log.csv:2: column 1 (t): '' is not a finite"},
      // A wrapped counter: the int64 difference would overflow.
      {header + "0,9223372036854775807,0,0,,,,\n0.2,-9223372036854775808,0,0,,,,\n",
       "log.csv:3: column 2 (odo_left_ticks): -9223372036854775808 ticks after "
       "9223372036854775807 on the previous row: a step of more than 2^31 ticks"},
      {header + "0,0,0,0,,,,\n0.2,0,2147483649,0,,,,\n",
       "log.csv:3: column 3 (odo_right_ticks): 2147483649 ticks after 0"},
      {header + "0,0,-5,0,,,,\n0.2,0,-2147483654,0,,,,\n",
       "log.csv:3: column 3 (odo_right_ticks): -2147483654 ticks after -5"},
  };
  for (const Case& c : cases) {
    const std::string error = ErrorOf([&] { ReadLogText(c.text); });
    EXPECT_NE(error.find(c.message), std::string::npos)
        << "log:\n"
        << c.text << "error: " << error << "\nexpected: " << c.message;
  }
}

// A UTF-8 byte-order mark before the header is skipped; file content quoted
// in a message has its control and non-ASCII bytes escaped (a NUL byte
// would cut the message short on a terminal).
TEST(CarTrackTest, ByteOrderMarkSkippedAndQuotedBytesEscaped) {
  const std::string header =
      "t,odo_left_ticks,odo_right_ticks,gyro_dtheta,gps_x,gps_y,gps_ex,gps_ey\n";
  EXPECT_EQ(ReadLogText("\xEF\xBB\xBF" + header + "0,0,0,0,,,,\n").size(), 1u);
  const char kRow[] = "0,0,0,1\0x,,,,\n";  // a NUL inside the fourth field
  const std::string row(kRow, sizeof kRow - 1);
  const std::string nul = ErrorOf([&] { ReadLogText(header + row); });
  EXPECT_NE(nul.find("column 4 (gyro_dtheta): '1\\x00x' is not a finite"), std::string::npos)
      << nul;
  const std::string column = ErrorOf([&] { ReadLogText("t,\x01\xff\n"); });
  EXPECT_NE(column.find("unknown column '\\x01\\xff'"), std::string::npos) << column;
  // A BOM anywhere else is content, quoted escaped.
  const std::string late = ErrorOf([&] { ReadLogText("# c\n\xEF\xBB\xBFt\n"); });
  EXPECT_NE(late.find("'\\xef\\xbb\\xbft'"), std::string::npos) << late;
}

TEST(CarTrackTest, NonPhysicalValuesFailWithLineAndColumn) {
  const std::string header =
      "t,odo_left_ticks,odo_right_ticks,gyro_dtheta,gps_x,gps_y,gps_ex,gps_ey,truth_x,truth_y,"
      "truth_theta\n";
  const std::pair<std::string, std::string> cases[] = {
      {"1e13,0,0,0,,,,,,,\n", "log.csv:2: column 1 (t): 1e+13 is beyond +-1e+12 s"},
      {"0,0,0,-2e6,,,,,,,\n", "log.csv:2: column 4 (gyro_dtheta): -2e+06 is beyond +-1e+06 rad"},
      {"0,0,0,0,2e9,0,1,1,,,\n", "log.csv:2: column 5 (gps_x): 2e+09 is beyond +-1e+09 m"},
      {"0,0,0,0,0,-2e9,1,1,,,\n", "log.csv:2: column 6 (gps_y): "},
      {"0,0,0,0,0,0,1e10,1,,,\n", "log.csv:2: column 7 (gps_ex): 1e+10 is beyond"},
      {"0,0,0,0,0,0,1,1e10,,,\n", "log.csv:2: column 8 (gps_ey): "},
      {"0,0,0,0,,,,,1e300,0,0\n", "log.csv:2: column 9 (truth_x): 1e+300 is beyond"},
      {"0,0,0,0,,,,,0,1e300,0\n", "log.csv:2: column 10 (truth_y): "},
      {"0,0,0,0,,,,,0,0,0\n0.2,0,0,0,,,,,0,0,1e300\n",
       "log.csv:3: column 11 (truth_theta): 1e+300 is beyond +-1e+06 rad"},
      // Within the bound but 3 rad off the gyro's 0.
      {"0,0,0,0,,,,,0,0,0\n0.2,0,0,0,,,,,0,0,3\n",
       "log.csv:3: column 11 (truth_theta): 3 turns the heading by 3 rad since the previous row "
       "(unwrapped) but the gyro by 0: more than pi/2 apart"},
  };
  for (const auto& [rows, message] : cases) {
    const std::string text = header + rows;  // (clang 14 cannot capture a structured binding)
    const std::string error = ErrorOf([&] { ReadLogText(text); });
    EXPECT_NE(error.find(message), std::string::npos)
        << "rows:\n" << rows << "error: " << error << "\nexpected: " << message;
  }
  // The bounds themselves are accepted.
  EXPECT_EQ(ReadLogText(header + "1e12,0,0,-1e6,-1e9,1e9,1e9,1e9,1e9,-1e9,1e6\n").size(), 1u);
  // One glitch in a simulated drive is caught on its own line, whether it is
  // far out (it would corrupt every later unwrapped heading) or just wrong.
  CarTrackParams p;
  p.steps = 20;
  for (const double glitch : {1e300, 2000 * kPi + 2, 2.0}) {
    std::vector<CarTrackRecord> records = SimulateCarTrack(p, 1);
    records[10].truth_theta += glitch;
    std::ostringstream csv;
    WriteCarTrackLog(records, csv);
    const std::string error = ErrorOf([&] { ReadLogText(csv.str()); });
    EXPECT_NE(error.find("log.csv:12: column 11 (truth_theta): "), std::string::npos)
        << glitch << ": " << error;
  }
}

TEST(CarTrackTest, TickCountsNeverOverflow) {
  const std::string header =
      "t,odo_left_ticks,odo_right_ticks,gyro_dtheta,gps_x,gps_y,gps_ex,gps_ey\n";
  // 2^31 ticks in one step is the documented limit, near the int64 ends too.
  EXPECT_EQ(ReadLogText(header + "0,9223372036854775807,-9223372036854775808,0,,,,\n"
                                 "0.2,9223372034707292159,-9223372034707292160,0,,,,\n")
                .size(),
            2u);
  // Records not read from a log: the difference is checked, not wrapped.
  CarTrackParams p;
  std::vector<CarTrackRecord> records(2);
  records[1].t = 0.2;
  records[0].odo_left_ticks = std::numeric_limits<std::int64_t>::max();
  records[1].odo_left_ticks = std::numeric_limits<std::int64_t>::min();
  const std::string error = ErrorOf([&] { MeasureCarTrack(p, records); });
  EXPECT_NE(error.find("overflows a 64-bit difference"), std::string::npos) << error;
  // A simulated count beyond int64 (a tiny wheel) is a parameter error.
  EXPECT_THROW(Make({{"wheel_radius", "1e-12"}, {"radius_error", "0"}, {"ticks_per_rev", "1e9"},
                     {"steps", "3"}},
                    1),
               ParamError);
}

}  // namespace
}  // namespace icp
