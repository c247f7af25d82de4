#include "core/expr.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace icp {

bool IsBinary(Op op) {
  switch (op) {
    case Op::kAdd: case Op::kSub: case Op::kMul: case Op::kDiv:
    case Op::kMin: case Op::kMax: case Op::kAtan2:
      return true;
    default:
      return false;
  }
}

std::string_view OpName(Op op) {
  switch (op) {
    case Op::kConst: return "const";
    case Op::kVar: return "var";
    case Op::kAdd: return "+";
    case Op::kSub: return "-";
    case Op::kMul: return "*";
    case Op::kDiv: return "/";
    case Op::kMin: return "min";
    case Op::kMax: return "max";
    case Op::kAtan2: return "atan2";
    case Op::kNeg: return "-";
    case Op::kSqr: return "sqr";
    case Op::kPow: return "^";
    case Op::kSqrt: return "sqrt";
    case Op::kExp: return "exp";
    case Op::kLog: return "log";
    case Op::kSin: return "sin";
    case Op::kCos: return "cos";
    case Op::kTan: return "tan";
    case Op::kAtan: return "atan";
    case Op::kSinh: return "sinh";
    case Op::kCosh: return "cosh";
    case Op::kTanh: return "tanh";
    case Op::kAbs: return "abs";
  }
  return "?";
}

int ExprGraph::Intern(const ExprNode& node) {
  std::string key(1, static_cast<char>(node.op));
  auto append = [&key](const void* p, std::size_t n) {
    key.append(static_cast<const char*>(p), n);
  };
  append(&node.a, sizeof node.a);
  append(&node.b, sizeof node.b);
  append(&node.n, sizeof node.n);
  if (node.op == Op::kConst) {
    double lo = node.value.lo(), hi = node.value.hi();
    append(&lo, sizeof lo);
    append(&hi, sizeof hi);
  }
  auto [it, inserted] = index_.emplace(std::move(key), size());
  if (inserted) nodes_.push_back(node);
  return it->second;
}

int ExprGraph::Constant(const Interval& value) {
  ExprNode node;
  node.op = Op::kConst;
  node.value = value;
  // A point is one real: its occurrences may share a node. An interval is
  // an enclosure of some real (a decimal such as 0.1, a measurement such as
  // a step's [ds]): two equal enclosures may hold different reals (0.1 and
  // 0.100000000000000002, two steps' equal tick intervals), so each call
  // makes a node of its own, which the contractors narrow apart. A caller
  // that means one quantity reuses its node.
  if (!(value.lo() == value.hi())) {
    nodes_.push_back(node);
    return size() - 1;
  }
  return Intern(node);
}

int ExprGraph::Variable(int index) {
  if (index < 0) throw std::invalid_argument("ExprGraph::Variable: negative index");
  ExprNode node;
  node.op = Op::kVar;
  node.n = index;
  return Intern(node);
}

int ExprGraph::Unary(Op op, int a) {
  if (IsBinary(op) || op == Op::kConst || op == Op::kVar || op == Op::kPow)
    throw std::invalid_argument("ExprGraph::Unary: not a unary operation");
  if (a < 0 || a >= size()) throw std::invalid_argument("ExprGraph::Unary: bad operand");
  ExprNode node;
  node.op = op;
  node.a = a;
  return Intern(node);
}

int ExprGraph::Binary(Op op, int a, int b) {
  if (!IsBinary(op)) throw std::invalid_argument("ExprGraph::Binary: not a binary operation");
  if (a < 0 || a >= size() || b < 0 || b >= size())
    throw std::invalid_argument("ExprGraph::Binary: bad operand");
  ExprNode node;
  node.op = op;
  node.a = a;
  node.b = b;
  return Intern(node);
}

int ExprGraph::Power(int a, int exponent) {
  if (a < 0 || a >= size()) throw std::invalid_argument("ExprGraph::Power: bad operand");
  if (exponent == 1) return a;
  if (exponent == 2) return Unary(Op::kSqr, a);
  ExprNode node;
  node.op = Op::kPow;
  node.a = a;
  node.n = exponent;
  return Intern(node);
}

std::string ExprGraph::ToString(int id, const std::vector<std::string>& names) const {
  const ExprNode& e = nodes_[id];
  switch (e.op) {
    case Op::kConst: {
      char buf[96];
      if (e.value.IsPoint())
        std::snprintf(buf, sizeof buf, "%.17g", e.value.lo());
      else
        std::snprintf(buf, sizeof buf, "[%.17g,%.17g]", e.value.lo(), e.value.hi());
      return buf;
    }
    case Op::kVar:
      return e.n < static_cast<int>(names.size()) ? names[e.n] : "v" + std::to_string(e.n);
    case Op::kAdd: case Op::kSub: case Op::kMul: case Op::kDiv:
      return "(" + ToString(e.a, names) + std::string(OpName(e.op)) + ToString(e.b, names) + ")";
    case Op::kMin: case Op::kMax: case Op::kAtan2:
      return std::string(OpName(e.op)) + "(" + ToString(e.a, names) + "," + ToString(e.b, names) + ")";
    case Op::kNeg:
      return "(-" + ToString(e.a, names) + ")";
    case Op::kPow:
      return "(" + ToString(e.a, names) + "^" + std::to_string(e.n) + ")";
    default:
      return std::string(OpName(e.op)) + "(" + ToString(e.a, names) + ")";
  }
}

}  // namespace icp
