#include "algorithms/window/window_estimator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <vector>

#include "algorithms/hc4/hc4.h"

namespace icp {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

TEST(CarryIntoTest, PlainComponentsIntersect) {
  EXPECT_EQ(CarryInto(Interval(0, 2), Interval(1, 3), 0), Interval(1, 2));
  EXPECT_TRUE(CarryInto(Interval(0, 1), Interval(2, 3), 0).IsEmpty());
}

TEST(CarryIntoTest, AFullTurnKeepsTheCarriedFrame) {
  // An unknown heading [-pi, pi] removes nothing from a heading carried in
  // another turn of the drive.
  const Interval unknown(-Pi().hi(), Pi().hi());
  EXPECT_EQ(CarryInto(unknown, Interval(7.4, 7.6), kTwoPi), Interval(7.4, 7.6));
}

TEST(CarryIntoTest, ANarrowPeriodicDomainIsIntersectedModuloThePeriod) {
  // fresh [0.1, 0.2] + 2 pi meets carried [6.2, 6.5] in about [6.383, 6.484].
  const Interval out = CarryInto(Interval(0.1, 0.2), Interval(6.2, 6.5), kTwoPi);
  EXPECT_LE(out.lo(), 0.1 + kTwoPi);
  EXPECT_GE(out.hi(), 0.2 + kTwoPi);
  EXPECT_GT(out.lo(), 6.3);
  EXPECT_LT(out.hi(), 6.49);
  EXPECT_TRUE(CarryInto(Interval(0.1, 0.2), Interval(1, 2), kTwoPi).IsEmpty());
}

// A two-state window x[t] = x[t-1] + 1, each x in [-10, 10]: carrying the
// previous result narrows the next window by identity of the states.
Views TwoStateWindow(int t) {
  Views views;
  views.step = t;
  views.space.names = {"x"};
  CspView v;
  Expr a = v.csp.AddVariable("x[" + std::to_string(t - 1) + "]", Interval(-10, 10));
  Expr b = v.csp.AddVariable("x[" + std::to_string(t) + "]", Interval(-10, 10));
  v.csp.AddConstraint(b, Relation::kEq, a + v.csp.Constant(1));
  v.states = {{t - 1, 0}, {t, 0}};
  v.newest = t;
  views.csp = std::move(v);
  return views;
}

TEST(WindowEstimatorTest, CarriesStatesByIdentity) {
  WindowEstimator none(&MakeHC4, {}, Carry::kNone);
  WindowEstimator first(&MakeHC4, {}, Carry::kFirst);
  for (int t = 1; t <= 3; ++t) {
    const Views views = TwoStateWindow(t);
    const Box a = none.Step(views, StopCondition()).estimate->Hull();
    const Box b = first.Step(views, StopCondition()).estimate->Hull();
    EXPECT_EQ(a[0], Interval(-9, 10)) << t;
    // x[t-1] starts from the previous window's x[t-1] = [-11 + t, 10].
    EXPECT_EQ(b[0], Interval(-10 + t, 10)) << t;
  }
}

TEST(WindowEstimatorTest, ReportsTheOldestStatesBoxForPostLocalization) {
  WindowEstimator first(&MakeHC4, {}, Carry::kFirst);
  for (int t = 1; t <= 3; ++t) {
    const StepResult r = first.Step(TwoStateWindow(t), StopCondition());
    EXPECT_EQ(NumberProperty(r.properties, "post_step"), t - 1);
    // x[t-1] = x[t] - 1 with x[t] <= 10, from [-11 + t, 10] (carried).
    EXPECT_EQ(NumberProperty(r.properties, "post_x_lo"), -11 + t) << t;
    EXPECT_EQ(NumberProperty(r.properties, "post_x_hi"), 9) << t;
    EXPECT_FALSE(NumberProperty(r.properties, "window_mean_area"));  // no y
  }
}

// Two planar states, x[1] = x[0] + 1 and y[1] = y[0]: the mean area of the
// window's states is the mean of their x-y boxes' areas.
TEST(WindowEstimatorTest, ReportsTheMeanAreaOfTheWindowsStates) {
  Views views;
  views.step = 1;
  views.space.names = {"x", "y"};
  views.space.x = 0;
  views.space.y = 1;
  CspView v;
  Expr x0 = v.csp.AddVariable("x[0]", Interval(0, 4));
  Expr y0 = v.csp.AddVariable("y[0]", Interval(0, 2));
  Expr x1 = v.csp.AddVariable("x[1]", Interval(2, 10));
  Expr y1 = v.csp.AddVariable("y[1]", Interval(1, 10));
  v.csp.AddConstraint(x1, Relation::kEq, x0 + v.csp.Constant(1));
  v.csp.AddConstraint(y1, Relation::kEq, y0);
  v.states = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
  v.newest = 1;
  views.csp = std::move(v);
  WindowEstimator hc4(&MakeHC4, {}, Carry::kNone);
  const StepResult r = hc4.Step(views, StopCondition());
  // x[0] in [1, 4], y[0] in [1, 2]; x[1] in [2, 5], y[1] in [1, 2].
  EXPECT_EQ(NumberProperty(r.properties, "window_mean_area"), (3.0 * 1 + 3.0 * 1) / 2);
  EXPECT_EQ(NumberProperty(r.properties, "post_y_lo"), 1);
  EXPECT_EQ(NumberProperty(r.properties, "post_x_hi"), 4);
}

TEST(StateRefTest, RobotStatesComeFirstThenLandmarks) {
  const std::vector<StateRef> ordered = {{0, 0}, {0, 1}, {5, 0}, StateRef::Landmark(0, 0),
                                         StateRef::Landmark(0, 5), StateRef::Landmark(3, 0)};
  EXPECT_TRUE(std::is_sorted(ordered.begin(), ordered.end()));
  EXPECT_FALSE(StateRef({0, 0}).is_landmark());
  EXPECT_TRUE(StateRef::Landmark(0, 0).is_landmark());
  EXPECT_NE(StateRef({0, 0}), StateRef::Landmark(0, 0));
}

// A window with the robot's x[t] and, when `sees`, a landmark L observed at
// the offset L - x[t] in `offset`.
Views LandmarkWindow(int t, Interval x, bool sees, Interval offset) {
  Views views;
  views.step = t;
  views.space.names = {"x"};
  CspView v;
  Expr xt = v.csp.AddVariable("x[" + std::to_string(t) + "]", x);
  v.states = {{t, 0}};
  if (sees) {
    Expr landmark = v.csp.AddVariable("L", Interval(-100, 100));
    v.csp.AddConstraint(landmark - xt, offset);
    v.states.push_back(StateRef::Landmark(0, 0));
  }
  v.newest = t;
  views.csp = std::move(v);
  return views;
}

// DIGO's landmark memory: a landmark seen at t = 1 (L in [9, 11]), out of
// view at t = 2, keeps its domain when seen again at t = 3, where it locates
// the robot (x[3] = L - 7 in [2, 4]); without carry, nothing is kept.
TEST(WindowEstimatorTest, KeepsLandmarksAcrossWindowsThatDoNotSeeThem) {
  for (Carry carry : {Carry::kFirst, Carry::kAll, Carry::kNone}) {
    WindowEstimator estimator(&MakeHC4, {}, carry);
    estimator.Step(LandmarkWindow(1, Interval(1), true, Interval(8, 10)), StopCondition());
    estimator.Step(LandmarkWindow(2, Interval(2), false, Interval()), StopCondition());
    const Box x3 = estimator
                       .Step(LandmarkWindow(3, Interval(-100, 100), true, Interval(7)),
                             StopCondition())
                       .estimate->Hull();
    EXPECT_EQ(x3[0], carry == Carry::kNone ? Interval(-100, 93) : Interval(2, 4));
  }
}

TEST(WindowEstimatorTest, ContractorParamsLeaveCarryOut) {
  EXPECT_EQ(ContractorParams({{"carry", "all"}, {"ratio", "0.1"}}), (ParamMap{{"ratio", "0.1"}}));
  EXPECT_THROW(ParseCarry("some"), ParamError);
}

}  // namespace
}  // namespace icp
