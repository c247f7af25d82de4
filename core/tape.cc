#include "core/tape.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "core/ops.h"

namespace icp {

Tape::Tape(const ExprGraph& graph, const Constraint& constraint) : range_(constraint.range) {
  if (constraint.root < 0 || constraint.root >= graph.size())
    throw std::invalid_argument("Tape: constraint root is not a node of the graph");
  // Reachable nodes; ids are already topologically ordered.
  std::vector<char> reachable(constraint.root + 1, 0);
  reachable[constraint.root] = 1;
  for (int id = constraint.root; id >= 0; --id) {
    if (!reachable[id]) continue;
    const ExprNode& e = graph.node(id);
    if (e.a >= 0) reachable[e.a] = 1;
    if (e.b >= 0) reachable[e.b] = 1;
  }
  std::vector<int> slot_of(constraint.root + 1, -1);
  for (int id = 0; id <= constraint.root; ++id) {
    if (!reachable[id]) continue;
    const ExprNode& e = graph.node(id);
    slot_of[id] = static_cast<int>(code_.size());
    TapeInstr in{e.op, e.a >= 0 ? slot_of[e.a] : -1, e.b >= 0 ? slot_of[e.b] : -1, e.n};
    code_.push_back(in);
    constants_.push_back(e.op == Op::kConst ? e.value : Interval());
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
  for (auto [var, count] : occ) {
    variables_.push_back(var);
    occurrences_.push_back(count);
  }
}

int Tape::Occurrences(int var) const {
  auto it = std::lower_bound(variables_.begin(), variables_.end(), var);
  if (it == variables_.end() || *it != var) return 0;
  return occurrences_[it - variables_.begin()];
}

Interval Tape::Forward(const Box& box, std::vector<Interval>& slots) const {
  if (slots.size() < code_.size()) slots.resize(code_.size());
  const int n = size();
  for (int s = 0; s < n; ++s) {
    const TapeInstr& in = code_[s];
    Interval& z = slots[s];
    if (in.op == Op::kConst) {
      z = constants_[s];
    } else if (in.op == Op::kVar) {
      z = box[in.n];
    } else {
      z = EvalOp(in.op, slots[in.a], slots[in.b >= 0 ? in.b : in.a], in.n);
    }
    if (z.IsEmpty()) return Interval::Empty();
  }
  return slots[n - 1];
}

Interval Tape::ForwardWithDerivative(const Box& box, int var, std::vector<Interval>& slots,
                                     std::vector<Interval>& dslots, Interval* derivative) const {
  if (slots.size() < code_.size()) slots.resize(code_.size());
  if (dslots.size() < code_.size()) dslots.resize(code_.size());
  const int n = size();
  for (int s = 0; s < n; ++s) {
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
    if (z.IsEmpty()) {
      *derivative = Interval::Empty();
      return Interval::Empty();
    }
  }
  *derivative = dslots[n - 1];
  return slots[n - 1];
}

bool Tape::Backward(Box& box, std::vector<Interval>& slots) const {
  const int n = size();
  Interval& root = slots[n - 1];
  root = Intersect(root, range_);
  if (root.IsEmpty()) return false;
  Interval unused;
  for (int s = n - 1; s >= 0; --s) {
    const TapeInstr& in = code_[s];
    if (in.op == Op::kConst) continue;
    if (in.op == Op::kVar) {
      box[in.n] = slots[s];  // started as box[in.n] and only shrank
      continue;
    }
    Interval& b = in.b >= 0 ? slots[in.b] : unused;
    ProjectOp(in.op, slots[s], slots[in.a], b, in.n);
    if (slots[in.a].IsEmpty() || b.IsEmpty()) return false;
  }
  return true;
}

bool Tape::Revise(Box& box, std::vector<Interval>& slots) const {
  if (Forward(box, slots).IsEmpty()) return false;
  return Backward(box, slots);
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
