#include "problems/car_track/car_track.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "algorithms/registry.h"
#include "core/tape.h"
#include "problems/registry.h"

namespace icp {
namespace {

constexpr double kPi = std::numbers::pi;

std::unique_ptr<Problem> Make(const ParamMap& params, std::uint64_t seed) {
  return FindProblem("car-track").make(params, seed);
}

// Runs HC4 on every step, feeding each contracted box back as the next
// step's previous_result; calls visit(step, contracted box) after each.
void RunHC4(Problem& problem, const std::function<void(const Step&, const Box&)>& visit) {
  const AlgorithmInfo& hc4 = FindAlgorithm("hc4");
  Step step;
  Box result;
  bool first = true;
  while (problem.Next(first ? nullptr : &result, &step)) {
    first = false;
    result = step.csp.domains();
    ContractContext context;
    hc4.make({}, step.csp)->Contract(result, context);
    visit(step, result);
  }
}

double NewestArea(const Step& step, const Box& box) {
  return box[step.reported[step.x].index].Width() * box[step.reported[step.y].index].Width();
}

double NewestHeadingWidth(const Step& step, const Box& box) {
  return box[step.reported[2].index].Width();
}

// Message of the std::invalid_argument thrown by f, or "" if none.
std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::vector<CarTrackRecord> ReadLogText(const std::string& text) {
  std::istringstream in(text);
  return ReadCarTrackLog(in, "log.csv");
}

TEST(CarTrackTest, TruthInsideEveryMeasurementIntervalOverALap) {
  for (std::uint64_t seed : {1, 2, 3, 4}) {
    CarTrackParams p;
    std::vector<CarTrackRecord> records = SimulateCarTrack(p, seed);
    ASSERT_EQ(records.size(), 2000u);
    std::vector<CarTrackMeasurement> m = MeasureCarTrack(p, records);
    for (std::size_t k = 1; k < records.size(); ++k) {
      const CarTrackRecord& r = records[k];
      const CarTrackRecord& prev = records[k - 1];
      const double ds = std::hypot(r.truth_x - prev.truth_x, r.truth_y - prev.truth_y);
      const double dth = r.truth_theta - prev.truth_theta;
      ASSERT_TRUE(m[k].ds.Contains(ds)) << "seed " << seed << " step " << k << " " << m[k].ds;
      ASSERT_TRUE(m[k].dth.Contains(dth)) << "seed " << seed << " step " << k << " " << m[k].dth;
      ASSERT_TRUE(m[k].x.Contains(r.truth_x)) << "seed " << seed << " step " << k;
      ASSERT_TRUE(m[k].y.Contains(r.truth_y)) << "seed " << seed << " step " << k;
      // Bounded, not trivially wide: ds within a few cm, the GPS box 5 m.
      ASSERT_LT(m[k].ds.Width(), 0.15);
      ASSERT_LT(m[k].x.Width(), 5.01);
    }
  }
}

TEST(CarTrackTest, OneLapIsAboutFiveAndAHalfKilometresAndCloses) {
  CarTrackParams p;
  std::vector<CarTrackRecord> r = SimulateCarTrack(p, 7);
  double length = 0;
  for (std::size_t k = 1; k < r.size(); ++k)
    length += std::hypot(r[k].truth_x - r[k - 1].truth_x, r[k].truth_y - r[k - 1].truth_y);
  EXPECT_NEAR(length, 5560, 60);
  // Four left corners: the heading turns once (the speed varies, so the car
  // is near, not at, the start after 2000 steps).
  EXPECT_NEAR(r.back().truth_theta - r.front().truth_theta, 2 * kPi, 0.1);
  EXPECT_LT(std::hypot(r.back().truth_x, r.back().truth_y), 100);
}

TEST(CarTrackTest, WheelTicksGiveTheLapsDistanceAndTurnWithoutSlip) {
  // Without slip and with exact radii the cumulative counts are off by less
  // than one tick, so dead reckoning over the whole lap is nearly exact: the
  // rear-axle centre travels the mean of the wheels, and they differ by
  // track_width times the turn.
  CarTrackParams p;
  p.odo_slip = 0;
  p.radius_error = 0;
  const std::vector<CarTrackRecord> r = SimulateCarTrack(p, 5);
  double distance = 0;
  for (std::size_t k = 1; k < r.size(); ++k)
    distance += std::hypot(r[k].truth_x - r[k - 1].truth_x, r[k].truth_y - r[k - 1].truth_y);
  const double metres_per_tick = 2 * kPi * p.wheel_radius / p.ticks_per_rev;
  const double left = (r.back().odo_left_ticks - r.front().odo_left_ticks) * metres_per_tick;
  const double right = (r.back().odo_right_ticks - r.front().odo_right_ticks) * metres_per_tick;
  EXPECT_NEAR((left + right) / 2, distance, metres_per_tick);
  EXPECT_NEAR((right - left) / p.track_width, r.back().truth_theta - r.front().truth_theta,
              2 * metres_per_tick / p.track_width);
}

TEST(CarTrackTest, TruthInsideEveryInitialBoxAndSatisfiesEveryConstraint) {
  for (std::uint64_t seed : {1, 2, 3}) {
    auto problem = Make({{"w", "5"}, {"steps", seed == 1 ? "2000" : "300"}}, seed);
    Step step;
    std::vector<Interval> slots;
    while (problem->Next(nullptr, &step)) {
      ASSERT_EQ(step.truth.size(), static_cast<std::size_t>(step.csp.num_variables()));
      ASSERT_TRUE(step.csp.domains().Contains(step.truth))
          << "seed " << seed << " step " << step.index;
      Box point;
      for (double t : step.truth) point.push_back(Interval(t));
      CompiledSystem sys(step.csp);
      for (int c = 0; c < sys.num_constraints(); ++c) {
        const Interval value = sys.tape(c).Forward(point, slots);
        ASSERT_FALSE(Intersect(value, sys.tape(c).range()).IsEmpty())
            << "seed " << seed << " step " << step.index << ": " << step.csp.ConstraintToString(c);
      }
    }
  }
}

TEST(CarTrackTest, WindowGrowsToWStepsThenSlides) {
  const int w = 4;
  auto problem = Make({{"w", std::to_string(w)}, {"steps", "10"}}, 3);
  EXPECT_EQ(problem->NumSteps(), 10);
  Step step;
  int k = 0;
  while (problem->Next(nullptr, &step)) {
    const int n = std::min(k, w);
    EXPECT_EQ(step.index, k);
    EXPECT_EQ(step.csp.constraints().size(), 3u * n) << "step " << k;
    ASSERT_EQ(step.csp.num_variables(), 3 * (n + 1));
    // Absolute step numbers, oldest first; the newest state is reported.
    const int oldest = k - n;
    EXPECT_EQ(step.csp.names()[0], "x[" + std::to_string(oldest) + "]");
    EXPECT_EQ(step.csp.names()[3 * n + 2], "th[" + std::to_string(k) + "]");
    ASSERT_EQ(step.reported.size(), 3u);
    EXPECT_EQ(step.reported[0].name, "x");
    EXPECT_EQ(step.reported[0].index, 3 * n);
    EXPECT_EQ(step.reported[2].index, 3 * n + 2);
    EXPECT_EQ(step.x, 0);
    EXPECT_EQ(step.y, 1);
    ++k;
  }
  EXPECT_EQ(k, 10);
  EXPECT_FALSE(problem->Next(nullptr, &step));
}

TEST(CarTrackTest, HC4KeepsTheTruthOverALapWithTheResultFedBack) {
  auto problem = Make({}, 11);
  double area_sum = 0;
  int steps = 0;
  RunHC4(*problem, [&](const Step& step, const Box& box) {
    ASSERT_TRUE(step.csp.domains().Contains(step.truth)) << "step " << step.index;
    ASSERT_FALSE(box.IsEmpty()) << "step " << step.index;
    ASSERT_TRUE(box.Contains(step.truth)) << "step " << step.index;
    if (step.index >= 100) {
      area_sum += NewestArea(step, box);
      ++steps;
    }
  });
  EXPECT_EQ(steps, 1900);
  // The window narrows the position below the 25 m^2 GPS box.
  EXPECT_LT(area_sum / steps, 20);
}

TEST(CarTrackTest, PreviousResultNarrowsTheCarriedStates) {
  auto problem = Make({{"w", "3"}, {"steps", "3"}}, 5);
  Step step;
  ASSERT_TRUE(problem->Next(nullptr, &step));
  Box result = step.csp.domains();
  result[0] = Interval(step.truth[0] - 0.01, step.truth[0] + 0.01);
  result[2] = Interval(step.truth[2] - 0.01, step.truth[2] + 0.01);
  ASSERT_TRUE(problem->Next(&result, &step));
  EXPECT_EQ(step.csp.domains()[0], result[0]);
  EXPECT_EQ(step.csp.domains()[2], result[2]);
  EXPECT_GT(step.csp.domains()[3].Width(), 1);  // the new state: its GPS box
  // A box of the wrong size is a caller's bug; an empty one means the track
  // was lost: the carried states fall back to their measurements.
  Box wrong(4);
  EXPECT_NE(ErrorOf([&] { problem->Next(&wrong, &step); }).find("previous_result has 4"),
            std::string::npos);
  Box lost(6);
  lost.SetEmpty();
  ASSERT_TRUE(problem->Next(&lost, &step));
  EXPECT_FALSE(step.csp.domains().IsEmpty());
  EXPECT_TRUE(step.csp.domains().Contains(step.truth));
}

TEST(CarTrackTest, GpsOutageGrowsTheBoxAndKeepsTheTruth) {
  const ParamMap params = {{"steps", "400"}, {"outage_start", "200"}, {"outage_length", "100"}};
  std::vector<double> area(400);
  bool outage_state_unbounded = true;
  RunHC4(*Make(params, 2), [&](const Step& step, const Box& box) {
    ASSERT_TRUE(box.Contains(step.truth)) << "step " << step.index;
    area[step.index] = NewestArea(step, box);
    if (step.index >= 200 && step.index < 300)
      outage_state_unbounded =
          outage_state_unbounded && !step.csp.domains()[step.reported[0].index].IsBounded();
  });
  EXPECT_TRUE(outage_state_unbounded);
  EXPECT_GT(area[299], 4 * area[199]);  // dead reckoning drifts
  EXPECT_TRUE(std::isfinite(area[299]));
  EXPECT_LT(area[350], area[299]);  // GPS back
  // With a fix every 5th step the box stays bounded, and smaller than at the
  // end of the outage.
  RunHC4(*Make({{"steps", "400"}, {"gps_period", "5"}}, 2), [&](const Step& step, const Box& box) {
    ASSERT_TRUE(box.Contains(step.truth)) << "step " << step.index;
    ASSERT_LT(NewestArea(step, box), area[299]) << "step " << step.index;
  });
}

TEST(CarTrackTest, UnknownStartHeadingIsNarrowedByHC4) {
  // HC4 is local: each step's constraints see one displacement against two
  // GPS boxes, so the heading narrows most when GPS is tight.
  for (const char* gps_error : {"2.5", "0.5"}) {
    double width = 0;
    RunHC4(*Make({{"steps", "200"}, {"gps_error", gps_error}}, 4),
           [&](const Step& step, const Box& box) {
             ASSERT_TRUE(box.Contains(step.truth)) << "step " << step.index;
             if (step.index == 0) {
               EXPECT_NEAR(step.csp.domains()[2].Width(), 2 * kPi, 1e-9);
             }
             width = NewestHeadingWidth(step, box);
           });
    EXPECT_LT(width, std::string(gps_error) == "0.5" ? 0.6 : kPi) << "gps_error " << gps_error;
  }
  // Known start heading: ± 0.1 rad from the start.
  auto problem = Make({{"heading_known", "true"}}, 4);
  Step step;
  ASSERT_TRUE(problem->Next(nullptr, &step));
  EXPECT_NEAR(step.csp.domains()[2].Width(), 0.2, 1e-9);
  EXPECT_TRUE(step.csp.domains().Contains(step.truth));
}

TEST(CarTrackTest, SameSeedSameDriveOtherSeedOtherDrive) {
  CarTrackParams p;
  p.steps = 50;
  std::ostringstream a, b, c;
  WriteCarTrackLog(SimulateCarTrack(p, 1), a);
  WriteCarTrackLog(SimulateCarTrack(p, 1), b);
  WriteCarTrackLog(SimulateCarTrack(p, 2), c);
  EXPECT_EQ(a.str(), b.str());
  EXPECT_NE(a.str(), c.str());
}

void ExpectSameSteps(Problem& a, Problem& b) {
  Step sa, sb;
  while (a.Next(nullptr, &sa)) {
    ASSERT_TRUE(b.Next(nullptr, &sb));
    ASSERT_EQ(sa.csp.domains(), sb.csp.domains()) << "step " << sa.index;
    ASSERT_EQ(sa.csp.constraints().size(), sb.csp.constraints().size());
    for (std::size_t c = 0; c < sa.csp.constraints().size(); ++c)
      ASSERT_EQ(sa.csp.ConstraintToString(c), sb.csp.ConstraintToString(c));
    ASSERT_EQ(sa.truth, sb.truth);
  }
  EXPECT_FALSE(b.Next(nullptr, &sb));
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
    ASSERT_TRUE(box.Contains(step.truth)) << "step " << step.index;
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
  std::vector<std::size_t> truth_sizes;
  while (problem.Next(nullptr, &step)) truth_sizes.push_back(step.truth.size());
  EXPECT_EQ(truth_sizes, (std::vector<std::size_t>{3, 6, 0, 0}));
  // Truth columns are optional.
  EXPECT_FALSE(ReadLogText("t,odo_left_ticks,odo_right_ticks,gyro_dtheta,gps_x,gps_y,gps_ex,"
                           "gps_ey\n0,0,0,0,,,,\n")[0]
                   .has_truth);
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
      {header + "0,0,0,0,,,\n", "log.csv:2: 7 fields, the header has 8"},
      {header + "0,0,0,0,,,,\n0,1,1,0,,,,\n", "log.csv:3: column 't': 0 is not after"},
      {header + ",0,0,0,,,,\n", "log.csv:2: column 1 (t): '' is not a finite"},
  };
  for (const Case& c : cases) {
    const std::string error = ErrorOf([&] { ReadLogText(c.text); });
    EXPECT_NE(error.find(c.message), std::string::npos)
        << "log:\n"
        << c.text << "error: " << error << "\nexpected: " << c.message;
  }
}

TEST(CarTrackTest, RegistryRejectsBadParameters) {
  const ProblemInfo& info = FindProblem("car-track");
  EXPECT_THROW(info.make({{"w", "0"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"gps_period", "0"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"speed", "-3"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"step_length", "3"}}, 1), ParamError);
  EXPECT_THROW(info.make({{"heading_known", "no"}}, 1), ParamError);
  const std::string radius = ErrorOf([&] {
    info.make({{"radius_error", "0.3"}, {"wheel_radius", "0.3"}}, 1);
  });
  EXPECT_NE(radius.find("car-track.radius_error = 0.3: must be below wheel_radius"),
            std::string::npos)
      << radius;
  EXPECT_THROW(info.validate("car-track", {{"radius_error", "1"}}), ParamError);
  EXPECT_NO_THROW(info.validate("car-track", {{"w", "3"}, {"gps_error", "1"}}));
  const std::string missing = ErrorOf([&] { info.make({{"log", "/nonexistent/log.csv"}}, 1); });
  EXPECT_NE(missing.find("/nonexistent/log.csv: cannot open"), std::string::npos) << missing;
  EXPECT_THROW(info.validate("car-track", {{"log", "/nonexistent/log.csv"}}),
               std::invalid_argument);
  EXPECT_EQ(info.make({{"steps", "30"}}, 1)->NumSteps(), 30);
  EXPECT_EQ(info.views, std::vector<View>{View::kCsp});
  // heading_known needs the truth of the first row.
  CarTrackParams p;
  p.heading_known = true;
  std::vector<CarTrackRecord> records = SimulateCarTrack(p, 1);
  records[0].has_truth = false;
  EXPECT_THROW(CarTrackProblem(p, records), ParamError);
}

}  // namespace
}  // namespace icp
