#include "core/box_polynomial.h"

#include <gtest/gtest.h>

#include "core/box_polynomial_testing.h"
#include "core/contractor_testing.h"

#include <atomic>
#include <chrono>
#include <memory>

#include "core/random.h"

namespace icp {
namespace {

using testing::ClipTo;
using testing::ExpandedSortTransform;

Box RandomBoxAround(RandomEngine& rng, const std::vector<double>& centre, double spread) {
  Box b(centre.size());
  for (std::size_t d = 0; d < centre.size(); ++d)
    b[d] = Interval(centre[d] - UniformReal(rng, 0, spread), centre[d] + UniformReal(rng, 0, spread));
  return b;
}

TEST(BoxPolynomialTest, ByHandOnIntervals) {
  // Sets [0, 2], [1, 3], [5, 6] on x = [-10, 10] (Fig. 5.1): degree 1 is
  // their hull, degree 2 the overlap [1, 2], degree 3 nothing.
  const SharedContractors cs = {std::make_shared<ClipTo>(Box{{0, 2}}),
                                std::make_shared<ClipTo>(Box{{1, 3}}),
                                std::make_shared<ClipTo>(Box{{5, 6}})};
  const std::vector<Box> p = HornerSortTransform(Box{{-10, 10}}, cs, StopCondition());
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0], (Box{{-10, 10}}));
  EXPECT_EQ(p[1], (Box{{0, 6}}));
  EXPECT_EQ(p[2], (Box{{1, 2}}));
  EXPECT_TRUE(p[3].IsEmpty());
}

TEST(BoxPolynomialTest, EqualsTheBruteForceUnionWhenTheSetsShareAPoint) {
  // When every subset's intersection is non-empty, clipping distributes over
  // the hull and the Horner scheme is exactly the expanded polynomial.
  RandomEngine rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = UniformInt(rng, 1, 7);
    SharedContractors cs;
    for (int i = 0; i < n; ++i)
      cs.push_back(std::make_shared<ClipTo>(RandomBoxAround(rng, {1.0, -2.0}, 3)));
    const Box x{{-10, 10}, {-10, 10}};
    EXPECT_EQ(HornerSortTransform(x, cs, StopCondition()), ExpandedSortTransform(x, cs)) << trial;
  }
}

TEST(BoxPolynomialTest, EnclosesTheBruteForceUnionAlways) {
  RandomEngine rng(4);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = UniformInt(rng, 1, 7);
    SharedContractors cs;
    for (int i = 0; i < n; ++i)
      cs.push_back(std::make_shared<ClipTo>(
          RandomBoxAround(rng, {UniformReal(rng, -5, 5), UniformReal(rng, -5, 5)}, 2)));
    const Box x{{-10, 10}, {-10, 10}};
    const std::vector<Box> horner = HornerSortTransform(x, cs, StopCondition());
    const std::vector<Box> brute = ExpandedSortTransform(x, cs);
    for (int j = 0; j <= n; ++j) EXPECT_TRUE(brute[j].IsSubsetOf(horner[j])) << trial << " " << j;
  }
}

TEST(BoxPolynomialTest, ASkippedContractorCountsAsTheIdentity) {
  const SharedContractors cs = {std::make_shared<ClipTo>(Box{{0, 2}})};
  bool stopped = false;
  const std::vector<Box> p =
      HornerSortTransform(Box{{-10, 10}}, cs, StopCondition::After(std::chrono::seconds(0)),
                          nullptr, &stopped);
  EXPECT_TRUE(stopped);
  EXPECT_EQ(p[1], (Box{{-10, 10}}));
}

TEST(BoxPolynomialTest, HornerCoefficientIsTheTransformsCoefficient) {
  // polynomial's c2 computes one coefficient at a time: the same box, from
  // fewer contractions.
  RandomEngine rng(5);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = UniformInt(rng, 0, 12);
    SharedContractors cs;
    for (int i = 0; i < n; ++i)
      cs.push_back(std::make_shared<ClipTo>(
          RandomBoxAround(rng, {UniformReal(rng, -3, 3), UniformReal(rng, -3, 3)}, 4)));
    const Box x{{-10, 10}, {-10, 10}};
    WorkCounters all;
    const std::vector<Box> horner = HornerSortTransform(x, cs, StopCondition(), &all);
    for (int degree = 0; degree <= n + 1; ++degree) {
      WorkCounters one;
      const Box coefficient = HornerCoefficient(x, cs, degree, StopCondition(), &one);
      if (degree > n)
        EXPECT_TRUE(coefficient.IsEmpty()) << trial;
      else
        EXPECT_EQ(coefficient, horner[degree]) << trial << " " << degree;
      EXPECT_LE(one.revise_calls, all.revise_calls) << trial << " " << degree;
    }
  }
}

TEST(BoxPolynomialTest, AStopMidwayKeepsEveryCoefficientAndEndsAtOnce) {
  // 20000 contractors, the stop condition firing at the 300th contraction:
  // the rest count as the identity. That used to take the n^2 / 2 hulls of
  // the full evaluation (about a minute); now O(n). The budget is generous.
  const int n = 20000;
  SharedContractors cs;
  RandomEngine rng(6);
  for (int i = 0; i < n; ++i)
    cs.push_back(std::make_shared<ClipTo>(RandomBoxAround(rng, {1.0, -2.0}, 3)));
  const Box x{{-10, 10}, {-10, 10}};
  std::atomic<bool> cancel = false;
  const SharedContractors counted = testing::CancelAfterCalls(cs, 300, &cancel);
  const StopCondition stop = StopCondition().WithCancelFlag(&cancel);
  bool stopped = false;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<Box> p = HornerSortTransform(x, counted, stop, nullptr, &stopped);
  cancel = false;
  bool stopped_one = false;
  const Box last = HornerCoefficient(x, testing::CancelAfterCalls(cs, 300, &cancel), n / 2, stop,
                                     nullptr, &stopped_one);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10);
  EXPECT_TRUE(stopped);
  EXPECT_TRUE(stopped_one);
  ASSERT_EQ(p.size(), static_cast<std::size_t>(n + 1));
  // Sound: every coefficient holds the common point of all the boxes
  // (satisfying them all, it counts for every degree), which the unstopped
  // evaluation keeps too.
  for (int j = 0; j <= n; ++j) EXPECT_TRUE(p[j].Contains({1.0, -2.0})) << j;
  EXPECT_TRUE(last.Contains({1.0, -2.0}));
}

}  // namespace
}  // namespace icp
