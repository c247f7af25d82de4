// ConstraintSystem: variables with domains, an expression DAG and constraints
// f(x) in [lo, hi]. Parsed from Minibex text (core/minibex_parser.h) or built in
// C++ with the Expr helpers below, e.g.
//   ConstraintSystem csp;
//   Expr x = csp.AddVariable("x", {-2, 4}), y = csp.AddVariable("y", {-1, 1});
//   csp.AddConstraint(x * x + Sqr(y), Relation::kEq, csp.Constant(2));
#ifndef ICPBENCH_CORE_CONSTRAINT_SYSTEM_H_
#define ICPBENCH_CORE_CONSTRAINT_SYSTEM_H_

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/box.h"
#include "core/expr.h"

namespace icp {

class ConstraintSystem;

// A handle to a node of a system's expression graph, with arithmetic that
// builds new nodes.
class Expr {
 public:
  Expr(ExprGraph* graph, int id) : graph_(graph), id_(id) {}
  ExprGraph* graph() const { return graph_; }
  int id() const { return id_; }

 private:
  ExprGraph* graph_;
  int id_;
};

Expr operator+(Expr a, Expr b);
Expr operator-(Expr a, Expr b);
Expr operator*(Expr a, Expr b);
Expr operator/(Expr a, Expr b);
Expr operator-(Expr a);
Expr operator+(Expr a, double b);
Expr operator+(double a, Expr b);
Expr operator-(Expr a, double b);
Expr operator-(double a, Expr b);
Expr operator*(double a, Expr b);
Expr operator*(Expr a, double b);
Expr operator/(Expr a, double b);
Expr Sqr(Expr a);
Expr Pow(Expr a, int n);
Expr Sqrt(Expr a);
Expr Exp(Expr a);
Expr Log(Expr a);
Expr Sin(Expr a);
Expr Cos(Expr a);
Expr Tan(Expr a);
Expr Atan(Expr a);
Expr Sinh(Expr a);
Expr Cosh(Expr a);
Expr Tanh(Expr a);
Expr Abs(Expr a);
Expr Min(Expr a, Expr b);
Expr Max(Expr a, Expr b);
// The argument of the vector (x, y) in [-pi, pi] (thesis 003 §4.7.3): y first,
// as C's atan2 and Minibex's.
Expr Atan2(Expr y, Expr x);

enum class Relation { kEq, kLeq, kGeq };

// f(x) in range, with f the expression node root.
struct Constraint {
  int root = -1;
  Interval range;
};

class ConstraintSystem {
 public:
  ConstraintSystem() : graph_(std::make_unique<ExprGraph>()) {}
  ConstraintSystem(const ConstraintSystem& other);
  ConstraintSystem& operator=(const ConstraintSystem& other);
  ConstraintSystem(ConstraintSystem&&) = default;
  ConstraintSystem& operator=(ConstraintSystem&&) = default;

  // Adds a scalar variable; names must be unique.
  Expr AddVariable(const std::string& name, const Interval& domain);
  Expr Var(int index) { return Expr(graph_.get(), graph_->Variable(index)); }
  Expr Constant(const Interval& value) { return Expr(graph_.get(), graph_->Constant(value)); }
  // lhs rel rhs, stored as lhs - rhs in {0}, ]-oo, 0] or [0, +oo[.
  void AddConstraint(Expr lhs, Relation rel, Expr rhs);
  // f in range.
  void AddConstraint(Expr f, const Interval& range);

  int num_variables() const { return static_cast<int>(names_.size()); }
  const std::vector<std::string>& names() const { return names_; }
  // Index of a variable by name, -1 if there is none.
  int FindVariable(const std::string& name) const;
  const Box& domains() const { return domains_; }
  Box& mutable_domains() { return domains_; }
  const std::vector<Constraint>& constraints() const { return constraints_; }
  const ExprGraph& graph() const { return *graph_; }
  ExprGraph& mutable_graph() { return *graph_; }
  // The same variables and domains with only the constraints at indices
  // (a sub-ICSP of a graph, paper 004 eq. 22-25).
  ConstraintSystem WithConstraints(const std::vector<int>& indices) const;
  // The constraint in Minibex syntax.
  std::string ConstraintToString(int index) const;
  // The whole system as a Minibex file that parses back to it, or to an
  // enclosure of it: domain bounds are written as the shortest decimal that
  // reads back to the same double (FormatDouble), and the parser rounds an
  // inexact decimal outward (by an ulp at most). A name that is not a
  // Minibex identifier, such as the car window's x[17], is written with
  // underscores for its other characters (x_17_); std::invalid_argument if
  // two names would then collide.
  std::string ToMinibex() const;

 private:
  std::unique_ptr<ExprGraph> graph_;
  std::vector<std::string> names_;
  std::unordered_map<std::string, int> index_of_;
  Box domains_;
  std::vector<Constraint> constraints_;
};

}  // namespace icp

#endif  // ICPBENCH_CORE_CONSTRAINT_SYSTEM_H_
