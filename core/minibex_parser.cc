// Minibex reader: the entry points and the statements (sections,
// declarations, for loops, constraints) of a recursive-descent parser that
// builds the expression DAG directly; its tokens, words and expressions are in
// minibex_tokenizer.cc, minibex_words.cc and minibex_expression.cc.
// Grammar (IBEX's parser.yc, reduced):
//
//   system     := [Constants {cst_decl ';'}] {function}
//                 Variables var_decl {(';'|',') var_decl} ';' {function}
//                 [Minimize expr [';']]
//                 [Constraints block {';' block} [';'] end | end] [';']
//   cst_decl   := NAME [shape] ('=' | 'in') (expr | array)    (constants)
//   var_decl   := NAME [shape] ['in' expr]                    (constant expr)
//   shape      := '[' expr ']' ['[' expr ']']                 (constant exprs)
//   function   := function NAME '(' NAME [shape] {',' NAME [shape]} ')'
//                 {NAME '=' expr ';'} return expr [';'] end
//   block      := for NAME '=' expr ':' expr ';' block {';' block} [';'] end
//               | NAME '=' expr                     (a temporary, then a ctr)
//               | ctr
//   ctr        := expr ('=' | 'in' | '<=' | '>=' | '<' | '>') expr | '(' ctr ')'
//   expr       := term {('+' | '-') term}
//   term       := unary {('*' | '/') unary}
//   unary      := ('-' | '+') unary | power
//   power      := primary {'^' (primary | ('-' | '+') unary)}  (left-assoc.)
//   primary    := NUMBER | '(' expr ')' | '[' bound ',' bound ']' | pi
//               | FUNC '(' expr {',' expr} ')' | NAME '(' arg {',' arg} ')'
//               | NAME | NAME '(' expr [',' expr] ')' | NAME '[' expr ']' ['[' expr ']']
//   arg        := expr | NAME | array                 (a NAME or array: a vector)
//   array      := '(' item {';' item} ')' | '(' item {',' item} ')'
//   item       := expr | array
//   bound      := ['+' | '-'] oo | expr
//
// Sub-expressions without variables are folded in interval arithmetic, so
// constants stay enclosures. Loops re-parse their body once per index value;
// a function call re-parses the function's body with its parameters bound to
// the arguments (minibex_functions.cc).
#include "core/minibex_parser.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "core/minibex_parser_internal.h"

namespace icp {

MinibexError::MinibexError(const std::string& source, int line, int column,
                           const std::string& message)
    : std::runtime_error(source + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": " + message),
      line_(line),
      column_(column) {}

namespace detail::minibex {

std::string FormatDouble(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

ConstraintSystem Parser::Run() {
  try {
    ParseSystem();
  } catch (const std::invalid_argument& e) {
    // ConstraintSystem and ExprGraph reject bad calls this way; the parser
    // should never make one, but a caller must only see MinibexError.
    Fail(Peek(), std::string_view(e.what()));
  }
  return std::move(csp_);
}

// ---- Sections -----------------------------------------------------------

void Parser::ParseSystem() {
  if (IsWord("constants")) {
    Next();
    // IBEX allows the section empty (files converted from COCONUT have it).
    if (!AtEnd() && !IsSectionWord(Peek().text)) ParseConstants();
  }
  ParseFunctions();
  if (!IsWord("variables")) {
    RejectUnsupportedSection();
    Fail(Peek(), "expected 'Variables', found ", Peek());
  }
  Next();
  ParseVariables();
  ParseFunctions();
  RejectUnsupportedSection();
  if (IsWord("minimize")) {
    // The goal of an optimisation file is read (so its errors are reported)
    // and dropped: solve contracts the constraints, which an objective does
    // not restrict, so the boxes stay sound.
    Next();
    ParseExpr();
    Accept(";");
    RejectUnsupportedSection();
  }
  ParseEnding();
}

// IBEX's functions come after the constants, the variables, or both.
void Parser::ParseFunctions() {
  while (IsWord("function")) ParseFunctionDefinition();
}

// Constraints ... end, or a bare 'end', or (as IBEX writes a system without
// constraints) nothing at all.
void Parser::ParseEnding() {
  if (IsWord("constraints")) {
    Next();
    ParseBlockList("Constraints section");  // reads the final 'end' too
  } else if (IsWord("end")) {
    Next();
  } else if (!AtEnd()) {
    Fail(Peek(), "expected 'Constraints' or 'end', found ", Peek());
  }
  Accept(";");
  if (!AtEnd()) Fail(Peek(), "unexpected ", Peek(), " after the final 'end'");
}

void Parser::RejectUnsupportedSection() {
  if (IsWord("parameters")) Fail(Peek(), "the '", Peek().text, "' section is not supported");
  if (IsWord("function"))
    Fail(Peek(), "a function must come before 'Minimize' and 'Constraints'");
}

// Constants: NAME [shape] ('=' | 'in') value ';' ...
void Parser::ParseConstants() {
  do {
    const Token& name = NewName("constant");
    const Shape shape = ParseShape(name, "constant");
    if (IsPunct("=") || IsIn()) {
      Next();
    } else {
      Fail(Peek(), "expected '=' or 'in' after constant '", name.text, "', found ", Peek());
    }
    Symbol s{Symbol::kConstant, shape};
    s.values = ParseConstantValue(name, shape);
    symbols_[name.text] = std::move(s);
    Expect(";", {"after the declaration of constant", name.text});
  } while (!AtEnd() && !IsSectionWord(Peek().text));
}

// Variables: NAME [shape] ['in' domain], separated by ';' or ',' (as in
// IBEX, where "x, y in [0,1]" leaves x unbounded), ending with ';'.
void Parser::ParseVariables() {
  while (true) {
    const Token& name = NewName("variable");
    const Shape shape = ParseShape(name, "variable");
    Interval domain;
    if (IsIn()) {
      Next();
      const Token& start = Peek();
      domain = ParseConstant({"the domain of", name.text});
      if (domain.IsEmpty()) Fail(start, What{"empty domain for", name.text});
    }
    Declare(name, shape, domain);
    if (Accept(",")) continue;
    Expect(";", {"after the declaration of", name.text});
    if (AtEnd() || (Peek().kind == TokKind::kIdent && IsSectionWord(Peek().text))) return;
  }
}

// ['[' n ']' ['[' m ']']]: a scalar, a vector of n, or an n x m matrix.
Shape Parser::ParseShape(const Token& name, const char* what) {
  Shape shape;
  for (int dimension = 0; dimension < 2 && IsPunct("["); ++dimension) {
    Next();
    const Token& start = Peek();
    const long long n = ParseInteger({"a dimension of", name.text});
    if (n < 1) Fail(start, what, " '", name.text, "' must have positive dimensions");
    if (n > kMaxVariables) Fail(start, what, " '", name.text, "' is too large");
    Expect("]", {"after a dimension of", name.text});
    (dimension == 0 ? shape.rows : shape.cols) = static_cast<int>(n);
  }
  if (static_cast<long long>(std::max(shape.rows, 1)) * std::max(shape.cols, 1) > kMaxVariables)
    Fail(name, what, " '", name.text, "' is too large");
  if (IsPunct("["))
    Fail(Peek(), "arrays of matrices (three dimensions) are not supported");
  return shape;
}

// A vector x[n] becomes the variables "x[0]" .. "x[n-1]", a matrix x[m][n]
// "x[0][0]", "x[0][1]" .. "x[m-1][n-1]", row by row (0-based, as written
// with []).
void Parser::Declare(const Token& name, const Shape& shape, const Interval& domain) {
  if (static_cast<long long>(csp_.num_variables()) + shape.size() > kMaxVariables)
    Fail(name, "too many variables (more than ", kMaxVariables, ")");
  Symbol s{Symbol::kVariable, shape};
  s.first = csp_.num_variables();
  if (shape.is_scalar()) {
    csp_.AddVariable(name.text, domain);
  } else if (!shape.is_matrix()) {
    for (int i = 0; i < shape.rows; ++i)
      csp_.AddVariable(name.text + "[" + std::to_string(i) + "]", domain);
  } else {
    for (int i = 0; i < shape.rows; ++i)
      for (int j = 0; j < shape.cols; ++j)
        csp_.AddVariable(name.text + "[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                         domain);
  }
  symbols_[name.text] = std::move(s);
}

// A name being declared: an identifier, not reserved, not yet used here (in
// a function body, global variables are out of sight and may be reused).
const Token& Parser::NewName(const std::string& what) {
  const Token& t = Peek();
  if (t.kind != TokKind::kIdent)
    Fail(t, "expected a ", what, " name, found ", t);
  if (IsReserved(t.text))
    Fail(t, "'", t.text, "' is a reserved word and cannot name a ", what);
  if (Lookup(t.text) || (scope_ == 0 && symbols_.count(t.text)) || functions_.count(t.text) ||
      t.text == function_being_defined_)
    Fail(t, "duplicate name '", t.text, "'");
  return Next();
}

// block {';' block} [';'], up to and including the closing 'end'.
void Parser::ParseBlockList(const std::string& what) {
  DepthGuard guard(this);
  bool first = true;
  while (true) {
    if (AtEnd()) Fail(Peek(), "unterminated ", what, ": missing 'end'");
    if (IsWord("end")) {
      if (first) Fail(Peek(), "expected a constraint before 'end' in the ", what);
      Next();
      return;
    }
    if (IsWord("for")) {
      ParseLoop();
    } else if (AssignmentAhead()) {
      ParseAssignment(what);
      continue;
    } else {
      ParseConstraint();
    }
    first = false;
    if (Accept(";")) continue;
    if (AtEnd()) Fail(Peek(), "unterminated ", what, ": missing 'end'");
    if (!IsWord("end"))
      Fail(Peek(), "expected ';' after the constraint, found ", Peek());
  }
}

// IBEX's ctr_assign: a new name followed by '=' binds the name to an
// expression (an unknown name in a constraint would be an error anyway).
bool Parser::AssignmentAhead() const {
  const Token& t = Peek();
  return t.kind == TokKind::kIdent && IsPunct("=", 1) && !IsReserved(t.text) &&
         !symbols_.count(t.text) && !functions_.count(t.text);
}

// NAME = expr ';' then a constraint: the name stands for the expression in
// the constraints that follow, up to the end of the enclosing loop body.
void Parser::ParseAssignment(const std::string& what) {
  const Token& name = NewName("temporary");
  Next();  // '='
  Symbol s{Symbol::kBound};
  s.bindings.push_back(BindExpression());
  symbols_[name.text] = std::move(s);
  temporaries_.push_back(name.text);
  Expect(";", {"after the expression of", name.text});
  if (IsWord("end") || AtEnd())
    Fail(Peek(), "expected a constraint after the temporary '", name.text, "' in the ", what);
}

// for NAME = lo : hi ; body end. The body is re-read for each index value.
void Parser::ParseLoop() {
  const Token& for_token = Next();
  const Token& name = NewName("loop index");
  Expect("=", {"after the loop index", name.text});
  const long long lo = ParseInteger({"the first value of", name.text});
  Expect(":", "between the loop bounds");
  const long long hi = ParseInteger({"the last value of", name.text});
  Expect(";", "after the loop bounds");
  const std::string what = "for loop at line " + std::to_string(for_token.line);
  if (lo > hi) {
    SkipLoopBody(what);
    return;
  }
  const std::size_t body = pos_;
  symbols_[name.text] = Symbol{Symbol::kLoopIndex};
  const std::size_t outer_temporaries = temporaries_.size();
  for (long long i = lo; i <= hi; ++i) {
    symbols_[name.text].values = {Interval(static_cast<double>(i))};
    pos_ = body;
    ParseBlockList(what);
    // The body's temporaries are its own, new at each iteration.
    for (std::size_t k = outer_temporaries; k < temporaries_.size(); ++k)
      symbols_.erase(temporaries_[k]);
    temporaries_.resize(outer_temporaries);
  }
  symbols_.erase(name.text);
}

// An empty loop is not expanded: jump to its 'end' by counting for/end.
void Parser::SkipLoopBody(const std::string& what) {
  int open = 1;
  while (open > 0) {
    if (AtEnd()) Fail(Peek(), "unterminated ", what, ": missing 'end'");
    if (IsWord("for")) ++open;
    if (IsWord("end")) --open;
    Next();
  }
}

// IBEX's '(' ctr ')': a constraint in parentheses, told apart from a
// parenthesised expression ('(x + 1)^2 <= 3') by where its relation is: in
// the group the opening parenthesis starts, at a depth d reached by d
// opening parentheses in a row ('((y >= 2))'; '((x) + 1 <= 2)' has d = 1).
bool Parser::ParenthesisedConstraintAhead() const {
  if (!IsPunct("(")) return false;
  int depth = 0, leading = 0, relation_depth = kMaxDepth + 1;
  bool opening_run = true;
  for (int k = 0;; ++k) {
    const Token& t = Peek(k);
    if (t.kind == TokKind::kEnd) return false;
    const bool open = IsPunct("(", k) || IsPunct("[", k);
    opening_run = opening_run && IsPunct("(", k);
    if (opening_run) ++leading;
    const bool relation = (t.kind == TokKind::kIdent && t.text == "in") ||
                          (t.kind == TokKind::kPunct && (t.text == "=" || t.text == "<=" || t.text == ">=" ||
                                                         t.text == "<" || t.text == ">"));
    if (open) {
      ++depth;
    } else if (IsPunct(")", k) || IsPunct("]", k)) {
      if (--depth == 0) return relation_depth <= leading;
    } else if (IsPunct(";", k)) {
      return false;
    } else if (relation) {
      relation_depth = std::min(relation_depth, depth);
    }
  }
}

void Parser::ParseConstraint() {
  if (ParenthesisedConstraintAhead()) {
    DepthGuard guard(this);
    const Token& open = Next();
    ParseConstraint();
    if (!IsPunct(")"))
      Fail(Peek(), "expected ')' to close the '(' at line ", open.line, ", column ", open.column, ", found ",
           Peek());
    Next();
    return;
  }
  Value lhs = ParseExpr();
  Relation rel;
  // e in X is IBEX's thick constraint: e takes a value of X, as e = X does
  // here (an interval right-hand side is a range, not a point).
  if (IsPunct("=") || IsIn()) {
    rel = Relation::kEq;
  } else if (IsPunct("<=") || IsPunct("<")) {
    rel = Relation::kLeq;  // strict and non-strict are the same on intervals
  } else if (IsPunct(">=") || IsPunct(">")) {
    rel = Relation::kGeq;
  } else {
    Fail(Peek(), "expected '=', 'in', '<=' or '>=' in the constraint, found ", Peek());
  }
  Next();
  Value rhs = ParseExpr();
  csp_.AddConstraint(ToExpr(lhs), rel, ToExpr(rhs));
}

}  // namespace detail::minibex

ConstraintSystem ParseMinibex(const std::string& text, const std::string& source) {
  using detail::minibex::Parser;
  using detail::minibex::Tokenize;
  return Parser(Tokenize(text, source), source).Run();
}

std::string ReadMinibexFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw MinibexError(path, 0, 0, "cannot read '" + path + "': it is a directory");
  // A pipe or a device could block the reader, or never end.
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw MinibexError(path, 0, 0, "cannot read '" + path + "': not a regular file (a pipe or a device)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MinibexError(path, 0, 0, "cannot open '" + path + "'");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw MinibexError(path, 0, 0, "error while reading '" + path + "'");
  return text;
}

ConstraintSystem ParseMinibexFile(const std::string& path) { return ParseMinibex(ReadMinibexFile(path), path); }

}  // namespace icp
