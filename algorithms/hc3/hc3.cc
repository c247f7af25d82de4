#include "algorithms/hc3/hc3.h"

#include "core/ops.h"

namespace icp {

void Describe(HC3Params& p, ParamSet& set) {
  set.Add("ratio", &p.ratio,
          "relative width decrease of a variable that re-queues its primitives",
          Range::HalfOpen(0, 1));
  set.Add("max_revise_calls", &p.max_revise_calls,
          "primitive revisions allowed per contraction before stopping", Range::AtLeast(1));
}

HC3Contractor::HC3Contractor(const ConstraintSystem& csp, const HC3Params& params)
    : params_(params), num_variables_(csp.num_variables()) {
  const ExprGraph& g = csp.graph();
  // Nodes used by some constraint; children have smaller ids than parents.
  std::vector<char> used(g.size(), 0);
  for (const Constraint& c : csp.constraints()) used[c.root] = 1;
  for (int id = g.size() - 1; id >= 0; --id) {
    if (!used[id]) continue;
    if (g.node(id).a >= 0) used[g.node(id).a] = 1;
    if (g.node(id).b >= 0) used[g.node(id).b] = 1;
  }
  // Extended variables: the originals, then one per constant or operation node.
  initial_ = Box(num_variables_);
  root_range_.assign(num_variables_, Interval());
  std::vector<int> var_of(g.size(), -1);
  for (int id = 0; id < g.size(); ++id) {
    if (!used[id]) continue;
    const ExprNode& e = g.node(id);
    if (e.op == Op::kVar) {
      var_of[id] = e.n;
      continue;
    }
    var_of[id] = static_cast<int>(initial_.size());
    initial_.push_back(e.op == Op::kConst ? e.value : Interval());
    if (e.op != Op::kConst)
      primitives_.push_back({e.op, var_of[id], var_of[e.a], e.b >= 0 ? var_of[e.b] : -1, e.n});
  }
  // A constraint f in R restricts f's variable: an auxiliary's initial
  // domain, or (for "x in R") the original variable at every call.
  for (const Constraint& c : csp.constraints()) {
    int v = var_of[c.root];
    if (v < num_variables_) {
      root_range_[v] = Intersect(root_range_[v], c.range);
    } else {
      initial_[v] = Intersect(initial_[v], c.range);
    }
  }
  // Topological order (children before parents): forward revises first.
  std::vector<std::vector<int>> scopes;
  for (const Primitive& q : primitives_) {
    scopes.push_back({q.z, q.a});
    if (q.b >= 0 && q.b != q.a) scopes.back().push_back(q.b);
  }
  propagation_ = Propagation(static_cast<int>(initial_.size()), std::move(scopes), params_.ratio,
                             params_.max_revise_calls);
}

bool HC3Contractor::Revise(int p, Box& extended, WorkCounters&, bool*) {
  const Primitive& q = primitives_[p];
  Interval unused;
  Interval& b = q.b >= 0 ? extended[q.b] : unused;
  extended[q.z] = Intersect(extended[q.z], EvalOp(q.op, extended[q.a], b, q.n));
  if (extended[q.z].IsEmpty()) return false;
  ProjectOp(q.op, extended[q.z], extended[q.a], b, q.n);
  return !extended[q.a].IsEmpty() && !b.IsEmpty();
}

ContractSummary HC3Contractor::Contract(Box& box, ContractContext& context) {
  extended_ = initial_;
  for (int v = 0; v < num_variables_; ++v) extended_[v] = Intersect(box[v], root_range_[v]);
  ContractSummary summary{ContractStatus::kEmpty, "", {}};
  if (!extended_.IsEmpty()) {
    // The auxiliaries start afresh, so every primitive is revised.
    ContractContext fresh(context.stop());
    summary = propagation_.Run(extended_, fresh, *this);
  }
  if (summary.status == ContractStatus::kEmpty) {
    box.SetEmpty();
    return summary;
  }
  bool shrank = false;
  for (int v = 0; v < num_variables_; ++v) {
    shrank |= !(extended_[v] == box[v]);
    box[v] = extended_[v];
  }
  if (summary.status != ContractStatus::kStopped)
    summary.status = shrank ? ContractStatus::kContracted : ContractStatus::kFixpoint;
  return summary;
}

std::unique_ptr<Contractor> MakeHC3(const ParamMap& params, const ConstraintSystem& csp) {
  return std::make_unique<HC3Contractor>(csp, ParseParams<HC3Params>("hc3", params));
}

}  // namespace icp
