// Minibex expressions: arithmetic, powers, functions, names and interval
// literals, with sub-expressions without variables folded to enclosures
// (the grammar is at the top of minibex_parser.cc).
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/minibex_parser_internal.h"

namespace icp::detail::minibex {

Value Parser::Arithmetic(char op, const Value& a, const Value& b) {
  if (a.is_constant() && b.is_constant()) {
    switch (op) {
      case '+': return Const(a.constant + b.constant);
      case '-': return Const(a.constant - b.constant);
      case '*': return Const(a.constant * b.constant);
      default: return Const(a.constant / b.constant);
    }
  }
  const Expr x = ToExpr(a), y = ToExpr(b);
  switch (op) {
    case '+': return Node(x + y);
    case '-': return Node(x - y);
    case '*': return Node(x * y);
    default: return Node(x / y);
  }
}

Value Parser::ParseExpr() {
  DepthGuard guard(this);
  Value v = ParseTerm();
  while (IsPunct("+") || IsPunct("-")) {
    const char op = Next().text[0];
    v = Arithmetic(op, v, ParseTerm());
  }
  return v;
}

Value Parser::ParseTerm() {
  Value v = ParseUnary();
  while (IsPunct("*") || IsPunct("/")) {
    const char op = Next().text[0];
    v = Arithmetic(op, v, ParseUnary());
  }
  return v;
}

Value Parser::ParseUnary() {
  if (IsPunct("-") || IsPunct("+")) {
    DepthGuard guard(this);
    const bool minus = Next().text == "-";
    Value v = ParseUnary();
    if (!minus) return v;
    return v.is_constant() ? Const(-v.constant) : Node(-*v.expr);
  }
  return ParsePower();
}

// '^' binds tighter than unary minus (-x^2 is -(x^2)). An integer constant
// exponent is a power; any other exponent (a real constant, an interval, an
// expression) reads as IBEX reads it (ibex_P_ExprGenerator.cpp,
// visit(P_ExprPower)): e1^e2 is exp(e2 * ln(e1)), defined for e1 > 0 only.
// It is left-associative, as in IBEX's parser.yc (%left
// '^'): x^2^3 is (x^2)^3, as IBEX reads a benchmark file. A signed exponent
// (x^-1) is a unary minus, which binds looser than '^' and so takes the
// rest of the chain: x^-2^3 is x^(-(2^3)), again as in IBEX.
Value Parser::ParsePower() {
  Value base = ParsePrimary();
  while (IsPunct("^")) {
    DepthGuard guard(this);
    Next();
    const Token& start = Peek();
    const Value e = IsPunct("-") || IsPunct("+") ? ParseUnary() : ParsePrimary();
    if (!e.is_constant() || !e.constant.IsPoint() || std::floor(e.constant.lo()) != e.constant.lo()) {
      const Value log = base.is_constant() ? Const(Log(base.constant)) : Node(Log(*base.expr));
      const Value product = Arithmetic('*', e, log);
      base = product.is_constant() ? Const(Exp(product.constant)) : Node(Exp(*product.expr));
      continue;
    }
    const int n = static_cast<int>(ToInteger(e.constant, start, {"the exponent"}, kMaxExponent));
    base = base.is_constant() ? Const(Pow(base.constant, n)) : Node(Pow(*base.expr, n));
  }
  return base;
}

Value Parser::ParsePrimary() {
  const Token& t = Peek();
  switch (t.kind) {
    case TokKind::kNumber: {
      const Interval x = ParseNumber(t);
      Next();
      return Const(x);
    }
    case TokKind::kPunct:
      if (IsPunct("(")) {
        Next();
        Value v = ParseExpr();
        if (!IsPunct(")"))
          Fail(Peek(), "expected ')' to close the '(' at line ", t.line, ", column ",
               t.column, ", found ", Peek(),
               IsPunct(";") || IsPunct(",")
                   ? " (an array such as (a; b) is only a constant's value or a function's argument)"
                   : "");
        Next();
        return v;
      }
      if (IsPunct("[")) return Const(ParseIntervalLiteral());
      Fail(t, "expected an expression, found ", t);
    case TokKind::kEnd:
      Fail(t, "expected an expression, found end of input");
    case TokKind::kIdent:
      return ParseName();
  }
  Fail(t, "expected an expression");
}

Value Parser::ParseName() {
  const Token& t = Peek();
  const std::string& name = t.text;
  // Declared names first: they are the common case and are never reserved.
  if (Symbol* s = Lookup(name)) return ParseSymbol(*s);
  if (auto f = functions_.find(name); f != functions_.end()) return ParseCall(name, f->second);
  if (name == function_being_defined_)
    Fail(t, "function '", name, "' calls itself: recursion is not supported");
  if (scope_ > 0 && symbols_.count(name))
    Fail(t, "'", name, "' is not visible in a function body (only parameters, temporaries and "
         "constants are)");
  if (name == "pi") {
    Next();
    return Const(Pi());
  }
  if (name == "oo") Fail(t, "'oo' is only allowed as an interval bound, as in [0, +oo]");
  if (const UnaryFunction* f = FindUnary(name)) {
    Next();
    Expect("(", {"after", name});
    Value a = ParseExpr();
    if (IsPunct(",")) Fail(Peek(), "'", name, "' takes one argument");
    Expect(")", {"to close the argument of", name});
    return a.is_constant() ? Const(f->on_interval(a.constant)) : Node(f->on_expr(*a.expr));
  }
  if (const BinaryFunction* f = FindBinary(name)) {
    Next();
    Expect("(", {"after", name});
    Value a = ParseExpr();
    Expect(",", {"between the two arguments of", name});
    // max and min take any number of arguments (IBEX's max(e1,e2,...)),
    // folded from the left; atan2 takes two.
    const bool n_ary = name == "max" || name == "min";
    while (true) {
      const Value b = ParseExpr();
      a = a.is_constant() && b.is_constant() ? Const(f->on_interval(a.constant, b.constant))
                                             : Node(f->on_expr(ToExpr(a), ToExpr(b)));
      if (!n_ary || !Accept(",")) break;
    }
    Expect(")", {n_ary ? "after the last argument of" : "after the second argument of", name});
    return a;
  }
  if (IsUnsupportedFunction(name)) Fail(t, "function '", name, "' is not supported");
  if (IsReserved(name)) Fail(t, What{"expected an expression, found keyword", name});
  if (IsPunct("(", 1)) Fail(t, What{"unknown function", name});
  Fail(t, What{"unknown identifier", name});
}

// A constant, loop index, variable, bound name, or a component of a vector
// or matrix one.
Value Parser::ParseSymbol(Symbol& s) {
  const Token& name_token = Next();
  if (s.shape.is_scalar()) {
    if (IsPunct("(") || IsPunct("["))
      Fail(Peek(), "'", name_token.text, "' is a scalar and cannot be indexed");
    return Component(s, 0);
  }
  return Component(s, ParseComponentIndex(s, name_token));
}

// A decimal, enclosed (ParseDecimal), or IBEX's '#' and 16 hexadecimal
// digits: the bits of a double, which is that double exactly.
Interval Parser::ParseNumber(const Token& t) {
  if (t.text[0] != '#') {
    Interval x;
    if (!ParseDecimal(t.text, &x)) Fail(t, "bad number ", t);
    return x;
  }
  if (t.text.size() > 17) Fail(t, "bad number ", t, ": more than 16 hexadecimal digits");
  const std::uint64_t bits = std::stoull(t.text.substr(1), nullptr, 16);
  const double x = std::bit_cast<double>(bits);
  if (!std::isfinite(x)) Fail(t, "bad number ", t, ": not the bits of a finite double");
  return Interval(x);
}

// [a, b] with a lower bound from a's enclosure and an upper one from b's,
// so decimals widen outward; a bound may be -oo, +oo or oo.
Interval Parser::ParseIntervalLiteral() {
  const Token& open = Next();
  const double lo = ParseBound(true);
  Expect(",", "between the bounds of the interval");
  const double hi = ParseBound(false);
  Expect("]", "to close the interval");
  const Interval x(lo, hi);
  if (x.IsEmpty())
    Fail(open, "empty interval [", lo, ", ", hi, "]");
  return x;
}

double Parser::ParseBound(bool lower) {
  const int sign_tokens = (IsPunct("-") || IsPunct("+")) ? 1 : 0;
  const Token& oo = Peek(sign_tokens);
  if (oo.kind == TokKind::kIdent && oo.text == "oo") {
    const bool negative = sign_tokens == 1 && IsPunct("-");
    Next();
    if (sign_tokens) Next();
    return negative ? -kInf : kInf;
  }
  const Token& start = Peek();
  const Interval b = ParseConstant({lower ? "the lower bound" : "the upper bound"});
  if (b.IsEmpty()) Fail(start, "the interval bound is the empty set");
  return lower ? b.lo() : b.hi();
}

Interval Parser::ParseConstant(const What& what) {
  const Token& start = Peek();
  const Value v = ParseExpr();
  if (!v.is_constant()) Fail(start, what, " must be a constant expression");
  return v.constant;
}

long long Parser::ParseInteger(const What& what) {
  const Token& start = Peek();
  return ToInteger(ParseConstant(what), start, what, kMaxInteger);
}

long long Parser::ToInteger(const Interval& x, const Token& at, const What& what, double limit) {
  if (!x.IsPoint() || std::floor(x.lo()) != x.lo()) {
    Fail(at, what, " must be an integer, got ", x);
  }
  if (std::fabs(x.lo()) > limit)
    Fail(at, what, " is too large (", x.lo(), ")");
  return static_cast<long long>(x.lo());
}

}  // namespace icp::detail::minibex
