#include "algorithms/bc3/bc3.h"

#include <algorithm>
#include <cmath>

#include "core/projections.h"

namespace icp {

void Describe(BC3Params& p, ParamSet& set) {
  set.Add("ratio", &p.ratio,
          "relative width decrease of a variable that re-queues its constraints",
          Range::HalfOpen(0, 1));
  set.Add("epsilon", &p.epsilon, "relative width of a quasi-zero slice (bound precision)",
          Range::Positive(1));
  set.Add("max_bisections", &p.max_bisections, "bisections allowed per bound search",
          Range::AtLeast(0));
  set.Add("max_revise_calls", &p.max_revise_calls,
          "constraint revisions allowed per contraction before stopping", Range::AtLeast(1));
}

bool BoxNarrower::Small(const Interval& j) const {
  return j.IsBounded() && j.Width() <= epsilon_ * std::max(1.0, j.Mag());
}

bool BoxNarrower::Consistent(const Tape& tape, const Interval& j) {
  // On the whole domain (Newton's first step after a failed edge test) the
  // caller's Forward is the evaluation: the lane takes its dependent slots.
  if (SameBits(j, entry_)) {
    for (std::size_t k = 0; k < univariate_.slots.size(); ++k)
      lane_[k] = (*slots_)[univariate_.slots[k]];
    return !Intersect(lane_[univariate_.code.size() - 1], tape.range()).IsEmpty();
  }
  const Interval f = Tape::ForwardUnivariate(univariate_.code, j, *slots_, lane_.data());
  return !Intersect(f, tape.range()).IsEmpty();
}

inline Interval BoxNarrower::EdgeSlice(const Interval& j, bool leftward) const {
  const double b = leftward ? j.lo() : j.hi();
  const double slice = epsilon_ * std::max(1.0, std::fabs(b));
  // Ordered and finite: j is bounded, and b +- slice only overflows past j's other bound.
  return leftward ? Interval(b, std::min(j.hi(), b + slice), Interval::kOrdered)
                  : Interval(std::max(j.lo(), b - slice), b, Interval::kOrdered);
}

Interval BoxNarrower::Newton(const Tape& tape, Interval j, WorkCounters& work) {
  for (int step = 0; step < 8 && !j.IsEmpty(); ++step) {
    ++work.newton_steps;
    if (!Consistent(tape, j)) return Interval::Empty();
    if (Small(j)) return j;
    // Mean value form: f(t) - f(m) = f'(xi) (t - m), with f(t) in range. The
    // derivative comes from the lane of the evaluation on j, before the
    // evaluation at m overwrites it.
    const Interval derivative =
        Tape::DerivativeUnivariate(univariate_.code, *slots_, lane_.data(), dlane_.data());
    const double m = j.Mid();
    Interval fm = Tape::ForwardUnivariate(univariate_.code, Interval(m), *slots_, lane_.data());
    if (fm.IsEmpty()) return j;  // f undefined at m: no Newton step
    Interval next = Interval(m) + DivideRelational(j - Interval(m), tape.range() - fm, derivative);
    next = Intersect(j, next);
    if (next.IsEmpty()) return next;
    // A point derivative means f is affine on j: the step was exact up to
    // rounding, and another would gain at most an ulp.
    const bool progress = next.Width() < 0.9 * j.Width() && derivative.lo() != derivative.hi();
    j = next;
    if (!progress) break;
  }
  return j;
}

bool BoxNarrower::OuterBound(const Tape& tape, const Interval& x, bool leftward,
                             const EdgeTest* known, double* bound, WorkCounters& work) {
  auto outer = [leftward](const Interval& j) { return leftward ? j.lo() : j.hi(); };
  // The edge slice of a piece: if the constraint can hold there, the piece's
  // outer bound is a quasi-zero.
  auto edge_consistent = [&](const Interval& j) {
    return j.IsBounded() && Consistent(tape, EdgeSlice(j, leftward));
  };
  // The bound is already a quasi-zero: the usual case at a fixpoint.
  if (known ? known->consistent : edge_consistent(x)) {
    *bound = outer(x);
    return true;
  }
  stack_.clear();
  stack_.push_back(x);
  int bisections = 0;
  while (!stack_.empty()) {
    Interval j = stack_.back();
    stack_.pop_back();
    j = Newton(tape, j, work);
    if (j.IsEmpty()) continue;
    // The first piece whose edge can hold a solution gives the bound: refining
    // inside it would move the bound by less than a slice.
    if (Small(j) || edge_consistent(j)) {
      *bound = outer(j);
      return true;
    }
    if (bisections >= max_bisections_) {
      // Out of budget: every remaining piece may hold a solution.
      *bound = outer(j);
      for (const Interval& rest : stack_)
        *bound = leftward ? std::min(*bound, rest.lo()) : std::max(*bound, rest.hi());
      return true;
    }
    ++bisections;
    ++work.bisections;
    const double m = j.Mid();
    Interval low(j.lo(), m), high(m, j.hi());
    // The piece to explore first goes on top.
    if (leftward) {
      stack_.push_back(high);
      stack_.push_back(low);
    } else {
      stack_.push_back(low);
      stack_.push_back(high);
    }
  }
  return false;
}

bool BoxNarrower::Narrow(const Tape& tape, int var, Box& box, std::vector<Interval>& slots,
                         WorkCounters& work) {
  // Only var changes during the search: the other slots keep their values
  // from the caller's Forward, and only the dependent ones are swept, into
  // the lanes; the caller's slots change only if var is narrowed.
  slots_ = &slots;
  univariate_ = tape.Univariate(var);
  if (lane_.size() < univariate_.code.size()) {
    lane_.resize(univariate_.code.size());
    other_lane_.resize(univariate_.code.size());
    dlane_.resize(univariate_.code.size());
  }
  const Interval x = box[var];
  entry_ = x;
  // Both edges of x in one sweep: the right one is x's own edge again unless
  // the left bound moves by nearly the whole domain.
  EdgeTest left_edge, right_edge;
  const EdgeTest* left_known = nullptr;
  const EdgeTest* right_known = nullptr;
  if (x.IsBounded()) {
    left_edge.edge = EdgeSlice(x, true);
    right_edge.edge = EdgeSlice(x, false);
    const auto [f_left, f_right] = Tape::ForwardUnivariatePair(
        univariate_.code, left_edge.edge, right_edge.edge, slots, lane_.data(), other_lane_.data());
    left_edge.consistent = !Intersect(f_left, tape.range()).IsEmpty();
    right_edge.consistent = !Intersect(f_right, tape.range()).IsEmpty();
    left_known = &left_edge;
    right_known = &right_edge;
  }
  double lo, hi;
  if (!OuterBound(tape, x, true, left_known, &lo, work)) return false;
  // The right edge test stands if the left bound stayed or moved less than
  // the slice's distance from the right one.
  const Interval rest(lo, x.hi());
  if (right_known && !SameBits(rest, x) && !SameBits(EdgeSlice(rest, false), right_edge.edge))
    right_known = nullptr;
  if (!OuterBound(tape, rest, false, right_known, &hi, work)) return false;
  box[var] = Interval(lo, hi);
  if (box[var] == x) return true;  // slots are still a Forward on the box
  // Leave slots as a Forward on the narrowed box.
  if (Tape::ForwardUnivariate(univariate_.code, box[var], slots, lane_.data()).IsEmpty())
    return false;
  for (std::size_t k = 0; k < univariate_.slots.size(); ++k) slots[univariate_.slots[k]] = lane_[k];
  return true;
}

BC3Contractor::BC3Contractor(std::shared_ptr<const CompiledSystem> system, const BC3Params& params)
    : PropagationContractor(std::move(system), params.ratio, params.max_revise_calls),
      narrower_(params.epsilon, params.max_bisections),
      memories_(this->system().num_constraints()) {
  for (int c = 0; c < this->system().num_constraints(); ++c) {
    const Tape& tape = this->system().tape(c);
    memories_[c].slots.resize(tape.size());
    memories_[c].domains.resize(tape.variables().size());
  }
}

bool BC3Contractor::Revise(int c, Box& box, WorkCounters& work, bool* idempotent) {
  const Tape& tape = system().tape(c);
  const std::vector<int>& vars = tape.variables();
  const std::size_t k = vars.size();
  Memory& memory = memories_[c];
  // Each variable is narrowed against the others' domains as they are at its
  // turn, and its narrowing holds until one of them shrinks. The last revise
  // left its slots as a Forward on its final domains: only the slots that
  // depend on a variable changed since are evaluated again, and if none
  // changed, the variables from settled_from on need no narrowing until one
  // before them shrinks.
  const bool remembered = memory.valid;
  bool unchanged = remembered;
  int changed = 0;  // bit i: vars[i] changed since (Reforward sweeps all past kMaskVariables)
  for (std::size_t i = 0; remembered && i < k; ++i) {
    if (SameBits(memory.domains[i], box[vars[i]])) continue;
    unchanged = false;
    if (i < Tape::kMaskVariables) changed |= 1 << i;
  }
  memory.valid = false;  // until this revise succeeds
  std::size_t settled_from = k;
  if (unchanged) {
    settled_from = memory.settled_from;
  } else {
    const Interval root = remembered ? tape.Reforward(box, changed, memory.slots)
                                     : tape.Forward(box, memory.slots);
    if (Intersect(root, tape.range()).IsEmpty()) return false;
  }
  std::size_t last_shrunk = k;  // k: none
  for (std::size_t i = 0; i < k; ++i) {
    if (i >= settled_from && last_shrunk == k) break;
    const Interval before = box[vars[i]];
    if (!narrower_.Narrow(tape, vars[i], box, memory.slots, work)) return false;
    if (!SameBits(before, box[vars[i]])) last_shrunk = i;
  }
  // The variables after the last one that shrank were narrowed against the
  // final domains, and so was that one: when it is the first, or none shrank,
  // the constraint is at its own fixpoint.
  memory.settled_from = last_shrunk == k ? 0 : last_shrunk;
  for (std::size_t i = 0; i < k; ++i) memory.domains[i] = box[vars[i]];
  memory.valid = true;
  if (idempotent) *idempotent = memory.settled_from == 0;
  return true;
}

std::unique_ptr<Contractor> MakeBC3(const ParamMap& params, const ConstraintSystem& csp) {
  return std::make_unique<BC3Contractor>(std::make_shared<CompiledSystem>(csp),
                                         ParseParams<BC3Params>("bc3", params));
}

}  // namespace icp
