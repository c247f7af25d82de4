#include "algorithms/landmark_tracking/belief_association.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

namespace icp {
namespace {

constexpr double kEps = 1e-12;

double Sum(const std::map<Hypotheses, double>& masses) {
  double sum = 0;
  for (const auto& [set, mass] : masses) sum += mass;
  return sum;
}

// The rule as stated, by enumerating all 3^p choices (one focal set per source): the reference
// FuseRoyere's factorized sum is checked against.
std::map<Hypotheses, double> FuseByEnumeration(const std::vector<OverlapMasses>& triplets) {
  const int p = static_cast<int>(triplets.size());
  const Hypotheses theta = (Hypotheses{1} << (p + 1)) - 1;
  int choices = 1;
  for (int i = 0; i < p; ++i) choices *= 3;
  std::map<Hypotheses, double> masses;
  for (int code = 0; code < choices; ++code) {
    Hypotheses singles = 0;
    Hypotheses others = theta;
    double product = 1;
    for (int i = 0, c = code; i < p; ++i, c /= 3) {
      const Hypotheses bit = Hypotheses{1} << i;
      switch (c % 3) {
        case 0: singles |= bit; product *= triplets[i].match; break;
        case 1: others &= theta & ~bit; product *= triplets[i].no_match; break;
        default: product *= triplets[i].ignorance; break;
      }
    }
    if (product == 0) continue;
    // |S| = 0: N; |S| = 1: S (inside N); |S| >= 2: the union of the conflicting singletons.
    masses[singles == 0 ? others : singles] += product;
  }
  return masses;
}

void ExpectTriplet(const OverlapMasses& m, double match, double no_match, double ignorance) {
  EXPECT_NEAR(m.match, match, kEps);
  EXPECT_NEAR(m.no_match, no_match, kEps);
  EXPECT_NEAR(m.ignorance, ignorance, kEps);
  EXPECT_GE(m.match, 0);
  EXPECT_GE(m.no_match, 0);
  EXPECT_GE(m.ignorance, 0);
  EXPECT_NEAR(m.match + m.no_match + m.ignorance, 1, kEps);
}

TEST(BeliefAssociationTest, MassesFromOverlapFollowsFigure6) {
  ExpectTriplet(MassesFromOverlap(0), 0, 1, 0);
  ExpectTriplet(MassesFromOverlap(12.5), 0, 0.5, 0.5);
  ExpectTriplet(MassesFromOverlap(25), 0, 0, 1);
  ExpectTriplet(MassesFromOverlap(62.5), 0.45, 0, 0.55);
  ExpectTriplet(MassesFromOverlap(100), 0.9, 0, 0.1);
  ExpectTriplet(MassesFromOverlap(150), 0.9, 0, 0.1);  // clamped to 100
  ExpectTriplet(MassesFromOverlap(-30), 0, 1, 0);      // clamped to 0
  ExpectTriplet(MassesFromOverlap(std::numeric_limits<double>::infinity()), 0.9, 0, 0.1);
  EXPECT_THROW(MassesFromOverlap(std::nan("")), std::invalid_argument);
}

// p = 1: Theta = {P1, *} = 0b11 and Theta \ {P1} = {*} = 0b10, so fusion is the identity.
TEST(BeliefAssociationTest, OneObservationKeepsItsTriplet) {
  const auto masses = FuseRoyere({{0.5, 0.2, 0.3}});
  ASSERT_EQ(masses.size(), 3u);
  EXPECT_NEAR(masses.at(0b01), 0.5, kEps);
  EXPECT_NEAR(masses.at(0b10), 0.2, kEps);
  EXPECT_NEAR(masses.at(0b11), 0.3, kEps);
  // BetP(P1) = 0.5 + 0.3/2, BetP(*) = 0.2 + 0.3/2.
  AssociationDecision d = DecideByBelief({{0.5, 0.2, 0.3}});
  EXPECT_EQ(d.observation, 0);
  ASSERT_EQ(d.pignistic.size(), 2u);
  EXPECT_NEAR(d.pignistic[0], 0.65, kEps);
  EXPECT_NEAR(d.pignistic[1], 0.35, kEps);
  // BetP(P1) = 0.1 + 0.15 < BetP(*) = 0.6 + 0.15: no match.
  d = DecideByBelief({{0.1, 0.6, 0.3}});
  EXPECT_EQ(d.observation, -1);
  EXPECT_NEAR(d.pignistic[1], 0.75, kEps);
  // Exactly even: * wins the tie.
  EXPECT_EQ(DecideByBelief({{0.4, 0.4, 0.2}}).observation, -1);
}

// Fig. 7: two observations both fully inside the track box. Dempster would put 0.81 on the
// empty set; Royère puts it on {P1, P2}.
TEST(BeliefAssociationTest, TwoFullOverlapsConflictOnTheUnion) {
  const std::vector<OverlapMasses> triplets = {MassesFromOverlap(100), MassesFromOverlap(100)};
  const auto masses = FuseRoyere(triplets);
  EXPECT_EQ(masses.count(0), 0u);
  EXPECT_NEAR(masses.at(0b011), 0.9 * 0.9, kEps);
  EXPECT_NEAR(masses.at(0b001), 0.9 * 0.1, kEps);
  EXPECT_NEAR(masses.at(0b010), 0.1 * 0.9, kEps);
  EXPECT_NEAR(masses.at(0b111), 0.1 * 0.1, kEps);
  EXPECT_EQ(masses.size(), 4u);
  const AssociationDecision d = DecideByBelief(triplets);
  ASSERT_EQ(d.pignistic.size(), 3u);
  EXPECT_EQ(d.pignistic[0], d.pignistic[1]);
  EXPECT_NEAR(d.pignistic[0], 0.09 + 0.81 / 2 + 0.01 / 3, kEps);
  EXPECT_NEAR(d.pignistic[2], 0.01 / 3, kEps);
  EXPECT_EQ(d.observation, 0);  // tie between P1 and P2 goes low
}

TEST(BeliefAssociationTest, LargerOverlapWins) {
  // 90 %: (0.78, 0, 0.22); 40 %: (0.18, 0, 0.82).
  AssociationDecision d = DecideByBelief({MassesFromOverlap(90), MassesFromOverlap(40)});
  EXPECT_EQ(d.observation, 0);
  EXPECT_NEAR(d.pignistic[0], 0.78 * 0.82 + 0.78 * 0.18 / 2 + 0.22 * 0.82 / 3, kEps);
  EXPECT_NEAR(d.pignistic[1], 0.22 * 0.18 + 0.78 * 0.18 / 2 + 0.22 * 0.82 / 3, kEps);
  // Swapped order: the decision follows the observation, not the index.
  d = DecideByBelief({MassesFromOverlap(40), MassesFromOverlap(90)});
  EXPECT_EQ(d.observation, 1);
}

TEST(BeliefAssociationTest, NoOverlapMeansStar) {
  const std::vector<OverlapMasses> triplets(4, MassesFromOverlap(0));
  const auto masses = FuseRoyere(triplets);
  ASSERT_EQ(masses.size(), 1u);
  EXPECT_NEAR(masses.at(Hypotheses{1} << 4), 1, kEps);
  const AssociationDecision d = DecideByBelief(triplets);
  EXPECT_EQ(d.observation, -1);
  EXPECT_EQ(d.pignistic, (std::vector<double>{0, 0, 0, 0, 1}));
}

TEST(BeliefAssociationTest, NoObservations) {
  const auto masses = FuseRoyere({});
  ASSERT_EQ(masses.size(), 1u);
  EXPECT_EQ(masses.at(1), 1);  // Theta = {*}
  const AssociationDecision d = DecideByBelief({});
  EXPECT_EQ(d.observation, -1);
  EXPECT_EQ(d.pignistic, std::vector<double>{1});
}

// Random triplets, some masses exactly zero: FuseRoyere agrees with the 3^p enumeration, the
// masses and the pignistic probabilities sum to 1.
TEST(BeliefAssociationTest, RandomTripletsMatchEnumerationAndSumToOne) {
  std::mt19937 rng(20040825);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::uniform_int_distribution<int> zero_one(0, 3);
  for (int trial = 0; trial < 300; ++trial) {
    const int p = trial % 9;
    std::vector<OverlapMasses> triplets;
    for (int i = 0; i < p; ++i) {
      if (trial % 3 == 0) {
        triplets.push_back(MassesFromOverlap(uniform(rng) * 150 - 25));
        continue;
      }
      double a = zero_one(rng) == 0 ? 0 : uniform(rng);
      double b = zero_one(rng) == 0 ? 0 : uniform(rng);
      const double c = uniform(rng);
      const double sum = a + b + c;
      a /= sum;
      b /= sum;
      triplets.push_back({a, b, 1 - a - b});
    }
    const auto masses = FuseRoyere(triplets);
    const auto expected = FuseByEnumeration(triplets);
    ASSERT_EQ(masses.size(), expected.size()) << "trial " << trial;
    for (const auto& [set, mass] : expected) {
      ASSERT_EQ(masses.count(set), 1u) << "trial " << trial << " set " << set;
      EXPECT_NEAR(masses.at(set), mass, 1e-12) << "trial " << trial << " set " << set;
    }
    EXPECT_EQ(masses.count(0), 0u);
    EXPECT_NEAR(Sum(masses), 1, 1e-12) << "trial " << trial;
    const auto bet = Pignistic(masses, p);
    ASSERT_EQ(bet.size(), static_cast<std::size_t>(p + 1));
    EXPECT_NEAR(std::accumulate(bet.begin(), bet.end(), 0.0), 1, 1e-12) << "trial " << trial;
  }
}

// p = 3, bits P1 = 1, P2 = 2, P3 = 4, * = 8, Theta = 15, triplets (m(P), m(not P), m(Theta)):
//   s1 = (0.5, 0.2, 0.3), s2 = (0.4, 0.4, 0.2), s3 = (0, 0.5, 0.5) (overlap 12.5 %).
// s3 never chooses P3. Choices with singletons (the rest of each source summed, b + c):
//   {P1}     = 0.5 * (0.2 + 0.4) * (0.5 + 0.5) = 0.30
//   {P2}     = (0.2 + 0.3) * 0.4 * 1           = 0.20
//   {P1,P2}  = 0.5 * 0.4 * 1                   = 0.20   (conflict P1 vs P2, on the union)
// No singleton: the negated sources K leave Theta \ P_K, product of b over K and c elsewhere:
//   K = {}       Theta      (15) = 0.3 * 0.2 * 0.5 = 0.03
//   K = {1}      {P2,P3,*}  (14) = 0.2 * 0.2 * 0.5 = 0.02
//   K = {2}      {P1,P3,*}  (13) = 0.3 * 0.4 * 0.5 = 0.06
//   K = {3}      {P1,P2,*}  (11) = 0.3 * 0.2 * 0.5 = 0.03
//   K = {1,2}    {P3,*}     (12) = 0.2 * 0.4 * 0.5 = 0.04
//   K = {1,3}    {P2,*}     (10) = 0.2 * 0.2 * 0.5 = 0.02
//   K = {2,3}    {P1,*}     ( 9) = 0.3 * 0.4 * 0.5 = 0.06
//   K = {1,2,3}  {*}        ( 8) = 0.2 * 0.4 * 0.5 = 0.04
// Total 0.30 + 0.20 + 0.20 + 0.30 = 1.
// BetP(P1) = 0.30 + 0.20/2 + 0.03/4 + 0.06/3 + 0.03/3 + 0.06/2            = 0.4675
// BetP(P2) = 0.20 + 0.20/2 + 0.03/4 + 0.02/3 + 0.03/3 + 0.02/2            = 0.334166...
// BetP(P3) = 0.03/4 + 0.02/3 + 0.06/3 + 0.04/2                           = 0.054166...
// BetP(*)  = 0.03/4 + 0.02/3 + 0.06/3 + 0.03/3 + 0.04/2 + 0.02/2 + 0.06/2 + 0.04
//          = 0.144166...
TEST(BeliefAssociationTest, HandComputedThreeObservations) {
  const std::vector<OverlapMasses> triplets = {
      {0.5, 0.2, 0.3}, {0.4, 0.4, 0.2}, MassesFromOverlap(12.5)};
  const std::map<Hypotheses, double> expected = {
      {1, 0.30},  {2, 0.20},  {3, 0.20},  {8, 0.04},  {9, 0.06},  {10, 0.02},
      {11, 0.03}, {12, 0.04}, {13, 0.06}, {14, 0.02}, {15, 0.03}};
  const auto masses = FuseRoyere(triplets);
  ASSERT_EQ(masses.size(), expected.size());
  for (const auto& [set, mass] : expected) {
    ASSERT_EQ(masses.count(set), 1u) << "set " << set;
    EXPECT_NEAR(masses.at(set), mass, kEps) << "set " << set;
  }
  const AssociationDecision d = DecideByBelief(triplets);
  ASSERT_EQ(d.pignistic.size(), 4u);
  EXPECT_NEAR(d.pignistic[0], 0.4675, kEps);
  EXPECT_NEAR(d.pignistic[1], 0.20 + 0.10 + 0.0075 + 0.02 / 3 + 0.01 + 0.01, kEps);
  EXPECT_NEAR(d.pignistic[2], 0.0075 + 0.02 / 3 + 0.02 + 0.02, kEps);
  EXPECT_NEAR(d.pignistic[3], 0.0075 + 0.02 / 3 + 0.02 + 0.01 + 0.02 + 0.01 + 0.03 + 0.04,
              kEps);
  EXPECT_EQ(d.observation, 0);
}

// 20 observations, each with two non-zero masses: 2^20 focal sets, still computed quickly
// (3^20 enumeration would not be).
TEST(BeliefAssociationTest, TwentyObservationsAreCheap) {
  std::vector<OverlapMasses> triplets;
  for (int i = 0; i < kMaxObservations; ++i) triplets.push_back(MassesFromOverlap(30 + 3 * i));
  const auto masses = FuseRoyere(triplets);
  EXPECT_EQ(masses.size(), (std::size_t{1} << 20) - 1 + 1);  // non-empty S, and Theta
  EXPECT_NEAR(Sum(masses), 1, 1e-9);
  const AssociationDecision d = DecideByBelief(triplets);
  EXPECT_EQ(d.observation, kMaxObservations - 1);  // the largest overlap
  EXPECT_NEAR(std::accumulate(d.pignistic.begin(), d.pignistic.end(), 0.0), 1, 1e-9);
}

TEST(BeliefAssociationTest, RejectsBadInput) {
  EXPECT_THROW(FuseRoyere(std::vector<OverlapMasses>(21, MassesFromOverlap(50))),
               std::invalid_argument);
  EXPECT_THROW(DecideByBelief(std::vector<OverlapMasses>(21, MassesFromOverlap(50))),
               std::invalid_argument);
  EXPECT_THROW(FuseRoyere({{0.5, 0.5, 0.5}}), std::invalid_argument);   // sums to 1.5
  EXPECT_THROW(FuseRoyere({{-0.1, 0.6, 0.5}}), std::invalid_argument);  // negative
  EXPECT_THROW(Pignistic({{0, 1.0}}, 1), std::invalid_argument);        // empty set
  EXPECT_THROW(Pignistic({{0b100, 1.0}}, 1), std::invalid_argument);    // outside Theta
  EXPECT_THROW(Pignistic({}, 21), std::invalid_argument);
}

}  // namespace
}  // namespace icp
