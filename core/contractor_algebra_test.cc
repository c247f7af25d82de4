#include "core/contractor_algebra.h"

#include <gtest/gtest.h>

#include "core/contractor_testing.h"

#include <memory>

namespace icp {
namespace {

using testing::ClipTo;

SharedContractors Clips(std::initializer_list<Interval> sets) {
  SharedContractors out;
  for (const Interval& s : sets) out.push_back(std::make_shared<ClipTo>(Box{s}));
  return out;
}

Box Apply(Contractor& c, Box box) {
  ContractContext context;
  c.Contract(box, context);
  return box;
}

TEST(ContractorAlgebraTest, QIntersectionKeepsWhatMostPartsKeep) {
  const SharedContractors parts = Clips({{0, 1}, {2, 3}, {0.5, 2.5}});
  const Box x{{-10, 10}};
  QIntersectionContractor q0(parts, 0), q1(parts, 1), q2(parts, 2), q3(parts, 3);
  EXPECT_TRUE(Apply(q0, x).IsEmpty());
  EXPECT_EQ(Apply(q1, x), (Box{{0.5, 2.5}}));  // [0.5, 1] u [2, 2.5]
  EXPECT_EQ(Apply(q2, x), (Box{{0, 3}}));
  EXPECT_EQ(Apply(q3, x), x);
  EXPECT_THROW(QIntersectionContractor(parts, -1), std::invalid_argument);
}

TEST(ContractorAlgebraTest, QZeroIsTheIntersection) {
  const SharedContractors parts = Clips({{-1, 4}, {0, 5}, {-3, 2.5}});
  QIntersectionContractor q0(parts, 0);
  IntersectionContractor all(parts);
  const Box x{{-10, 10}};
  EXPECT_EQ(Apply(q0, x), (Box{{0, 2.5}}));
  EXPECT_EQ(Apply(all, x), Apply(q0, x));
}

TEST(ContractorAlgebraTest, UnionIsTheHullOfTheParts) {
  UnionContractor u(Clips({{0, 1}, {2, 3}, {20, 30}}));
  EXPECT_EQ(Apply(u, Box{{-10, 10}}), (Box{{0, 3}}));
  UnionContractor none(Clips({{20, 30}}));
  EXPECT_TRUE(Apply(none, Box{{-10, 10}}).IsEmpty());
}

TEST(ContractorAlgebraTest, StoppedPartsCountAsTheIdentity) {
  const SharedContractors parts = Clips({{0, 1}, {2, 3}});
  IntersectionContractor all(parts);
  Box box{{-10, 10}};
  ContractContext stopped(StopCondition::After(std::chrono::seconds(0)));
  const ContractSummary s = all.Contract(box, stopped);
  EXPECT_EQ(s.status, ContractStatus::kStopped);
  EXPECT_EQ(box, (Box{{-10, 10}}));
}

TEST(ContractorAlgebraTest, CompositionNestsInsideIntersection) {
  // Prop. 20: C1 o C2 is inside C1 ∩ C2; for these two lines of the plane
  // (x = y and x + y = 2 as thin bands) composition shrinks more.
  auto c1 = std::make_shared<ClipTo>(Box{{0.9, 1.1}, {-10, 10}});
  auto c2 = std::make_shared<ClipTo>(Box{{-10, 10}, {0.9, 1.1}});
  SequenceContractor composed({c2, c1});
  IntersectionContractor both({c1, c2});
  const Box x{{-10, 10}, {-10, 10}};
  const Box a = Apply(composed, x), b = Apply(both, x);
  EXPECT_TRUE(a.IsSubsetOf(b));
  EXPECT_EQ(a, (Box{{0.9, 1.1}, {0.9, 1.1}}));
}

}  // namespace
}  // namespace icp
