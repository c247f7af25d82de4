// The expression DAG: constraints are data. Nodes are hash-consed, so equal
// sub-expressions are shared, and a node's children always have smaller ids
// (the node vector is a topological order). Interval (non-point) constants
// are not: each stands for a real of its own (ExprGraph::Constant).
#ifndef ICPBENCH_CORE_EXPR_H_
#define ICPBENCH_CORE_EXPR_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/interval.h"

namespace icp {

enum class Op : std::uint8_t {
  kConst, kVar,
  kAdd, kSub, kMul, kDiv, kMin, kMax, kAtan2,  // binary (kAtan2: atan2(a, b), a the y)
  kNeg, kSqr, kPow, kSqrt, kExp, kLog, kSin, kCos, kTan, kAtan,
  kSinh, kCosh, kTanh, kAbs,           // unary (kPow carries its exponent)
};

bool IsBinary(Op op);
std::string_view OpName(Op op);

struct ExprNode {
  Op op = Op::kConst;
  int a = -1;        // first operand (node id)
  int b = -1;        // second operand (node id), binary ops only
  int n = 0;         // variable index (kVar) or integer exponent (kPow)
  Interval value;    // constant enclosure (kConst)
};

class ExprGraph {
 public:
  int Constant(const Interval& value);
  int Variable(int index);
  int Unary(Op op, int a);
  int Binary(Op op, int a, int b);
  int Power(int a, int exponent);

  const ExprNode& node(int id) const { return nodes_[id]; }
  int size() const { return static_cast<int>(nodes_.size()); }
  // Infix text of a node, with variable names from names.
  std::string ToString(int id, const std::vector<std::string>& names) const;

 private:
  int Intern(const ExprNode& node);
  std::vector<ExprNode> nodes_;
  std::unordered_map<std::string, int> index_;  // structural key -> id
};

}  // namespace icp

#endif  // ICPBENCH_CORE_EXPR_H_
