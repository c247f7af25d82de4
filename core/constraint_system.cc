#include "core/constraint_system.h"

#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <unordered_set>

#include "core/params.h"

namespace icp {

namespace {
ExprGraph* SameGraph(Expr a, Expr b) {
  if (a.graph() != b.graph())
    throw std::invalid_argument("Expr: operands belong to different constraint systems");
  return a.graph();
}
Expr Bin(Op op, Expr a, Expr b) {
  ExprGraph* g = SameGraph(a, b);
  return Expr(g, g->Binary(op, a.id(), b.id()));
}
Expr Un(Op op, Expr a) { return Expr(a.graph(), a.graph()->Unary(op, a.id())); }
Expr Const(Expr like, double v) { return Expr(like.graph(), like.graph()->Constant(Interval(v))); }
}  // namespace

Expr operator+(Expr a, Expr b) { return Bin(Op::kAdd, a, b); }
Expr operator-(Expr a, Expr b) { return Bin(Op::kSub, a, b); }
Expr operator*(Expr a, Expr b) { return Bin(Op::kMul, a, b); }
Expr operator/(Expr a, Expr b) { return Bin(Op::kDiv, a, b); }
Expr operator-(Expr a) { return Un(Op::kNeg, a); }
Expr operator+(Expr a, double b) { return a + Const(a, b); }
Expr operator+(double a, Expr b) { return Const(b, a) + b; }
Expr operator-(Expr a, double b) { return a - Const(a, b); }
Expr operator-(double a, Expr b) { return Const(b, a) - b; }
Expr operator*(double a, Expr b) { return Const(b, a) * b; }
Expr operator*(Expr a, double b) { return a * Const(a, b); }
Expr operator/(Expr a, double b) { return a / Const(a, b); }
Expr Sqr(Expr a) { return Un(Op::kSqr, a); }
Expr Pow(Expr a, int n) {
  if (n == 0) return Const(a, 1.0);
  if (n < 0) return Const(a, 1.0) / Pow(a, -n);
  return Expr(a.graph(), a.graph()->Power(a.id(), n));
}
Expr Sqrt(Expr a) { return Un(Op::kSqrt, a); }
Expr Exp(Expr a) { return Un(Op::kExp, a); }
Expr Log(Expr a) { return Un(Op::kLog, a); }
Expr Sin(Expr a) { return Un(Op::kSin, a); }
Expr Cos(Expr a) { return Un(Op::kCos, a); }
Expr Tan(Expr a) { return Un(Op::kTan, a); }
Expr Atan(Expr a) { return Un(Op::kAtan, a); }
Expr Sinh(Expr a) { return Un(Op::kSinh, a); }
Expr Cosh(Expr a) { return Un(Op::kCosh, a); }
Expr Tanh(Expr a) { return Un(Op::kTanh, a); }
Expr Abs(Expr a) { return Un(Op::kAbs, a); }
Expr Min(Expr a, Expr b) { return Bin(Op::kMin, a, b); }
Expr Max(Expr a, Expr b) { return Bin(Op::kMax, a, b); }
Expr Atan2(Expr y, Expr x) { return Bin(Op::kAtan2, y, x); }

ConstraintSystem::ConstraintSystem(const ConstraintSystem& other)
    : graph_(std::make_unique<ExprGraph>(*other.graph_)),
      names_(other.names_),
      index_of_(other.index_of_),
      domains_(other.domains_),
      constraints_(other.constraints_) {}

ConstraintSystem& ConstraintSystem::operator=(const ConstraintSystem& other) {
  if (this != &other) *this = ConstraintSystem(other);
  return *this;
}

ConstraintSystem ConstraintSystem::WithConstraints(const std::vector<int>& indices) const {
  ConstraintSystem out;
  out.names_ = names_;
  out.index_of_ = index_of_;
  out.domains_ = domains_;
  // Only the nodes the kept constraints reach, so that a small ICSP of a
  // large graph is small: children have smaller ids, so one pass down from
  // the roots marks them and one pass up copies them.
  std::vector<char> reached(graph_->size(), 0);
  for (int i : indices) {
    if (i < 0 || i >= static_cast<int>(constraints_.size()))
      throw std::out_of_range("constraint " + std::to_string(i) + " of " +
                              std::to_string(constraints_.size()));
    reached[constraints_[i].root] = 1;
  }
  for (int id = graph_->size() - 1; id >= 0; --id) {
    if (!reached[id]) continue;
    const ExprNode& node = graph_->node(id);
    if (node.op == Op::kConst || node.op == Op::kVar) continue;
    reached[node.a] = 1;
    if (IsBinary(node.op)) reached[node.b] = 1;
  }
  std::vector<int> copy(graph_->size(), -1);
  ExprGraph& g = *out.graph_;
  for (int id = 0; id < graph_->size(); ++id) {
    if (!reached[id]) continue;
    const ExprNode& node = graph_->node(id);
    if (node.op == Op::kConst) copy[id] = g.Constant(node.value);
    else if (node.op == Op::kVar) copy[id] = g.Variable(node.n);
    else if (node.op == Op::kPow) copy[id] = g.Power(copy[node.a], node.n);
    else if (IsBinary(node.op)) copy[id] = g.Binary(node.op, copy[node.a], copy[node.b]);
    else copy[id] = g.Unary(node.op, copy[node.a]);
  }
  for (int i : indices) out.constraints_.push_back({copy[constraints_[i].root], constraints_[i].range});
  return out;
}

Expr ConstraintSystem::AddVariable(const std::string& name, const Interval& domain) {
  if (FindVariable(name) >= 0)
    throw std::invalid_argument("variable '" + name + "' is declared twice");
  index_of_.emplace(name, num_variables());
  names_.push_back(name);
  domains_.push_back(domain);
  return Var(num_variables() - 1);
}

void ConstraintSystem::AddConstraint(Expr lhs, Relation rel, Expr rhs) {
  Interval range = rel == Relation::kEq    ? Interval(0.0)
                   : rel == Relation::kLeq ? Interval(-kInf, 0.0)
                                           : Interval(0.0, kInf);
  // "f = c" with a constant right side keeps f's tree as it is.
  const ExprNode& r = graph_->node(rhs.id());
  if (r.op == Op::kConst) {
    AddConstraint(lhs, range + r.value);
    return;
  }
  AddConstraint(lhs - rhs, range);
}

void ConstraintSystem::AddConstraint(Expr f, const Interval& range) {
  if (f.graph() != graph_.get())
    throw std::invalid_argument("AddConstraint: expression from another constraint system");
  constraints_.push_back(Constraint{f.id(), range});
}

int ConstraintSystem::FindVariable(const std::string& name) const {
  auto it = index_of_.find(name);
  return it == index_of_.end() ? -1 : it->second;
}

namespace {
// "f = v", "f <= hi", "f >= lo" or "f = [lo, hi]"; %.17g reads back to the
// same doubles.
std::string ConstraintText(const ExprGraph& graph, const Constraint& c,
                           const std::vector<std::string>& names) {
  const std::string f = graph.ToString(c.root, names);
  char buf[96];
  if (c.range.IsPoint()) {
    std::snprintf(buf, sizeof buf, " = %.17g", c.range.lo());
  } else if (c.range.lo() == -kInf && c.range.hi() == kInf) {
    std::snprintf(buf, sizeof buf, " = [-oo, +oo]");
  } else if (c.range.lo() == -kInf) {
    std::snprintf(buf, sizeof buf, " <= %.17g", c.range.hi());
  } else if (c.range.hi() == kInf) {
    std::snprintf(buf, sizeof buf, " >= %.17g", c.range.lo());
  } else {
    std::snprintf(buf, sizeof buf, " = [%.17g, %.17g]", c.range.lo(), c.range.hi());
  }
  return f + buf;
}

std::string MinibexIdentifier(const std::string& name) {
  std::string id = name;
  for (char& ch : id)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') ch = '_';
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "v_" + id;
  return id;
}
}  // namespace

std::string ConstraintSystem::ConstraintToString(int index) const {
  return ConstraintText(*graph_, constraints_.at(index), names_);
}

std::string ConstraintSystem::ToMinibex() const {
  std::vector<std::string> ids;
  std::unordered_set<std::string> seen;
  for (const std::string& name : names_) {
    ids.push_back(MinibexIdentifier(name));
    if (!seen.insert(ids.back()).second)
      throw std::invalid_argument("ToMinibex: variables '" + name + "' and another are both written '" +
                                  ids.back() + "'");
  }
  std::string text = "Variables\n";
  for (int v = 0; v < num_variables(); ++v)
    text += "  " + ids[v] + " in [" + FormatDouble(domains_[v].lo()) + ", " +
            FormatDouble(domains_[v].hi()) + "];\n";
  text += "Constraints\n";
  for (const Constraint& c : constraints_) text += "  " + ConstraintText(*graph_, c, ids) + ";\n";
  return text + "end\n";
}

}  // namespace icp
