// Minibex names: looking them up in the scopes of function calls, indexing
// vectors and matrices, constant arrays such as ((1, 2); (3, 4)), and the
// bindings that stand for an argument's or a temporary's expression.
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/minibex_parser_internal.h"

namespace icp::detail::minibex {

std::string Shape::Describe(const std::string& name) const {
  if (is_scalar()) return "scalar '" + name + "'";
  std::string s = "'" + name + "[" + std::to_string(rows) + "]";
  if (is_matrix()) s += "[" + std::to_string(cols) + "]";
  return s + "'";
}

Symbol* Parser::Lookup(const std::string& name) {
  if (scope_ > 0) {
    auto& local = function_scopes_[scope_ - 1];
    if (auto it = local.find(name); it != local.end()) return &it->second;
  }
  auto it = symbols_.find(name);
  if (it == symbols_.end()) return nullptr;
  // A function body sees the system's constants only, as in IBEX.
  if (scope_ > 0 && it->second.kind != Symbol::kConstant) return nullptr;
  return &it->second;
}

Value Parser::Component(Symbol& s, int k) {
  switch (s.kind) {
    case Symbol::kConstant:
    case Symbol::kLoopIndex:
      return Const(s.values[k]);
    case Symbol::kVariable:
      return Node(csp_.Var(s.first + k));
    case Symbol::kBound:
      break;
  }
  return Resolve(s.bindings[k]);
}

// After a vector's or a matrix's name: (i) or [i] for a vector, (i, j) or
// [i][j] for a matrix; (..) counts from 1 as in IBEX, [..] from 0. Returns
// the component's place, row by row.
int Parser::ParseComponentIndex(const Symbol& s, const Token& name_token) {
  const std::string& name = name_token.text;
  const bool one_based = IsPunct("(");
  if (!one_based && !IsPunct("[")) {
    Fail(name_token, s.shape.is_matrix() ? "matrix '" : "vector '", name,
         "' must be indexed, as in ", name, s.shape.is_matrix() ? "(1,1) or " : "(1) or ", name,
         s.shape.is_matrix() ? "[0][0]" : "[0]");
  }
  Next();
  const int i = ParseIndex(name, one_based, s.shape.rows);
  if (!s.shape.is_matrix()) {
    Expect(one_based ? ")" : "]", {"after the index of", name});
    return i;
  }
  if (one_based) {
    if (!IsPunct(","))
      Fail(Peek(), "matrix '", name, "' takes two indices, as in ", name, "(1,1), found ", Peek());
    Next();
  } else {
    Expect("]", {"after the row index of", name});
    if (!IsPunct("["))
      Fail(Peek(), "matrix '", name, "' takes two indices, as in ", name, "[0][0], found ", Peek());
    Next();
  }
  const int j = ParseIndex(name, one_based, s.shape.cols);
  Expect(one_based ? ")" : "]", {"after the column index of", name});
  return i * s.shape.cols + j;
}

// One index, checked against size; returned 0-based.
int Parser::ParseIndex(const std::string& name, bool one_based, int size) {
  const Token& start = Peek();
  const long long i = ParseInteger({"the index of", name});
  const long long base = one_based ? 1 : 0;
  if (i < base || i >= size + base)
    Fail(start, "index ", i, " out of range for '", name, "' (", one_based ? "(..) takes 1.." : "[..] takes 0..",
         one_based ? size : size - 1, ")");
  return static_cast<int>(i - base);
}

// A constant's value: a constant expression (every component takes it, as
// in IBEX's "c[10][10] in [0,0]") or an array of the constant's shape.
std::vector<Interval> Parser::ParseConstantValue(const Token& name, const Shape& shape) {
  std::vector<Interval> values;
  if (!shape.is_scalar() && IsPunct("(") && ListAhead()) {
    const Token& open = Peek();
    const Array array = ParseArray();
    if (!(array.shape == shape))
      Fail(open, "the value of ", shape.Describe(name.text), " has the wrong shape (",
           array.shape.Describe("value"), ")");
    for (std::size_t k = 0; k < array.components.size(); ++k) {
      const Binding& b = array.components[k];
      if (!b.value || !b.value->is_constant())
        Fail(*array.starts[k], What{"a component of constant", name.text},
             " must be a constant expression");
      if (b.value->constant.IsEmpty())
        Fail(*array.starts[k], "a component of constant '", name.text, "' is the empty set");
      values.push_back(b.value->constant);
    }
  } else {
    const Token& start = Peek();
    values.assign(shape.size(), ParseConstant({"the value of constant", name.text}));
    if (values[0].IsEmpty()) Fail(start, "constant '", name.text, "' is the empty set");
  }
  return values;
}

// Whether the '(' ahead opens a list: a ',' or ';' inside it, outside any
// inner group.
bool Parser::ListAhead() const {
  int depth = 0;
  for (int k = 0;; ++k) {
    const Token& t = Peek(k);
    if (t.kind == TokKind::kEnd) return false;
    if (IsPunct("(", k) || IsPunct("[", k)) {
      ++depth;
    } else if (IsPunct(")", k) || IsPunct("]", k)) {
      if (--depth == 0) return false;
    } else if (depth == 1 && (IsPunct(",", k) || IsPunct(";", k))) {
      return true;
    }
  }
}

// '(' item {sep item} ')', sep all ';' (a column: scalars, or rows that
// make a matrix) or all ',' (a row: scalars, or columns that make a matrix).
Array Parser::ParseArray() {
  DepthGuard guard(this);
  const Token& open = Next();
  std::vector<Array> items;
  items.push_back(ParseArrayItem());
  const bool column = IsPunct(";");
  const char* separator = column ? ";" : ",";
  while (Accept(separator)) items.push_back(ParseArrayItem());
  if (!IsPunct(")"))
    Fail(Peek(), "expected '", separator, "' or ')' in the array opened at line ", open.line,
         ", column ", open.column, ", found ", Peek());
  Next();
  const Shape inner = items[0].shape;
  for (const Array& item : items)
    if (!(item.shape == inner))
      Fail(*item.starts[0], "the components of an array must have the same shape");
  const int n = static_cast<int>(items.size());
  Array out;
  if (inner.is_scalar()) {
    out.shape = column ? Shape{n, 0} : Shape{1, n};
  } else if (column && inner.rows == 1 && inner.is_matrix()) {
    out.shape = Shape{n, inner.cols};  // rows
  } else if (!column && !inner.is_matrix()) {
    out.shape = Shape{inner.rows, n};  // columns
  } else {
    Fail(open, "arrays of more than two dimensions are not supported");
  }
  // Row by row: rows (and scalars) are appended in order, columns interleaved.
  const bool by_columns = !column && !inner.is_scalar();
  const int per_item = inner.size();
  for (int r = 0; r < (by_columns ? per_item : 1); ++r) {
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < (by_columns ? 1 : per_item); ++c) {
        const int k = by_columns ? r : c;
        out.components.push_back(items[i].components[k]);
        out.starts.push_back(items[i].starts[k]);
      }
    }
  }
  return out;
}

Array Parser::ParseArrayItem() {
  if (IsPunct("(") && ListAhead()) return ParseArray();
  Array item;
  item.starts.push_back(&Peek());
  item.components.push_back(BindExpression());
  return item;
}

// Reads an expression here and binds it: its value if the same node can
// serve every use, else the tokens to read again at each use.
Binding Parser::BindExpression() {
  Binding b;
  b.begin = pos_;
  b.scope = scope_;
  const Value v = ParseExpr();
  b.end = pos_;
  if (HoldsNoIntervalConstant(v)) b.value = v;
  return b;
}

Value Parser::Resolve(Binding& b) {
  if (b.value) return *b.value;
  const std::size_t pos = pos_;
  const int scope = scope_;
  pos_ = b.begin;
  scope_ = b.scope;
  const Value v = ParseExpr();
  if (pos_ != b.end) Fail(Peek(), "internal error: a bound expression read differently");
  pos_ = pos;
  scope_ = scope;
  return v;
}

// A folded constant makes a node of its own at each use anyway (ToExpr); a
// node whose operands hold no interval constant is what hash-consing would
// give again.
bool Parser::HoldsNoIntervalConstant(const Value& v) const {
  if (v.is_constant()) return true;
  const ExprGraph& g = csp_.graph();
  std::vector<int> stack = {v.expr->id()};
  std::unordered_set<int> seen;
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    if (!seen.insert(id).second) continue;
    const ExprNode& node = g.node(id);
    if (node.op == Op::kConst && !node.value.IsPoint()) return false;
    if (node.a >= 0) stack.push_back(node.a);
    if (node.b >= 0) stack.push_back(node.b);
  }
  return true;
}

}  // namespace icp::detail::minibex
