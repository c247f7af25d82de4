// BC3 (Benhamou, McAllester, Van Hentenryck 1994; paper 000 §3.3): box
// consistency for every (constraint, variable) pair. With the other variables
// kept as intervals, the constraint becomes univariate in x; the left bound of
// x moves to the leftmost "quasi-zero" (a slice of relative width `epsilon`
// on which the constraint's interval extension can hold) and the right bound
// to the rightmost one. Slices are found by bisection, each piece first
// narrowed by the univariate interval Newton operator with the derivative
// computed on the tape, and the search stops at the first piece whose edge
// slice is consistent (BC3revise's LNAR/RNAR; RealPaver's shrink). Pairs are
// propagated with the AC3-like queue. A revise narrows its constraint's
// variables in turn on one evaluation of the tape; each constraint keeps that
// evaluation and which variables were narrowed against its final domains, so
// a revise whose domains did not change since evaluates nothing twice, and a
// revise in which only the first variable shrank is not queued again.
//
// Sound: slices are removed only when the interval extension proves them
// solution-free. Not affected by multiple occurrences the way HC4 is
// (x*x + y^2 = 2 is contracted), but slower.
#ifndef ICPBENCH_ALGORITHMS_BC3_BC3_H_
#define ICPBENCH_ALGORITHMS_BC3_BC3_H_

#include <memory>
#include <span>
#include <vector>

#include "core/constraint_system.h"
#include "core/params.h"
#include "core/propagation.h"

namespace icp {

struct BC3Params {
  // Propagation threshold: a variable whose width shrinks by more than this
  // fraction re-queues its constraints.
  double ratio = 1e-3;
  // Width of a quasi-zero slice relative to max(1, |bound|): the precision
  // of the bounds. 1e-8 to 1e-4 are typical; smaller costs more bisections.
  double epsilon = 1e-6;
  // Bisections allowed per bound search; when exhausted the bound moves only
  // as far as proven.
  int max_bisections = 200;
  // Upper bound on constraint revisions per contraction.
  int max_revise_calls = 1000000;
};
void Describe(BC3Params& p, ParamSet& set);

// The univariate narrowing of one variable in one constraint (BC3Revise),
// shared by BC3 and BC4.
class BoxNarrower {
 public:
  BoxNarrower(double epsilon, int max_bisections)
      : epsilon_(epsilon), max_bisections_(max_bisections) {}
  // Narrows box[var] to its outermost quasi-zeros of tape. slots must hold
  // tape.Forward(box): the slots that do not depend on var are read from it,
  // and it is left as a Forward on the narrowed box, so that the variables of
  // one constraint are narrowed in turn after one evaluation. Returns false
  // if there is no quasi-zero (no solution in box). The two edge tests of an
  // unchanged bound, the usual case at a fixpoint, are one paired sweep.
  bool Narrow(const Tape& tape, int var, Box& box, std::vector<Interval>& slots,
              WorkCounters& work);

 private:
  // An edge slice of a bound search and whether the constraint can hold there.
  struct EdgeTest {
    Interval edge;
    bool consistent = false;
  };
  // Where the constraint can hold on x = j (interval extension test); the
  // lane is left with the evaluation on j.
  bool Consistent(const Tape& tape, const Interval& j);
  // The slice at the outer bound of j, on the left (leftward) or the right.
  Interval EdgeSlice(const Interval& j, bool leftward) const;
  // Shrinks j with interval Newton steps; empty if j holds no solution.
  Interval Newton(const Tape& tape, Interval j, WorkCounters& work);
  // Sets *bound to the outermost quasi-zero's bound on the left (leftward =
  // true) or the right of x; false if there is none. known: the test of x's
  // own edge slice, if it was already made. (Not an std::optional return:
  // GCC returns it through a partial store and a wider load that stall.)
  bool OuterBound(const Tape& tape, const Interval& x, bool leftward, const EdgeTest* known,
                  double* bound, WorkCounters& work);
  bool Small(const Interval& j) const;

  double epsilon_;
  int max_bisections_;
  const std::vector<Interval>* slots_ = nullptr;  // the caller's Forward, during Narrow
  Tape::UnivariateCode univariate_;               // the narrowed variable's sweep
  Interval entry_;                                // the variable's domain on entry to Narrow
  // The dependent slots' values of the last evaluation, of a second one (the
  // paired edge tests) and the derivatives (Newton).
  std::vector<Interval> lane_, other_lane_, dlane_;
  std::vector<Interval> stack_;
};

class BC3Contractor : public PropagationContractor {
 public:
  BC3Contractor(std::shared_ptr<const CompiledSystem> system, const BC3Params& params);
  std::string_view Name() const override { return "bc3"; }

 protected:
  bool Revise(int c, Box& box, WorkCounters& work, bool* idempotent) override;

 private:
  // What the last revise of a constraint leaves for the next one.
  struct Memory {
    bool valid = false;             // whether there was one and it succeeded
    std::vector<Interval> domains;  // its variables' domains after it
    std::vector<Interval> slots;    // the tape's Forward on those domains
    std::size_t settled_from = 0;   // the variables from here on need no narrowing there
  };
  BoxNarrower narrower_;
  std::vector<Memory> memories_;
};

std::unique_ptr<Contractor> MakeBC3(const ParamMap& params, const ConstraintSystem& csp);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_BC3_BC3_H_
