// Box polynomials and the Horner evaluation of the contractor polynomial
// sort transform (paper 003 §5.1.3, prop. 31). For contractors C_1..C_n and
// a box x, the box polynomial [X_n](s) = sum_j [x_j] s^j is built by
//   [X_0](s) = x,   [X_{k+1}](s) = C_{k+1}([X_k](s)) * s + [X_k](s),
// where a contractor applies to every coefficient and "+" is the box hull:
// coefficient j of the result encloses every point of x that satisfies at
// least j of the n constraints (n - j outliers allowed), whatever the
// order. n(n+1)/2 contractions.
#ifndef ICPBENCH_CORE_BOX_POLYNOMIAL_H_
#define ICPBENCH_CORE_BOX_POLYNOMIAL_H_

#include <vector>

#include "core/contractor_algebra.h"

namespace icp {

// Coefficients 0..n (index = degree); coefficient 0 is x. When stop fires,
// the contractors not yet applied count as the identity (sound), which
// costs O(n) more, and *stopped is set. work, when given, adds the
// contractions' counters.
std::vector<Box> HornerSortTransform(const Box& x, const SharedContractors& sequence,
                                     const StopCondition& stop, WorkCounters* work = nullptr,
                                     bool* stopped = nullptr);

// Coefficient `degree` of HornerSortTransform(x, sequence), the same box,
// from only the coefficients it depends on: after k of the n contractors,
// degrees degree - (n - k) to degree, at most min(degree, n - degree) + 1
// contractions a step instead of k + 1. Empty for a degree above n. Stops
// as HornerSortTransform does.
Box HornerCoefficient(const Box& x, const SharedContractors& sequence, int degree,
                      const StopCondition& stop, WorkCounters* work = nullptr,
                      bool* stopped = nullptr);

}  // namespace icp

#endif  // ICPBENCH_CORE_BOX_POLYNOMIAL_H_
