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
  initial_.assign(num_variables_, Interval());
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
  primitives_of_.resize(initial_.size());
  for (int p = 0; p < num_primitives(); ++p) {
    const Primitive& q = primitives_[p];
    primitives_of_[q.z].push_back(p);
    primitives_of_[q.a].push_back(p);
    if (q.b >= 0 && q.b != q.a) primitives_of_[q.b].push_back(p);
  }
}

ContractSummary HC3Contractor::Contract(Box& box, ContractContext& context) {
  ContractSummary summary;
  const Box start = box;
  std::vector<Interval> d = initial_;
  for (int v = 0; v < num_variables_; ++v) d[v] = Intersect(box[v], root_range_[v]);
  auto empty_result = [&] {
    box.SetEmpty();
    summary.status = ContractStatus::kEmpty;
    return summary;
  };
  for (const Interval& x : d)
    if (x.IsEmpty()) return empty_result();

  const int m = num_primitives();
  std::vector<int> queue(m);
  std::vector<char> queued(m, 1);
  for (int p = 0; p < m; ++p) queue[p] = p;  // topological order: forward first
  std::size_t head = 0, count = m;
  Interval unused;
  Interval before[3];
  while (count > 0) {
    if (summary.work.revise_calls >= params_.max_revise_calls ||
        ((summary.work.revise_calls & 1023) == 1023 && context.stop().ShouldStop())) {
      summary.status = ContractStatus::kStopped;
      summary.message = summary.work.revise_calls >= params_.max_revise_calls
                            ? "max_revise_calls reached"
                            : "stopped (time limit)";
      for (int v = 0; v < num_variables_; ++v) box[v] = d[v];
      return summary;
    }
    const int p = queue[head];
    head = (head + 1) % m;
    --count;
    queued[p] = 0;
    const Primitive& q = primitives_[p];
    const int vars[3] = {q.z, q.a, q.b};
    for (int i = 0; i < 3; ++i) before[i] = vars[i] >= 0 ? d[vars[i]] : Interval();
    ++summary.work.revise_calls;
    Interval& b = q.b >= 0 ? d[q.b] : unused;
    d[q.z] = Intersect(d[q.z], EvalOp(q.op, d[q.a], b, q.n));
    if (d[q.z].IsEmpty()) return empty_result();
    ProjectOp(q.op, d[q.z], d[q.a], b, q.n);
    if (d[q.a].IsEmpty() || b.IsEmpty()) return empty_result();
    for (int i = 0; i < 3; ++i) {
      if (vars[i] < 0 || !ShrankByMoreThan(before[i], d[vars[i]], params_.ratio)) continue;
      for (int other : primitives_of_[vars[i]]) {
        if (queued[other]) continue;
        queued[other] = 1;
        queue[(head + count) % m] = other;
        ++count;
      }
    }
  }
  for (int v = 0; v < num_variables_; ++v) box[v] = d[v];
  summary.status = StatusOf(start, box);
  return summary;
}

std::unique_ptr<Contractor> MakeHC3(const ParamMap& params, const ConstraintSystem& csp) {
  return std::make_unique<HC3Contractor>(csp, ParseParams<HC3Params>("hc3", params));
}

}  // namespace icp
