#include "core/polar_sighting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/constraint_contractor.h"
#include "core/contractor_algebra.h"
#include "core/random.h"

namespace icp {
namespace {

constexpr double kPi = std::numbers::pi;

// The sighting of (xl, yl) as a contractor over (x, y, theta).
ContractSummary ContractBySighting(Box& pose, double xl, double yl, const PolarObservation& o) {
  FixpointContractor fixpoint(
      std::make_shared<SequenceContractor>(ConstraintContractors(PoseSighting(xl, yl, o, Box(3)))),
      0.001, 100);
  ContractContext context;
  return fixpoint.Contract(pose, context);
}

PolarObservation Reading(double range, double bearing, double range_error, double bearing_error,
                         RandomEngine& rng) {
  return {0, Interval(range + UniformReal(rng, -range_error, range_error)) +
                 Interval(-range_error, range_error),
          Interval(bearing + UniformReal(rng, -bearing_error, bearing_error)) +
              Interval(-bearing_error, bearing_error)};
}

// Every bearing, every heading representative (theta + 2 k pi), bearings
// across atan2's cut behind the robot: the true pose is never removed, and
// the box does shrink.
TEST(PolarSightingTest, KeepsTheTruePoseForEveryBearingAndHeadingRepresentative) {
  RandomEngine rng(7);
  int shrank = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double x = UniformReal(rng, -5, 5), y = UniformReal(rng, -5, 5);
    const double bearing = trial % 3 == 0 ? UniformReal(rng, kPi - 0.05, kPi) * (trial % 2 ? 1 : -1)
                                          : UniformReal(rng, -kPi, kPi);
    const double range = UniformReal(rng, 0.2, 8);
    const int turns = static_cast<int>(UniformInt(rng, -2, 2));
    const double theta = UniformReal(rng, -kPi, kPi) + 2 * kPi * turns;
    const double xl = x + range * std::cos(theta + bearing), yl = y + range * std::sin(theta + bearing);
    const PolarObservation o = Reading(range, bearing, 0.03, 0.02, rng);
    Box pose({Interval(x - 1, x + 1), Interval(y - 1, y + 1), Interval(theta - 0.3, theta + 0.3)});
    const Box before = pose;
    ContractBySighting(pose, xl, yl, o);
    ASSERT_TRUE(pose.Contains({x, y, theta}))
        << "trial " << trial << " bearing " << bearing << " theta " << theta;
    if (pose != before) ++shrank;
  }
  EXPECT_GT(shrank, 2900);
}

TEST(PolarSightingTest, ALandmarkTooFarForTheRangeEmptiesTheBox) {
  Box pose({Interval(0, 0.1), Interval(0, 0.1), Interval(-0.05, 0.05)});
  const PolarObservation o{0, Interval(1.9, 2.1), Interval(-0.02, 0.02)};
  EXPECT_EQ(ContractBySighting(pose, 5, 0, o).status, ContractStatus::kEmpty);
}

TEST(PolarSightingTest, ALandmarkOnTheWrongSideEmptiesTheBox) {
  // Seen ahead (bearing 0) at 2 m, but the landmark is 2 m behind.
  Box pose({Interval(0, 0.1), Interval(0, 0.1), Interval(-0.05, 0.05)});
  const PolarObservation o{0, Interval(1.9, 2.1), Interval(-0.02, 0.02)};
  EXPECT_EQ(ContractBySighting(pose, -2, 0, o).status, ContractStatus::kEmpty);
}

TEST(PolarSightingTest, AFullTurnOfBearingConstrainsOnlyTheRange) {
  Box pose({Interval(-3, 3), Interval(-3, 3), Interval(-1, 1)});
  const PolarObservation o{0, Interval(0.9, 1.1), Interval(-4, 4)};
  ContractBySighting(pose, 0, 0, o);
  EXPECT_EQ(pose[2], Interval(-1, 1));
  EXPECT_LE(pose[0].hi(), 1.1 + 1e-9);
  EXPECT_GE(pose[0].lo(), -1.1 - 1e-9);
}

TEST(PolarSightingTest, WorldBoxAndPredictionHoldTheTruth) {
  RandomEngine rng(3);
  for (int trial = 0; trial < 1000; ++trial) {
    const double x = UniformReal(rng, -5, 5), y = UniformReal(rng, -5, 5);
    const double theta = UniformReal(rng, -10, 10);
    const Box pose({Interval(x - 0.1, x + 0.1), Interval(y - 0.1, y + 0.1),
                    Interval(theta - 0.05, theta + 0.05)});
    const double range = UniformReal(rng, 0.2, 8), bearing = UniformReal(rng, -kPi, kPi);
    const auto world = SightingWorldBox(pose, Reading(range, bearing, 0.03, 0.02, rng));
    EXPECT_TRUE(world[0].Contains(x + range * std::cos(theta + bearing)));
    EXPECT_TRUE(world[1].Contains(y + range * std::sin(theta + bearing)));

    const double rr = 0.04 * UniformReal(rng, 0.99, 1.01), rl = 0.04 * UniformReal(rng, 0.99, 1.01);
    const double track = 0.35 * UniformReal(rng, 0.99, 1.01);
    const double d = UniformReal(rng, 0, 0.5), turn = UniformReal(rng, -0.3, 0.3);
    const double wr = (d + turn * track / 2) / rr, wl = (d - turn * track / 2) / rl;
    WheelOdometry o{Interval(0.0396, 0.0404), Interval(0.0396, 0.0404), Interval(0.3465, 0.3535),
                    Interval(wr - 0.01, wr + 0.01), Interval(wl - 0.01, wl + 0.01)};
    EXPECT_TRUE(OdometryDistance(o).Contains(d));
    EXPECT_TRUE(OdometryTurn(o).Contains(turn));
    const Box next = PredictPose(Box({Interval(x), Interval(y), Interval(theta)}), o);
    EXPECT_TRUE(next.Contains({x + d * std::cos(theta + turn / 2), y + d * std::sin(theta + turn / 2),
                               theta + turn}));
  }
}

// The odometry as constraints keeps the true motion and contracts the
// poses at least as much as PredictPose's forward evaluation.
TEST(PolarSightingTest, WheelOdometryConstraintsKeepTheMotion) {
  ConstraintSystem csp;
  const double wr = 7.6, wl = 7.4;
  WheelOdometry o{Interval(0.0396, 0.0404), Interval(0.0396, 0.0404), Interval(0.346, 0.354),
                  Interval(wr - 0.05, wr + 0.05), Interval(wl - 0.05, wl + 0.05)};
  const Box from({Interval(1, 1.1), Interval(2, 2.1), Interval(0.1, 0.15)});
  std::array<Expr, 3> a = {csp.AddVariable("x0", from[0]), csp.AddVariable("y0", from[1]),
                           csp.AddVariable("t0", from[2])};
  std::array<Expr, 3> b = {csp.AddVariable("x1", Interval()), csp.AddVariable("y1", Interval()),
                           csp.AddVariable("t1", Interval())};
  AddWheelOdometry(csp, a, b, o, "[1]");
  Box box = csp.domains();
  FixpointContractor fixpoint(std::make_shared<SequenceContractor>(ConstraintContractors(csp)),
                              0.001, 100);
  ContractContext context;
  fixpoint.Contract(box, context);
  const Box predicted = PredictPose(from, o);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(predicted[i].IsSubsetOf(box[3 + i]) || box[3 + i].IsSubsetOf(predicted[i])) << i;
    EXPECT_LE(box[3 + i].hi() - box[3 + i].lo(), predicted[i].hi() - predicted[i].lo() + 1e-12) << i;
  }
  const double d = (0.04 * wr + 0.04 * wl) / 2, turn = (0.04 * wr - 0.04 * wl) / 0.35;
  EXPECT_TRUE(box[3].Contains(1.05 + d * std::cos(0.12 + turn / 2)));
  EXPECT_TRUE(box[5].Contains(0.12 + turn));
}

}  // namespace
}  // namespace icp
