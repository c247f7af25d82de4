#include "algorithms/landmark_tracking/belief_association.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace icp {
namespace {

using WeightedSets = std::vector<std::pair<Hypotheses, double>>;

// Extends every partial product by one source's two alternatives: `with` adds `bit` to the set,
// `without` leaves it. A zero alternative adds no entries, so certain sources do not double
// the list.
void Extend(WeightedSets& sets, Hypotheses bit, double with, double without) {
  if (with == 0) {
    if (without == 0) {
      sets.clear();
      return;
    }
    for (auto& [set, weight] : sets) weight *= without;
    return;
  }
  if (without == 0) {
    for (auto& [set, weight] : sets) {
      set |= bit;
      weight *= with;
    }
    return;
  }
  const std::size_t n = sets.size();
  sets.reserve(2 * n);
  for (std::size_t k = 0; k < n; ++k) {
    sets.emplace_back(sets[k].first | bit, sets[k].second * with);
    sets[k].second *= without;
  }
}

void CheckTriplet(const OverlapMasses& m, std::size_t index) {
  const double masses[] = {m.match, m.no_match, m.ignorance};
  for (double mass : masses) {
    if (!std::isfinite(mass) || mass < 0) {
      throw std::invalid_argument("FuseRoyere: triplet " + std::to_string(index) +
                                  " has a negative or non-finite mass");
    }
  }
  if (std::abs(m.match + m.no_match + m.ignorance - 1) > 1e-9) {
    throw std::invalid_argument("FuseRoyere: triplet " + std::to_string(index) +
                                " does not sum to 1");
  }
}

}  // namespace

OverlapMasses MassesFromOverlap(double overlap_percent) {
  if (std::isnan(overlap_percent)) {
    throw std::invalid_argument("MassesFromOverlap: overlap is NaN");
  }
  const double o = std::clamp(overlap_percent, 0.0, 100.0);
  OverlapMasses m;
  if (o < kNoMatchUntil) {
    m.no_match = 1 - o / kNoMatchUntil;
  } else if (o > kNoMatchUntil) {
    m.match = kMaxMatchMass * std::min(1.0, (o - kNoMatchUntil) / (kFullMatchAt - kNoMatchUntil));
  }
  m.ignorance = 1 - m.match - m.no_match;
  return m;
}

std::map<Hypotheses, double> FuseRoyere(const std::vector<OverlapMasses>& triplets) {
  if (triplets.size() > static_cast<std::size_t>(kMaxObservations)) {
    throw std::invalid_argument("FuseRoyere: more than " + std::to_string(kMaxObservations) +
                                " observations");
  }
  for (std::size_t i = 0; i < triplets.size(); ++i) CheckTriplet(triplets[i], i);
  const int p = static_cast<int>(triplets.size());
  const Hypotheses theta = (Hypotheses{1} << (p + 1)) - 1;

  // The result of a choice depends only on S when S is non-empty, and only on the set K of
  // sources that chose their negation when S is empty (N = Theta \ {P_i : i in K}). So the sum
  // over the 3^p choices factorizes:
  //   m(S)           = prod_{i in S} m_i(P_i) * prod_{i not in S} (m_i(not P_i) + m_i(Theta)),
  //   m(Theta \ P_K) = prod_{i in K} m_i(not P_i) * prod_{i not in K} m_i(Theta).
  // The two families never meet: S lacks *, Theta \ P_K contains it.
  WeightedSets singletons = {{0, 1.0}};  // S -> weight; S = 0 is dropped below
  WeightedSets negations = {{0, 1.0}};   // K -> weight
  for (int i = 0; i < p; ++i) {
    const OverlapMasses& m = triplets[i];
    const Hypotheses bit = Hypotheses{1} << i;
    Extend(singletons, bit, m.match, m.no_match + m.ignorance);
    Extend(negations, bit, m.no_match, m.ignorance);
  }

  WeightedSets focal;
  focal.reserve(singletons.size() + negations.size());
  for (const auto& [set, weight] : singletons) {
    if (set != 0 && weight > 0) focal.emplace_back(set, weight);
  }
  for (const auto& [negated, weight] : negations) {
    if (weight > 0) focal.emplace_back(theta & ~negated, weight);
  }
  // Sorted, the map is built in linear time (2^20 focal sets are possible).
  std::sort(focal.begin(), focal.end());
  std::map<Hypotheses, double> masses;
  for (const auto& entry : focal) masses.emplace_hint(masses.end(), entry);
  return masses;
}

std::vector<double> Pignistic(const std::map<Hypotheses, double>& masses, int p) {
  if (p < 0 || p > kMaxObservations) {
    throw std::invalid_argument("Pignistic: p outside [0, " + std::to_string(kMaxObservations) +
                                "]");
  }
  const Hypotheses theta = (Hypotheses{1} << (p + 1)) - 1;
  std::vector<double> bet(p + 1, 0.0);
  for (const auto& [set, mass] : masses) {
    if (set == 0 || (set & ~theta) != 0) {
      throw std::invalid_argument("Pignistic: focal set empty or outside Theta");
    }
    if (!std::isfinite(mass) || mass < 0) {
      throw std::invalid_argument("Pignistic: negative or non-finite mass");
    }
    const double share = mass / std::popcount(set);
    for (Hypotheses rest = set; rest != 0; rest &= rest - 1) {
      bet[std::countr_zero(rest)] += share;
    }
  }
  return bet;
}

AssociationDecision DecideByBelief(const std::vector<OverlapMasses>& triplets) {
  const std::map<Hypotheses, double> masses = FuseRoyere(triplets);  // throws for p > 20
  const int p = static_cast<int>(triplets.size());
  AssociationDecision decision;
  decision.pignistic = Pignistic(masses, p);
  // * is the incumbent and a P_i replaces the best only when clearly larger, so ties go to *,
  // then to the lower index.
  double best = decision.pignistic[p];
  for (int i = 0; i < p; ++i) {
    if (decision.pignistic[i] > best + kTieTolerance) {
      best = decision.pignistic[i];
      decision.observation = i;
    }
  }
  return decision;
}

}  // namespace icp
