// HC3 (Cleary 1987, Benhamou & Older 1997; paper 000 §3.1, paper 002 §2.2):
// every constraint is decomposed into primitive constraints z = x op y or
// z = f(x), one per node of the expression DAG, with an auxiliary variable
// for each intermediate node; the shared AC3-like loop (core/propagation.h)
// revises the primitives (forward: z ∩= x op y, backward: the projections
// onto x and y) until no variable shrinks by more than `ratio`. Auxiliary
// variables live only inside a contraction and never appear in the output
// box, so every contraction starts from all primitives, whatever the context
// says changed.
//
// Sound (each revise is a projection). Weaker than HC4 in general: the
// auxiliaries are contracted independently of each other.
#ifndef ICPBENCH_ALGORITHMS_HC3_HC3_H_
#define ICPBENCH_ALGORITHMS_HC3_HC3_H_

#include <memory>
#include <vector>

#include "core/constraint_system.h"
#include "core/contractor.h"
#include "core/params.h"
#include "core/propagation.h"

namespace icp {

struct HC3Params {
  // A variable (original or auxiliary) whose width shrinks by more than this
  // fraction re-queues the primitives it occurs in.
  double ratio = 1e-3;
  // Upper bound on primitive revisions per contraction.
  int max_revise_calls = 10000000;
};
void Describe(HC3Params& p, ParamSet& set);

class HC3Contractor : public Contractor, private Revisers {
 public:
  HC3Contractor(const ConstraintSystem& csp, const HC3Params& params);
  std::string_view Name() const override { return "hc3"; }
  ContractSummary Contract(Box& box, ContractContext& context) override;

  int num_primitives() const { return static_cast<int>(primitives_.size()); }
  int num_auxiliaries() const { return static_cast<int>(initial_.size()) - num_variables_; }

 private:
  // z = op(a, b) over the extended box (originals first).
  struct Primitive {
    Op op;
    int z;
    int a;
    int b;  // -1 for unary ops
    int n;  // kPow exponent
  };
  // Revises primitive p over the extended box.
  bool Revise(int p, Box& extended, WorkCounters& work, bool* idempotent) override;

  HC3Params params_;
  int num_variables_;
  std::vector<Primitive> primitives_;
  Box initial_;                       // extended domains before a call
  std::vector<Interval> root_range_;  // per original variable: ranges of constraints "x in R"
  Propagation propagation_;           // over primitives_, scoped to {z, a, b}
  Box extended_;                      // the box a call propagates over
};

std::unique_ptr<Contractor> MakeHC3(const ParamMap& params, const ConstraintSystem& csp);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_HC3_HC3_H_
