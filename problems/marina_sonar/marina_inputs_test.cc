// The marina-sonar problem under extreme and malformed input (issue 31):
// every speed and time step in range drives the route, and the rest is
// rejected with the rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "problems/marina_sonar/marina_map.h"
#include "problems/marina_sonar/marina_sonar.h"
#include "problems/registry.h"

namespace icp {
namespace {

const MarinaMap& ShippedMap() {
  static const MarinaMap map = LoadMarinaMap(ShippedMarinaMapPath());
  return map;
}

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
    for (double dt : {0.05, 0.5, 1.0, 4.0, 20 / speed, 60.0})
      if (dt <= 60 && speed * dt <= 20) ExpectFollowsTheRoute(speed, dt);
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
  for (const auto& [speed, dt] : std::vector<std::pair<std::string, std::string>>{
           {"0.5", "60"}, {"5", "4.5"}, {"1", "20.5"}}) {
    try {
      info.resolve("marina-sonar", {{"speed", speed}, {"dt", dt}});
      ADD_FAILURE() << "speed " << speed << " dt " << dt << " accepted";
    } catch (const ParamError& e) {
      EXPECT_NE(std::string(e.what()).find("speed x dt <= 20 m"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(info.resolve("marina-sonar", {{"speed", "5"}, {"dt", "4"}}));
  EXPECT_NO_THROW(info.resolve("marina-sonar", {{"speed", "0.05"}, {"dt", "60"}}));
}

}  // namespace
}  // namespace icp
