// polynomial: the contractor polynomial of the measurements (paper 003
// §2.5, §5.1), evaluated on the prior as a box polynomial whose coefficient
// of degree m - q encloses the points satisfying at least m - q of the m
// measurements: the solution for every number of outliers at once (the
// step's `hulls_by_q`). Three approximations of C*(s), with repetition p:
//   c1  coefficient k = (q-relaxed intersection, q = m - k)^p   (eq. 5.5)
//   c2  coefficient k = (relaxed composition)^p: coefficient k of the Horner
//       evaluation (prop. 31) applied p times                  (eq. 5.8)
//   c3  coefficient k = coefficient k*p of the Horner evaluation over the
//       measurements repeated p times                           (eq. 5.10)
// Costs in contractions: c1 O(p m^2), c2 O(p m^3), c3 O(p^2 m^2).
// Sound for every approximation and p (prop. 30 for c3): each coefficient
// keeps every point that satisfies that many measurements.
#ifndef ICPBENCH_ALGORITHMS_POLYNOMIAL_POLYNOMIAL_H_
#define ICPBENCH_ALGORITHMS_POLYNOMIAL_POLYNOMIAL_H_

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/relaxed/relaxed_estimator.h"

namespace icp {

struct PolynomialParams {
  RelaxedParams relaxed;
  std::string approximation = "c3";
  // Repetitions: more narrows the coefficients towards C*(s), at a cost
  // linear (c1, c2) or quadratic (c3) in p. Fig. 5.2 uses 10 (30 for c1).
  int p = 10;
};
void Describe(PolynomialParams& p, ParamSet& set);

// C^(p*)(s)(prior) of eq. 5.10: the Horner evaluation (prop. 31) over the
// measurements repeated p times, coefficients 0..p m by degree; c3 keeps
// every p-th. Stops as HornerSortTransform does.
std::vector<Box> RepeatedSortTransform(const Box& prior, const SharedContractors& measurements,
                                       int p, const StopCondition& stop,
                                       WorkCounters* work = nullptr, bool* stopped = nullptr);

// The approximation's coefficients on prior, by q = 0..m (the coefficient
// of degree m - q; an empty one set empty): what the estimator solves with,
// and what Fig. 5.2 draws. summary gets the work, and kStopped with its
// message when stop fired.
std::vector<Box> PolynomialHullsByQ(const PolynomialParams& params, const Box& prior,
                                    const SharedContractors& measurements,
                                    const StopCondition& stop, ContractSummary* summary);

std::unique_ptr<Estimator> MakePolynomial(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_POLYNOMIAL_POLYNOMIAL_H_
