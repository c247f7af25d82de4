#include "core/random.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace icp {
namespace {

// Golden values: the first draws for seed 42, as computed by this code (and
// the reals checked against engine() / 2^64 * (hi - lo) + lo by hand). They
// pin portable seeds (issue 8): they must not move with the standard library,
// the compiler or the machine. If one moves, every problem instance moves.
TEST(RandomTest, FirstDrawsForSeed42AreFixed) {
  RandomEngine engine(42);
  EXPECT_EQ(UniformReal(engine, 0, 1), 0x1.82a3befaddcbcp-1);
  EXPECT_EQ(UniformReal(engine, 0, 1), 0x1.472f1f73724ap-1);
  EXPECT_EQ(UniformReal(engine, 0, 1), 0x1.81192cfe1cbcfp-1);
  EXPECT_EQ(UniformReal(engine, -1, 1), -0x1.7474ef01d794bp-1);
  EXPECT_EQ(UniformReal(engine, -1, 1), 0x1.9cf28a3934d86p-1);
  EXPECT_EQ(UniformReal(engine, -1, 1), -0x1.9fac8e758e02cp-1);
  EXPECT_EQ(UniformInt(engine, 1, 6), 4);
  EXPECT_EQ(UniformInt(engine, 1, 6), 3);
  EXPECT_EQ(UniformInt(engine, 1, 6), 2);
  EXPECT_EQ(UniformIndex(engine, 10), 3u);
  EXPECT_EQ(UniformIndex(engine, 10), 0u);
  EXPECT_EQ(UniformIndex(engine, 10), 5u);
}

TEST(RandomTest, EngineIsTheStandardsMt19937_64) {
  // The standard fixes the 10000th output of a default-constructed engine.
  RandomEngine engine;
  engine.discard(9999);
  EXPECT_EQ(engine(), 9981545732273789042u);
}

TEST(RandomTest, DrawsStayInTheirRangesAndReachBothEndsOfIntegerRanges) {
  RandomEngine engine(1);
  std::vector<int> seen(5, 0);
  for (int i = 0; i < 1000; ++i) {
    const double x = UniformReal(engine, -2.5, 0.5);
    ASSERT_GE(x, -2.5);
    ASSERT_LT(x, 0.5);
    const std::int64_t k = UniformInt(engine, -2, 2);
    ASSERT_GE(k, -2);
    ASSERT_LE(k, 2);
    ++seen[k + 2];
    ASSERT_LT(UniformIndex(engine, 3), 3u);
  }
  for (int count : seen) EXPECT_GT(count, 100);
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  EXPECT_EQ(UniformInt(engine, kMin, kMin), kMin);
  EXPECT_EQ(UniformIndex(engine, 1), 0u);
}

TEST(RandomTest, EmptyRangeIsItsPointAndBadRangesThrow) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  RandomEngine engine(1);
  EXPECT_EQ(UniformReal(engine, 3, 3), 3);  // Boost alone would loop forever
  EXPECT_THROW(UniformReal(engine, 1, 0), std::invalid_argument);
  EXPECT_THROW(UniformReal(engine, 0, kInf), std::invalid_argument);
  EXPECT_THROW(UniformReal(engine, kNaN, 1), std::invalid_argument);
  EXPECT_THROW(UniformInt(engine, 1, 0), std::invalid_argument);
  EXPECT_THROW(UniformIndex(engine, 0), std::invalid_argument);
}

}  // namespace
}  // namespace icp
