#include "tests/bc3_reference.h"

#include <algorithm>
#include <cmath>

#include "core/projections.h"

namespace icp::testing {

bool ReferenceBoxNarrower::Small(const Interval& j) const {
  return j.IsBounded() && j.Width() <= epsilon_ * std::max(1.0, j.Mag());
}

bool ReferenceBoxNarrower::Consistent(const Tape& tape, int var, const Interval& j) {
  work_box_[var] = j;
  return !Intersect(tape.Forward(work_box_, slots_), tape.range()).IsEmpty();
}

Interval ReferenceBoxNarrower::Newton(const Tape& tape, int var, Interval j, WorkCounters& work) {
  for (int step = 0; step < 8 && !j.IsEmpty(); ++step) {
    ++work.newton_steps;
    work_box_[var] = j;
    Interval derivative;
    Interval f = tape.ForwardWithDerivative(work_box_, var, slots_, dslots_, &derivative);
    if (Intersect(f, tape.range()).IsEmpty()) return Interval::Empty();
    if (Small(j)) return j;
    const double m = j.Mid();
    work_box_[var] = Interval(m);
    Interval fm = tape.Forward(work_box_, slots_);
    if (fm.IsEmpty()) return j;
    Interval next = Interval(m) + DivideRelational(j - Interval(m), tape.range() - fm, derivative);
    next = Intersect(j, next);
    if (next.IsEmpty()) return next;
    const bool progress = next.Width() < 0.9 * j.Width();
    j = next;
    if (!progress) break;
  }
  return j;
}

std::optional<double> ReferenceBoxNarrower::OuterBound(const Tape& tape, int var,
                                                       const Interval& x, bool leftward,
                                                       WorkCounters& work) {
  auto outer = [leftward](const Interval& j) { return leftward ? j.lo() : j.hi(); };
  if (x.IsBounded()) {
    const double b = outer(x);
    const double slice = epsilon_ * std::max(1.0, std::fabs(b));
    Interval edge = leftward ? Interval(b, std::min(x.hi(), b + slice))
                             : Interval(std::max(x.lo(), b - slice), b);
    if (Consistent(tape, var, edge)) return b;
  }
  stack_.clear();
  stack_.push_back(x);
  int bisections = 0;
  while (!stack_.empty()) {
    Interval j = stack_.back();
    stack_.pop_back();
    j = Newton(tape, var, j, work);
    if (j.IsEmpty()) continue;
    if (Small(j)) return outer(j);
    if (bisections >= max_bisections_) {
      double bound = outer(j);
      for (const Interval& rest : stack_)
        bound = leftward ? std::min(bound, rest.lo()) : std::max(bound, rest.hi());
      return bound;
    }
    ++bisections;
    ++work.bisections;
    const double m = j.Mid();
    Interval low(j.lo(), m), high(m, j.hi());
    if (leftward) {
      stack_.push_back(high);
      stack_.push_back(low);
    } else {
      stack_.push_back(low);
      stack_.push_back(high);
    }
  }
  return std::nullopt;
}

bool ReferenceBoxNarrower::Narrow(const Tape& tape, int var, Box& box, WorkCounters& work) {
  work_box_ = box;
  const Interval x = box[var];
  std::optional<double> lo = OuterBound(tape, var, x, true, work);
  if (!lo) return false;
  std::optional<double> hi = OuterBound(tape, var, Interval(*lo, x.hi()), false, work);
  if (!hi) return false;
  box[var] = Interval(*lo, *hi);
  return true;
}

ReferenceBC3Contractor::ReferenceBC3Contractor(std::shared_ptr<const CompiledSystem> system,
                                               const BC3Params& params)
    : PropagationContractor(std::move(system), params.ratio, params.max_revise_calls),
      narrower_(params.epsilon, params.max_bisections) {}

bool ReferenceBC3Contractor::Revise(int c, Box& box, WorkCounters& work, bool*) {
  const Tape& tape = system().tape(c);
  if (tape.variables().empty()) {
    return !Intersect(tape.Forward(box, scratch_), tape.range()).IsEmpty();
  }
  for (int v : tape.variables())
    if (!narrower_.Narrow(tape, v, box, work)) return false;
  return true;
}

ReferenceBC4Contractor::ReferenceBC4Contractor(std::shared_ptr<const CompiledSystem> system,
                                               const BC3Params& params)
    : PropagationContractor(std::move(system), params.ratio, params.max_revise_calls),
      narrower_(params.epsilon, params.max_bisections),
      slots_(this->system().max_tape_size()),
      multiple_(this->system().num_constraints()) {
  for (int c = 0; c < this->system().num_constraints(); ++c) {
    const Tape& t = this->system().tape(c);
    for (int v : t.variables())
      if (t.Occurrences(v) > 1) multiple_[c].push_back(v);
  }
}

bool ReferenceBC4Contractor::Revise(int c, Box& box, WorkCounters& work, bool* idempotent) {
  const Tape& tape = system().tape(c);
  if (!tape.Revise(box, slots_, multiple_[c].empty() ? idempotent : nullptr)) return false;
  for (int v : multiple_[c])
    if (!narrower_.Narrow(tape, v, box, work)) return false;
  return true;
}

}  // namespace icp::testing
