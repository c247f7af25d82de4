#include "core/argument_contractor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/random.h"

namespace icp {
namespace {

constexpr double kPi = std::numbers::pi;

struct Result {
  Interval x, y, theta;
};

Result Contract(Interval x, Interval y, Interval theta) {
  ContractArgument(x, y, theta);
  return {x, y, theta};
}

void ExpectNear(const Interval& got, double lo, double hi, double tol = 1e-12) {
  EXPECT_NEAR(got.lo(), lo, tol) << "[" << got.lo() << ", " << got.hi() << "]";
  EXPECT_NEAR(got.hi(), hi, tol) << "[" << got.lo() << ", " << got.hi() << "]";
}

TEST(ArgumentContractorTest, HandComputedCases) {
  // First quadrant: theta from the box's corners.
  Result r = Contract(Interval(1, 2), Interval(1, 2), Interval(-kPi, kPi));
  ExpectNear(r.theta, std::atan(0.5), std::atan(2.0));
  // Second quadrant, by the y axis symmetry.
  r = Contract(Interval(-2, -1), Interval(1, 2), Interval(-kPi, kPi));
  ExpectNear(r.theta, kPi - std::atan(2.0), kPi - std::atan(0.5));
  // Fourth quadrant one turn up: theta near 2 pi.
  r = Contract(Interval(1, 2), Interval(-2, -1), Interval(4, 7));
  ExpectNear(r.theta, 2 * kPi - std::atan(2.0), 2 * kPi - std::atan(0.5));
  // x and y from theta: a narrow bearing through the first quadrant.
  r = Contract(Interval(0, 10), Interval(1, 10), Interval(0.7, 0.8));
  ExpectNear(r.x, 1 / std::tan(0.8), 10);
  ExpectNear(r.y, 1, 10);
  // The origin has every argument (Remark 16): theta is kept, x and y are
  // the ray's part in the box.
  r = Contract(Interval(-1, 1), Interval(-1, 1), Interval(0.3, 0.4));
  ExpectNear(r.theta, 0.3, 0.4);
  ExpectNear(r.x, 0, 1);
  ExpectNear(r.y, 0, std::tan(0.4));
  r = Contract(Interval(0), Interval(0), Interval(0.5, 0.6));
  ExpectNear(r.theta, 0.5, 0.6);
  // On the y axis: the vertical rays, whatever their length.
  r = Contract(Interval(0), Interval(-2, -1), Interval(-kPi, kPi));
  ExpectNear(r.theta, -kPi / 2, -kPi / 2);
  ExpectNear(r.y, -2, -1);
  r = Contract(Interval(0), Interval(1, kInf), Interval(1, 2));
  ExpectNear(r.theta, kPi / 2, kPi / 2);
  EXPECT_EQ(r.y.hi(), kInf);
  // On the negative x axis, both ends of the cut.
  r = Contract(Interval(-3, -1), Interval(0), Interval(-kPi, kPi));
  EXPECT_TRUE(r.theta.Contains(kPi) && r.theta.Contains(-kPi));
  // Across the branch cut at pi.
  r = Contract(Interval(-2, -1), Interval(-0.5, 0.5), Interval(3, 3.3));
  ExpectNear(r.theta, 3, 3.3);
  ExpectNear(r.y, 2 * std::tan(3.3) * -1, -2 * std::tan(3.0), 1e-12);
  // No point: the first quadrant seen at negative angles.
  r = Contract(Interval(1, 2), Interval(1, 2), Interval(-1, 0));
  EXPECT_TRUE(r.x.IsEmpty() && r.y.IsEmpty() && r.theta.IsEmpty());
  // Unbounded x: theta down to 0, not below.
  r = Contract(Interval(1, kInf), Interval(1, 2), Interval(-kPi, kPi));
  EXPECT_EQ(r.theta.lo(), 0);
  EXPECT_NEAR(r.theta.hi(), std::atan(2.0), 1e-12);
  EXPECT_EQ(r.x.hi(), kInf);
  // Four turns or more: nothing to contract.
  r = Contract(Interval(1, 2), Interval(1, 2), Interval(-20, 20));
  ExpectNear(r.theta, -20, 20);
  r = Contract(Interval(1, 2), Interval(1, 2), Interval(1e300, 1e300));
  EXPECT_EQ(r.theta, Interval(1e300));
}

TEST(ArgumentContractorTest, ContractsThreeComponentsOfABox) {
  // theta first, then an unrelated component, then y and x.
  Box box{Interval(-kPi, kPi), Interval(5, 6), Interval(1, 2), Interval(1, 2)};
  ArgumentContractor c(3, 2, 0);
  ContractContext context;
  EXPECT_EQ(c.Contract(box, context).status, ContractStatus::kContracted);
  ExpectNear(box[0], std::atan(0.5), std::atan(2.0));
  EXPECT_EQ(box[1], Interval(5, 6));
  box[0] = Interval(-1, 0);
  EXPECT_EQ(c.Contract(box, context).status, ContractStatus::kEmpty);
  EXPECT_TRUE(box.IsEmpty());
}

// The set's points in a box, by brute force: every theta of a fine grid (and
// the bounds), the ray's segment in the x-y box (slab method), the origin
// with every theta when the box holds it. Its hull is inside the true hull
// and within the grid's resolution of it.
struct BruteHull {
  Interval x = Interval::Empty(), y = Interval::Empty(), theta = Interval::Empty();
};
BruteHull Brute(const Interval& x, const Interval& y, const Interval& theta, int samples) {
  BruteHull h;
  if (x.Contains(0) && y.Contains(0)) {
    h.x = h.y = Interval(0);
    h.theta = theta;
  }
  for (int i = 0; i <= samples; ++i) {
    const double t =
        i == samples ? theta.hi() : theta.lo() + (theta.hi() - theta.lo()) * i / samples;
    const double c = std::cos(t), s = std::sin(t);
    double lo = 0, hi = 1e300;
    bool empty = false;
    auto slab = [&](double d, const Interval& range) {
      if (std::abs(d) < 1e-300) {
        if (!range.Contains(0)) empty = true;
        return;
      }
      double a = range.lo() / d, b = range.hi() / d;
      if (a > b) std::swap(a, b);
      lo = std::max(lo, a), hi = std::min(hi, b);
    };
    slab(c, x);
    slab(s, y);
    if (empty || lo > hi) continue;
    h.theta = Hull(h.theta, Interval(t));
    for (double rho : {lo, hi}) {
      h.x = Hull(h.x, Interval(std::clamp(rho * c, x.lo(), x.hi())));
      h.y = Hull(h.y, Interval(std::clamp(rho * s, y.lo(), y.hi())));
    }
  }
  return h;
}

Interval RandomRange(RandomEngine& rng, double radius) {
  const double a = UniformReal(rng, -radius, radius), b = UniformReal(rng, -radius, radius);
  return Interval(std::min(a, b), std::max(a, b));
}

TEST(ArgumentContractorTest, SoundAndMinimalAgainstBruteForce) {
  RandomEngine rng(5);
  constexpr int kSamples = 20000;
  int contracted = 0, emptied = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Interval x = RandomRange(rng, 5), y = RandomRange(rng, 5);
    const double centre = UniformReal(rng, -12, 12), half = UniformReal(rng, 0.01, 4);
    const Interval theta(centre - half, centre + half);
    const Result r = Contract(x, y, theta);
    const BruteHull b = Brute(x, y, theta, kSamples);
    const std::string where = "trial " + std::to_string(trial);
    if (b.theta.IsEmpty()) {
      // The grid may miss a sliver; then the result is thin or empty.
      if (!r.theta.IsEmpty()) {
        EXPECT_LT(r.theta.Width(), 1e-2) << where;
      }
      ++emptied;
      continue;
    }
    ASSERT_FALSE(r.theta.IsEmpty()) << where;
    // Sound: every brute-force point is kept.
    EXPECT_TRUE(b.x.IsSubsetOf(r.x) && b.y.IsSubsetOf(r.y) && b.theta.IsSubsetOf(r.theta))
        << where << ": box x [" << x.lo() << ", " << x.hi() << "] y [" << y.lo() << ", " << y.hi()
        << "] theta [" << theta.lo() << ", " << theta.hi() << "]; result x [" << r.x.lo() << ", "
        << r.x.hi() << "] y [" << r.y.lo() << ", " << r.y.hi() << "] theta [" << r.theta.lo()
        << ", " << r.theta.hi() << "]; brute x [" << b.x.lo() << ", " << b.x.hi() << "] y ["
        << b.y.lo() << ", " << b.y.hi() << "] theta [" << b.theta.lo() << ", " << b.theta.hi() << "]";
    // Minimal: no wider than the brute hull beyond the grid's resolution
    // (theta step, and the ray's sweep over 5 * sqrt(2) m).
    const double step = theta.Width() / kSamples;
    const double tol = 8 * step + 1e-9;
    EXPECT_LT(r.theta.hi() - b.theta.hi(), tol) << where;
    EXPECT_LT(b.theta.lo() - r.theta.lo(), tol) << where;
    EXPECT_LT(r.x.hi() - b.x.hi(), 8 * tol) << where;
    EXPECT_LT(b.x.lo() - r.x.lo(), 8 * tol) << where;
    EXPECT_LT(r.y.hi() - b.y.hi(), 8 * tol) << where;
    EXPECT_LT(b.y.lo() - r.y.lo(), 8 * tol) << where;
    if (!(r.theta == theta) || !(r.x == x) || !(r.y == y)) ++contracted;
  }
  // Not vacuous: most boxes contract, some hold no point.
  EXPECT_GT(contracted, 300);
  EXPECT_GT(emptied, 20);
}

}  // namespace
}  // namespace icp
