// Track-to-observation association by belief functions (Delafosse et al. 2004; paper 002 §3.5
// "Propagation of a track"). A tracked landmark Q_j is matched with one of p observations
// P_1..P_p of its type in the Transferable Belief Model, extended open world (Royère 2002):
// Theta = {P_1, ..., P_p, *}, * = "Q_j matches none of them". Each observation's overlap with
// the track box gives a triplet m_i(P_i), m_i(not P_i), m_i(Theta) (the BPA of Fig. 6); the
// triplets are fused by Royère's operator, which puts the conflict on the union of the
// hypotheses generating it, and the decision is the hypothesis of largest pignistic probability.
//
// Choices the paper leaves open:
// - Fig. 6 shows breakpoints at 0, 25, 100 and 150 % but no masses; we use the piecewise-linear
//   BPA below (kNoMatchUntil, kFullMatchAt, kMaxMatchMass). The overlap is relative to the track
//   box, so it cannot exceed 100 %: inputs are clamped to [0, 100].
// - Royère's operator, written for these triplets: conflict only arises between two or more
//   chosen singletons {P_i}, {P_k}, and goes to their union (see FuseRoyere).
// - Ties in the decision: * wins (no match when in doubt), then the lower index. Pignistic values
//   within kTieTolerance of each other count as tied, so that rounding in the sums of
//   symmetric situations does not pick a side.
// - p <= 20, so that a subset of Theta fits a 32-bit mask (the fused masses can have 2^p focal
//   sets anyway).
#ifndef ICPBENCH_ALGORITHMS_LANDMARK_TRACKING_BELIEF_ASSOCIATION_H_
#define ICPBENCH_ALGORITHMS_LANDMARK_TRACKING_BELIEF_ASSOCIATION_H_

#include <cstdint>
#include <map>
#include <vector>

namespace icp {

// The BPA of Fig. 6 from an overlap percentage (clamped to [0, 100]).
struct OverlapMasses {
  double match = 0;      // m(P_i)
  double no_match = 0;   // m(not P_i), mass on Theta \ {P_i}
  double ignorance = 1;  // m(Theta)
};

// Breakpoints of Fig. 6 (the figure shows 0, 25, 100, 150 % but not the masses).
inline constexpr double kNoMatchUntil = 25;   // m(not P) falls linearly from 1 at 0 % to 0 at 25 %
inline constexpr double kFullMatchAt = 100;   // m(P) rises linearly from 0 at 25 % to kMaxMatchMass
                                              // at 100 %
inline constexpr double kMaxMatchMass = 0.9;  // never certain: 0.1 ignorance stays at full overlap

// Largest number of observations FuseRoyere, Pignistic and DecideByBelief accept.
inline constexpr int kMaxObservations = 20;

// Pignistic probabilities closer than this are a tie in DecideByBelief.
inline constexpr double kTieTolerance = 1e-12;

// m(Theta) = 1 - the others. NaN -> std::invalid_argument; +-infinity clamp like any value.
OverlapMasses MassesFromOverlap(double overlap_percent);

// A subset of Theta = {P_1..P_p, *}: bit i (0-based) for P_{i+1}, bit p for *.
using Hypotheses = std::uint32_t;

// Royère fusion of p triplets (p <= kMaxObservations; more: std::invalid_argument): the mass of
// every focal set (sets of zero mass are left out; the empty set never gets mass).
// Rule, n-ary: choose one focal set per source (P_i, Theta\{P_i} or Theta); let S be the chosen
// singletons and N the intersection of the other choices. |S| = 0: the product goes to N;
// |S| = 1: to S (S is inside N, since only source i can choose P_i or its negation); |S| >= 2:
// the singletons conflict, the product goes to their union (Royère: the conflict on the union of
// the hypotheses generating it; that union is again inside N).
// The sum over the 3^p choices factorizes, so it is computed in O(2^k) for k the number of
// sources with two or more non-zero masses, not by enumeration.
// A triplet with a negative or non-finite mass, or whose masses do not sum to 1 (within 1e-9),
// throws std::invalid_argument.
std::map<Hypotheses, double> FuseRoyere(const std::vector<OverlapMasses>& triplets);

// Pignistic probabilities BetP(x) = sum over focal A containing x of m(A)/|A|; size p + 1
// (last: *). Throws std::invalid_argument for p outside [0, kMaxObservations], a set outside
// Theta, the empty set (Royère's fusion never gives it mass) or a negative or non-finite mass.
std::vector<double> Pignistic(const std::map<Hypotheses, double>& masses, int p);

struct AssociationDecision {
  int observation = -1;           // 0-based index of the chosen P_i; -1: * (no match)
  std::vector<double> pignistic;  // size p + 1, last entry *
};

// Fuses, then picks the largest pignistic probability; ties go to the lower index, and * wins a
// tie with any P_i (no match when in doubt). p = 0: observation -1, pignistic {1}.
AssociationDecision DecideByBelief(const std::vector<OverlapMasses>& triplets);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_LANDMARK_TRACKING_BELIEF_ASSOCIATION_H_
