// The argument contractor of thesis 003 §4.7.3 (eq. 4.76-4.84): the
// contractor of the constraint θ = arg(x, y) + 2kπ, k ∈ Z, i.e. of the set
// {(x, y, θ) : (x, y) = ρ (cos θ, sin θ), ρ >= 0}. A bearing to a landmark,
// a camera's view angle or a sonar's beam direction is this constraint; an
// arctangent of y / x would lose the quadrant.
//
// Built as the thesis builds it: a core contractor on x >= 0, y >= 0,
// θ ∈ [0, π/2] (eq. 4.83), carried to the other quadrants by the symmetries
// arg(x, y) = π − arg(−x, y) and arg(x, y) = −arg(x, −y) (eq. 4.77-4.79) and
// to every period by 2kπ translations; the result is the hull of the pieces
// (eq. 4.81-4.82). The core is the fixpoint of its three projections (θ from
// y / x, x from y / tan θ, y from x tan θ), monotone in each variable, so the
// result is the smallest box holding the set's points in the box, up to the
// outward rounding (tested against brute force). The origin has every
// argument (Remark 16): a box holding (0, 0) keeps its θ.
#ifndef ICPBENCH_CORE_ARGUMENT_CONTRACTOR_H_
#define ICPBENCH_CORE_ARGUMENT_CONTRACTOR_H_

#include <string_view>

#include "core/box.h"
#include "core/contractor.h"
#include "core/interval.h"

namespace icp {

// Contracts x, y and theta in place; all three empty when the box holds no
// point of the set. A theta wider than four turns, or beyond 1e12 rad, is not
// contracted (nor are x and y by it, as every direction is then allowed).
void ContractArgument(Interval& x, Interval& y, Interval& theta);

// atan2(y, x): the arguments in [-pi, pi] of the vectors of the box (the
// hull: [-pi, pi] where the box meets the negative x axis or holds the
// origin, whose argument is any). Empty when x or y is.
Interval Atan2(const Interval& y, const Interval& x);
// The backward projection of z = atan2(y, x): y and x contracted to the
// vectors whose argument in [-pi, pi] lies in z.
void BwdAtan2(const Interval& z, Interval& y, Interval& x);

// The same over three components of a box.
class ArgumentContractor : public Contractor {
 public:
  ArgumentContractor(int x, int y, int theta) : x_(x), y_(y), theta_(theta) {}
  std::string_view Name() const override { return "argument"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

 private:
  int x_, y_, theta_;
};

}  // namespace icp

#endif  // ICPBENCH_CORE_ARGUMENT_CONTRACTOR_H_
