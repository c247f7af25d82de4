// 3B consistency (Lhomme 1993; paper 000 §3.5): each bound of each variable
// is shaved: a slice [lo, lo + width / slices] is tried with an inner
// contractor (BC4 in the paper: "3b-bc4"; or HC4: "3b-hc4"; any Contractor
// will do) and removed if the inner contractor proves it empty, else the
// bound moves to where the inner contractor shrank the slice. Rounds repeat
// until no variable shrinks by more than `ratio`. This projects the whole CSP,
// not one constraint at a time: x + y = 0, x - y = 0 on [-2,2]^2 becomes
// [0,0]^2, which no constraint-by-constraint algorithm finds. The inner
// contractor is told (ContractContext) that only the shaved variable
// changed, which a propagation turns into far less work than a fresh start.
//
// A trial whose slice lies inside the slice of the same bound's previous
// trial (the next round's, mostly) starts from that trial's result, which
// holds every solution with the variable in the slice, since the box only
// shrinks during a contraction; the inner contractor is told that only the
// variables where the start differs from that result (and the shaved one)
// changed. A later round's trial then costs about a quarter of a first one's
// (algorithms/three_b/three_b_test.cc checks that on car-track windows the
// boxes stay those of cold trials).
//
// Sound: a slice or part of a slice is removed only when the sound inner
// contractor proves it holds no solution.
#ifndef ICPBENCH_ALGORITHMS_THREE_B_THREE_B_H_
#define ICPBENCH_ALGORITHMS_THREE_B_THREE_B_H_

#include <memory>
#include <vector>

#include "algorithms/bc4/bc4.h"
#include "algorithms/hc4/hc4.h"
#include "core/contractor.h"
#include "core/params.h"

namespace icp {

// The shaving parameters, common to every inner contractor.
struct ShavingParams {
  // Slices per bound: a slice is width / slices wide. IBEX's 3BCID suggests
  // values between 5 and 200; more slices are tighter and slower.
  int slices = 10;
  // A round that shrinks no variable by more than this fraction ends 3B; a
  // shave that shrinks its variable by more is propagated at once. Each
  // round costs as much as the first; on the car-track windows the rounds
  // after the first shrink variables by a few percent at most, so values
  // from 1e-3 to 0.05 give about the same boxes and smaller ones only add
  // rounds.
  double ratio = 0.02;
  // No shaving below a slice of relative width epsilon (bound precision).
  double epsilon = 1e-6;
  // Upper bound on shaving rounds over all variables.
  int max_rounds = 1000;
  // Start a trial from the previous trial of the same bound when its slice
  // lies inside that one's (see above). Off, every trial starts from the box:
  // for measuring what the warm starts save.
  bool warm_start = true;
};
void Describe(ShavingParams& p, ParamSet& set);

// 3B with inner parameters nested under "inner." (STYLE.md: pass inner
// parameters explicitly, never default-construct them behind the user).
template <class InnerParams>
struct ThreeBParams {
  ShavingParams shaving;
  InnerParams inner;
};
template <class InnerParams>
void Describe(ThreeBParams<InnerParams>& p, ParamSet& set) {
  Describe(p.shaving, set);
  set.Nest("inner", [&p](ParamSet& s) { Describe(p.inner, s); });
}

class ThreeBContractor : public Contractor {
 public:
  ThreeBContractor(std::string name, std::unique_ptr<Contractor> inner,
                   const ShavingParams& params);
  std::string_view Name() const override { return name_; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

 private:
  // The last trial of one bound: its slice (empty when there is none to
  // start from) and the inner contractor's result on it.
  struct LastTrial {
    Interval slice = Interval::Empty();
    Box result;
  };

  // Shaves the left (or right) bound of box[var] with the inner contractor,
  // called with inner_context; false if box has no solution.
  bool Shave(Box& box, int var, bool left, ContractContext& inner_context, WorkCounters& work);
  // Contracts trial_ (box with var in slice) with the inner contractor,
  // starting from last's result when slice lies inside last's slice; false
  // when the slice holds no solution. Records the trial in last.
  bool Trial(const Box& box, int var, const Interval& slice, LastTrial& last,
             ContractContext& inner_context, WorkCounters& work);

  std::string name_;
  std::unique_ptr<Contractor> inner_;
  ShavingParams params_;
  Box trial_;
  std::vector<LastTrial> last_trials_;  // per bound: 2 var (left), 2 var + 1 (right)
  std::vector<int> changed_;
};

std::unique_ptr<Contractor> MakeThreeBBC4(const ParamMap& params, const ConstraintSystem& csp);
std::unique_ptr<Contractor> MakeThreeBHC4(const ParamMap& params, const ConstraintSystem& csp);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_THREE_B_THREE_B_H_
