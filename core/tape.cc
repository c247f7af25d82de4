#include "core/tape.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "core/ops.h"

namespace icp {

namespace {
// Appends to out, ascending, the slots of code that depend on a variable n
// with selected(n): its own and every operation above them (ids are
// topologically ordered, so one upward pass).
template <class Selected>
void AppendDependentSlots(const std::vector<TapeInstr>& code, Selected selected,
                          std::vector<int>& out) {
  std::vector<char> depends(code.size());
  for (std::size_t s = 0; s < code.size(); ++s) {
    const TapeInstr& in = code[s];
    depends[s] = in.op == Op::kVar ? selected(in.n)
                                   : (in.a >= 0 && depends[in.a]) || (in.b >= 0 && depends[in.b]);
    if (depends[s]) out.push_back(static_cast<int>(s));
  }
}
}  // namespace

Tape::Tape(const ExprGraph& graph, const Constraint& constraint) : range_(constraint.range) {
  if (constraint.root < 0 || constraint.root >= graph.size())
    throw std::invalid_argument("Tape: constraint root is not a node of the graph");
  // The reachable nodes, found from the root (not by a scan of every node
  // below it: m constraints over one graph would cost O(m^2)), ascending:
  // ids are already topologically ordered.
  // marked: a flag per node of the graphs seen so far, kept per thread and
  // cleared after use, so that a tape costs its own size only.
  thread_local std::vector<char> marked;
  if (marked.size() <= static_cast<std::size_t>(constraint.root)) marked.resize(constraint.root + 1, 0);
  std::vector<int> ids;
  struct Unmark {  // also when an allocation throws: a stale mark would drop a node from a later tape
    std::vector<int>& ids;
    ~Unmark() {
      for (int id : ids) marked[id] = 0;
    }
  } unmark{ids};
  ids.push_back(constraint.root);
  marked[constraint.root] = 1;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const ExprNode& e = graph.node(ids[k]);
    for (int operand : {e.a, e.b})
      if (operand >= 0 && !marked[operand]) {
        ids.push_back(operand);  // before the mark: a throwing push leaves no mark behind
        marked[operand] = 1;
      }
  }
  std::sort(ids.begin(), ids.end());
  auto slot_of = [&ids](int id) {
    return static_cast<int>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
  };
  for (int id : ids) {
    const ExprNode& e = graph.node(id);
    TapeInstr in{e.op, e.a >= 0 ? slot_of(e.a) : -1, e.b >= 0 ? slot_of(e.b) : -1, e.n};
    code_.push_back(in);
    constants_.push_back(e.op == Op::kConst ? e.value : Interval());
  }
  // Constant folding: an operation on constants only is evaluated once here,
  // exactly as Forward would on every call, and becomes a constant slot, so
  // that neither sweep spends time on it.
  for (int s = 0; s < size(); ++s) {
    TapeInstr& in = code_[s];
    if (in.op == Op::kConst || in.op == Op::kVar) continue;
    const int b = in.b >= 0 ? in.b : in.a;
    if (code_[in.a].op != Op::kConst || code_[b].op != Op::kConst) continue;
    constants_[s] = EvalOp(in.op, constants_[in.a], constants_[b], in.n);
    in = TapeInstr{Op::kConst, -1, -1, 0};
  }
  // Occurrences: number of root-to-node paths (uses of shared nodes count).
  std::vector<double> paths(code_.size(), 0);
  paths.back() = 1;
  for (int s = size() - 1; s >= 0; --s) {
    if (code_[s].a >= 0) paths[code_[s].a] += paths[s];
    if (code_[s].b >= 0) paths[code_[s].b] += paths[s];
  }
  std::map<int, int> occ;
  for (int s = 0; s < size(); ++s)
    if (code_[s].op == Op::kVar)
      occ[code_[s].n] = static_cast<int>(std::min(paths[s], 1e9));
  idempotent_when_bounded_ = true;
  for (auto [var, count] : occ) {
    variables_.push_back(var);
    occurrences_.push_back(count);
    if (count > 1) idempotent_when_bounded_ = false;
  }
  // Dependent slots, per variable and, for few variables, per set of them.
  dependent_begin_.push_back(0);
  for (int var : variables_) {
    AppendDependentSlots(code_, [var](int n) { return n == var; }, dependent_slots_);
    dependent_begin_.push_back(static_cast<int>(dependent_slots_.size()));
  }
  // The sweeps' code: an operand that depends on the variable is read from
  // the lane, at its place among the dependent slots.
  std::vector<int> lane_of(code_.size(), -1);  // -1 outside the variable's dependent slots
  auto operand = [&lane_of](int slot) { return lane_of[slot] >= 0 ? ~lane_of[slot] : slot; };
  for (std::size_t i = 0; i < variables_.size(); ++i) {
    for (int k = dependent_begin_[i]; k < dependent_begin_[i + 1]; ++k)
      lane_of[dependent_slots_[k]] = k - dependent_begin_[i];
    for (int k = dependent_begin_[i]; k < dependent_begin_[i + 1]; ++k) {
      const TapeInstr& in = code_[dependent_slots_[k]];
      if (in.op == Op::kVar) {
        univariate_code_.push_back({Op::kVar, 0, 0, in.n});
        continue;
      }
      const int a = operand(in.a);
      univariate_code_.push_back({in.op, a, in.b >= 0 ? operand(in.b) : a, in.n});
    }
    for (int k = dependent_begin_[i]; k < dependent_begin_[i + 1]; ++k)
      lane_of[dependent_slots_[k]] = -1;
  }
  if (variables_.size() <= kMaskVariables) {
    for (int m = 0; m < (1 << variables_.size()); ++m) {
      recompute_begin_.push_back(static_cast<int>(recompute_slots_.size()));
      auto in_mask = [this, m](int n) {
        const auto i = std::lower_bound(variables_.begin(), variables_.end(), n) - variables_.begin();
        return ((m >> i) & 1) != 0;
      };
      AppendDependentSlots(code_, in_mask, recompute_slots_);
    }
    recompute_begin_.push_back(static_cast<int>(recompute_slots_.size()));
  }
  for (const TapeInstr& in : code_) {
    if (in.op == Op::kDiv || in.op == Op::kTan || in.op == Op::kLog || in.op == Op::kAtan2 ||
        (in.op == Op::kPow && in.n < 0))
      idempotent_when_bounded_ = false;
    if (in.op == Op::kSqrt || in.op == Op::kLog) has_partial_ops_ = true;
  }
}

int Tape::Occurrences(int var) const {
  auto it = std::lower_bound(variables_.begin(), variables_.end(), var);
  if (it == variables_.end() || *it != var) return 0;
  return occurrences_[it - variables_.begin()];
}

namespace {
// An operand of a univariate sweep: a slot of the Forward or a lane value.
inline const Interval& Operand(int ref, const std::vector<Interval>& slots, const Interval* lane) {
  return ref >= 0 ? slots[ref] : lane[~ref];
}

// The sweep of ForwardUnivariate from code[begin] on, lane[0 .. begin)
// already computed.
Interval SweepUnivariate(std::span<const UnivariateInstr> code, std::size_t begin,
                         const Interval& x, const std::vector<Interval>& slots, Interval* lane) {
  for (std::size_t k = begin; k < code.size(); ++k) {
    const UnivariateInstr& in = code[k];
    if (in.op == Op::kVar) {
      lane[k] = x;
      continue;
    }
    lane[k] = EvalOp<true>(in.op, Operand(in.a, slots, lane), Operand(in.b, slots, lane), in.n);
    if (lane[k].IsEmpty()) return Interval::Empty();
  }
  return lane[code.size() - 1];
}
}  // namespace

Interval Tape::ForwardUnivariate(std::span<const UnivariateInstr> code, const Interval& x,
                                 const std::vector<Interval>& slots, Interval* lane) {
  if (x.IsEmpty()) return Interval::Empty();
  return SweepUnivariate(code, 0, x, slots, lane);
}

std::pair<Interval, Interval> Tape::ForwardUnivariatePair(std::span<const UnivariateInstr> code,
                                                         const Interval& x, const Interval& y,
                                                         const std::vector<Interval>& slots,
                                                         Interval* lane_x, Interval* lane_y) {
  if (x.IsEmpty() || y.IsEmpty())
    return {ForwardUnivariate(code, x, slots, lane_x), ForwardUnivariate(code, y, slots, lane_y)};
  // Both lanes step together until one of them is empty; the other then
  // finishes alone. (The step is SweepUnivariate's, written out: shared
  // through an inline helper, BC3 executed 1.3 % more instructions.)
  for (std::size_t k = 0; k < code.size(); ++k) {
    const UnivariateInstr& in = code[k];
    if (in.op == Op::kVar) {
      lane_x[k] = x;
      lane_y[k] = y;
      continue;
    }
    lane_x[k] = EvalOp<true>(in.op, Operand(in.a, slots, lane_x), Operand(in.b, slots, lane_x), in.n);
    lane_y[k] = EvalOp<true>(in.op, Operand(in.a, slots, lane_y), Operand(in.b, slots, lane_y), in.n);
    const bool x_empty = lane_x[k].IsEmpty(), y_empty = lane_y[k].IsEmpty();
    if (x_empty || y_empty) {
      return {x_empty ? Interval::Empty() : SweepUnivariate(code, k + 1, x, slots, lane_x),
              y_empty ? Interval::Empty() : SweepUnivariate(code, k + 1, y, slots, lane_y)};
    }
  }
  return {lane_x[code.size() - 1], lane_y[code.size() - 1]};
}

Interval Tape::DerivativeUnivariate(std::span<const UnivariateInstr> code,
                                    const std::vector<Interval>& slots, const Interval* lane,
                                    Interval* dlane) {
  // The slots that do not depend on var have derivative 0.
  static const Interval kZero(0.0);
  auto derivative = [dlane](int ref) -> const Interval& { return ref >= 0 ? kZero : dlane[~ref]; };
  for (std::size_t k = 0; k < code.size(); ++k) {
    const UnivariateInstr& in = code[k];
    if (in.op == Op::kVar) {
      dlane[k] = Interval(1.0);
      continue;
    }
    dlane[k] = DerivOp(in.op, Operand(in.a, slots, lane), Operand(in.b, slots, lane), lane[k],
                       derivative(in.a), derivative(in.b), in.n);
  }
  return dlane[code.size() - 1];
}

template <bool kTrackBounded>
Interval Tape::ForwardSweep(const Box& box, std::vector<Interval>& slots, bool* bounded) const {
  if (slots.size() < code_.size()) slots.resize(code_.size());
  const int n = size();
  for (int s = 0; s < n; ++s) {
    const TapeInstr& in = code_[s];
    Interval& z = slots[s];
    if (in.op == Op::kConst) {
      z = constants_[s];
    } else if (in.op == Op::kVar) {
      z = box[in.n];
      if (z.IsEmpty()) return Interval::Empty();
      continue;
    } else {
      z = EvalOp(in.op, slots[in.a], slots[in.b >= 0 ? in.b : in.a], in.n);
    }
    if (z.IsEmpty()) return Interval::Empty();
    if (kTrackBounded && !z.IsBounded()) *bounded = false;
  }
  return slots[n - 1];
}

Interval Tape::Forward(const Box& box, std::vector<Interval>& slots) const {
  return ForwardSweep<false>(box, slots, nullptr);
}

void Tape::EvalWithDerivative(int s, const Box& box, int var, std::vector<Interval>& slots,
                              std::vector<Interval>& dslots) const {
  const TapeInstr& in = code_[s];
  Interval& z = slots[s];
  Interval& dz = dslots[s];
  if (in.op == Op::kConst) {
    z = constants_[s];
    dz = Interval(0.0);
  } else if (in.op == Op::kVar) {
    z = box[in.n];
    dz = Interval(in.n == var ? 1.0 : 0.0);
  } else {
    const int b = in.b >= 0 ? in.b : in.a;
    z = EvalOp(in.op, slots[in.a], slots[b], in.n);
    dz = DerivOp(in.op, slots[in.a], slots[b], z, dslots[in.a], dslots[b], in.n);
  }
}

Interval Tape::ForwardWithDerivative(const Box& box, int var, std::vector<Interval>& slots,
                                     std::vector<Interval>& dslots, Interval* derivative) const {
  if (slots.size() < code_.size()) slots.resize(code_.size());
  if (dslots.size() < code_.size()) dslots.resize(code_.size());
  const int n = size();
  for (int s = 0; s < n; ++s) {
    EvalWithDerivative(s, box, var, slots, dslots);
    if (slots[s].IsEmpty()) {
      *derivative = Interval::Empty();
      return Interval::Empty();
    }
  }
  *derivative = dslots[n - 1];
  return slots[n - 1];
}

template <bool kPaired>
bool Tape::Backward(Box& box, std::vector<Interval>& slots) const {
  const int n = size();
  Interval& root = slots[n - 1];
  const Interval narrowed = Intersect(root, range_);
  if (narrowed.IsEmpty()) return false;
  // A projection whose result set z still holds its forward enclosure keeps
  // every operand value where the operation is defined (each has a partner
  // with op(a, b) in z), and a sound projection intersected with the operand
  // then returns the operand itself. So only slots narrowed below their
  // forward value are projected: if the root already lies in range, nothing
  // can change. Tapes with sqrt or log, whose projections also cut the
  // operand to the function's domain, are swept in full.
  if (narrowed == root && !has_partial_ops_) return true;
  root = narrowed;
  constexpr int kStackSlots = 256;
  char stack_changed[kStackSlots];
  std::vector<char> heap_changed;
  char* changed = stack_changed;
  if (n > kStackSlots) {
    heap_changed.assign(n, has_partial_ops_);
    changed = heap_changed.data();
  } else {
    std::fill(stack_changed, stack_changed + n, has_partial_ops_);
  }
  changed[n - 1] = 1;
  Interval unused;
  for (int s = n - 1; s >= 0; --s) {
    if (!changed[s]) continue;
    const TapeInstr& in = code_[s];
    if (in.op == Op::kConst) continue;  // narrowed constants are not written back
    if (in.op == Op::kVar) {
      box[in.n] = slots[s];  // started as box[in.n] and only shrank
      continue;
    }
    Interval& a = slots[in.a];
    Interval& b = in.b >= 0 ? slots[in.b] : unused;
    const Interval a_before = a;
    const Interval b_before = b;
    ProjectOp<kPaired>(in.op, slots[s], a, b, in.n);
    if (a.IsEmpty() || b.IsEmpty()) return false;
    if (!(a == a_before)) changed[in.a] = 1;
    if (in.b >= 0 && !(b == b_before)) changed[in.b] = 1;
  }
  return true;
}

template bool Tape::Backward<false>(Box&, std::vector<Interval>&) const;
template bool Tape::Backward<true>(Box&, std::vector<Interval>&) const;

bool Tape::Revise(Box& box, std::vector<Interval>& slots, bool* idempotent) const {
  if (idempotent && idempotent_when_bounded_) {
    bool bounded = true;
    if (ForwardSweep<true>(box, slots, &bounded).IsEmpty()) return false;
    *idempotent = bounded;
  } else {
    if (Forward(box, slots).IsEmpty()) return false;
    if (idempotent) *idempotent = false;
  }
  return Backward(box, slots);
}

// ForwardIncremental keeps its own copy of this loop, with the count of
// unbounded slots: sharing one through a helper cost 3B 1-2 % of its
// instructions (callgrind, 100 lap steps), even inlined.
Interval Tape::Reforward(const Box& box, int changed, std::vector<Interval>& slots) const {
  if (static_cast<int>(variables_.size()) > kMaskVariables) return Forward(box, slots);
  for (int k = recompute_begin_[changed]; k < recompute_begin_[changed + 1]; ++k) {
    const int s = recompute_slots_[k];
    const TapeInstr& in = code_[s];
    Interval& z = slots[s];
    if (in.op == Op::kVar) {
      z = box[in.n];
    } else {
      z = EvalOp<true>(in.op, slots[in.a], slots[in.b >= 0 ? in.b : in.a], in.n);
    }
    if (z.IsEmpty()) return Interval::Empty();
  }
  return slots[size() - 1];
}

Interval Tape::ForwardIncremental(const Box& box, ForwardMemory& memory,
                                  std::vector<Interval>& slots) const {
  const int n = size();
  const int num_vars = static_cast<int>(variables_.size());
  if (slots.size() < code_.size()) slots.resize(code_.size());
  auto unbounded = [this](int s, const Interval& z) {
    return code_[s].op != Op::kVar && !z.IsBounded();
  };
  if (memory.slots_.size() != code_.size() || num_vars > kMaskVariables) {
    memory.slots_.resize(code_.size());
    memory.inputs_.resize(variables_.size());
    if (Forward(box, memory.slots_).IsEmpty()) {
      memory.slots_.clear();
      return Interval::Empty();
    }
    for (int i = 0; i < num_vars; ++i) memory.inputs_[i] = box[variables_[i]];
    memory.unbounded_ = 0;
    for (int s = 0; s < n; ++s) memory.unbounded_ += unbounded(s, memory.slots_[s]);
  } else {
    int mask = 0;
    for (int i = 0; i < num_vars; ++i) {
      const Interval& x = box[variables_[i]];
      if (SameBits(x, memory.inputs_[i])) continue;
      mask |= 1 << i;
      memory.inputs_[i] = x;
    }
    for (int k = recompute_begin_[mask]; k < recompute_begin_[mask + 1]; ++k) {
      const int s = recompute_slots_[k];
      const TapeInstr& in = code_[s];
      Interval& z = memory.slots_[s];
      if (in.op == Op::kVar) {
        z = box[in.n];  // variables are not counted in unbounded_
      } else {
        const bool was_unbounded = !z.IsBounded();
        z = EvalOp<true>(in.op, memory.slots_[in.a], memory.slots_[in.b >= 0 ? in.b : in.a], in.n);
        memory.unbounded_ += static_cast<int>(!z.IsBounded()) - static_cast<int>(was_unbounded);
      }
      if (z.IsEmpty()) {
        memory.slots_.clear();
        return Interval::Empty();
      }
    }
  }
  std::copy(memory.slots_.begin(), memory.slots_.end(), slots.begin());
  return slots[n - 1];
}

bool Tape::ReviseIncremental(Box& box, ForwardMemory& memory, std::vector<Interval>& slots,
                             bool* idempotent) const {
  if (ForwardIncremental(box, memory, slots).IsEmpty()) return false;
  // As Revise: every operation's and constant's enclosure bounded.
  if (idempotent) *idempotent = idempotent_when_bounded_ && memory.unbounded_ == 0;
  return Backward<true>(box, slots);
}

CompiledSystem::CompiledSystem(const ConstraintSystem& system)
    : num_variables_(system.num_variables()), constraints_of_(system.num_variables()) {
  tapes_.reserve(system.constraints().size());
  for (const Constraint& c : system.constraints()) {
    tapes_.emplace_back(system.graph(), c);
    const Tape& t = tapes_.back();
    for (int v : t.variables()) {
      if (v >= num_variables_)
        throw std::invalid_argument("constraint uses variable index " + std::to_string(v) +
                                    " but the system has " + std::to_string(num_variables_));
      constraints_of_[v].push_back(num_constraints() - 1);
    }
    max_tape_size_ = std::max(max_tape_size_, t.size());
  }
}

}  // namespace icp
