// Minibex reader: a small tokenizer and a recursive-descent parser that builds
// the expression DAG directly. Grammar (IBEX's parser.yc, reduced):
//
//   system     := [Constants cst_decl ';' {cst_decl ';'}]
//                 Variables var_decl {(';'|',') var_decl} ';'
//                 [Constraints block {';' block} [';']] end [';']
//   cst_decl   := NAME ('=' | 'in') expr                  (constant expr)
//   var_decl   := NAME ['[' expr ']'] ['in' expr]         (constant exprs)
//   block      := for NAME '=' expr ':' expr ';' block {';' block} [';'] end
//               | expr ('=' | '<=' | '>=' | '<' | '>') expr
//   expr       := term {('+' | '-') term}
//   term       := unary {('*' | '/') unary}
//   unary      := ('-' | '+') unary | power
//   power      := primary ['^' exponent]                  (right-associative)
//   exponent   := ('-' | '+') exponent | power
//   primary    := NUMBER | '(' expr ')' | '[' bound ',' bound ']' | pi
//               | FUNC '(' expr [',' expr] ')' | NAME | NAME '(' expr ')'
//               | NAME '[' expr ']'
//   bound      := ['+' | '-'] oo | expr
//
// Sub-expressions without variables are folded in interval arithmetic, so
// constants stay enclosures. Loops re-parse their body once per index value.
#include "core/minibex_parser.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace icp {

MinibexError::MinibexError(const std::string& source, int line, int column,
                           const std::string& message)
    : std::runtime_error(source + ":" + std::to_string(line) + ":" + std::to_string(column) +
                         ": " + message),
      line_(line),
      column_(column) {}

namespace {

// Bounds that keep hostile input from exhausting the stack, memory or time.
// Nesting levels ((), [], functions, signs, ^, for loops). A level costs
// about 1.3 KB of stack in release builds and 8 KB with sanitizers, so 500
// levels fit a 4 MB thread stack; benchmark files nest fewer than 20.
constexpr int kMaxDepth = 500;
constexpr long long kMaxTokenWork = 10'000'000;  // tokens read, loop bodies re-read
// ConstraintSystem::AddVariable checks names linearly, so n variables cost
// O(n^2); IBEX benchmarks have at most a few thousand.
constexpr int kMaxVariables = 1'000'000;
constexpr int kMaxExponent = 1 << 30;
// Integers (indices, loop bounds, exponents) must be exact doubles.
constexpr double kMaxInteger = 9007199254740992.0;  // 2^53

enum class TokKind { kIdent, kNumber, kPunct, kEnd };

struct Token {
  TokKind kind;
  std::string text;
  int line;
  int column;
};

// IBEX accepts keywords as "end", "End" or "END".
bool IsKeywordText(const std::string& text, std::string_view word) {
  if (text.size() != word.size()) return false;
  bool lower = true, upper = true, capital = true;
  for (std::size_t i = 0; i < word.size(); ++i) {
    const char w = word[i];
    const char up = static_cast<char>(std::toupper(static_cast<unsigned char>(w)));
    lower = lower && text[i] == w;
    upper = upper && text[i] == up;
    capital = capital && text[i] == (i == 0 ? up : w);
  }
  return lower || upper || capital;
}

constexpr std::string_view kSectionWords[] = {"constants", "variables", "constraints", "end",
                                              "parameters", "function", "minimize"};
constexpr std::string_view kKeywords[] = {"for", "begin", "return"};
// Words IBEX reserves for functions this reader does not support: calling one
// is a clear "not supported" error rather than "unknown identifier".
constexpr std::string_view kUnsupportedFunctions[] = {
    "acos", "asin", "atan2", "acosh", "asinh", "atanh", "sign", "floor", "ceil",
    "integer", "chi", "diff", "inf", "mid", "sup", "sum"};

struct UnaryFunction {
  std::string_view name;
  Interval (*on_interval)(const Interval&);
  Expr (*on_expr)(Expr);
};
const UnaryFunction kUnaryFunctions[] = {
    {"sqr", Sqr, Sqr},     {"sqrt", Sqrt, Sqrt}, {"exp", Exp, Exp},    {"log", Log, Log},
    {"ln", Log, Log},      {"sin", Sin, Sin},    {"cos", Cos, Cos},    {"tan", Tan, Tan},
    {"atan", Atan, Atan},  {"sinh", Sinh, Sinh}, {"cosh", Cosh, Cosh}, {"tanh", Tanh, Tanh},
    {"abs", Abs, Abs},
};

struct BinaryFunction {
  std::string_view name;
  Interval (*on_interval)(const Interval&, const Interval&);
  Expr (*on_expr)(Expr, Expr);
};
const BinaryFunction kBinaryFunctions[] = {{"min", Min, Min}, {"max", Max, Max}};

const UnaryFunction* FindUnary(const std::string& name) {
  for (const UnaryFunction& f : kUnaryFunctions)
    if (f.name == name) return &f;
  return nullptr;
}

const BinaryFunction* FindBinary(const std::string& name) {
  for (const BinaryFunction& f : kBinaryFunctions)
    if (f.name == name) return &f;
  return nullptr;
}

bool IsUnsupportedFunction(const std::string& name) {
  for (std::string_view w : kUnsupportedFunctions)
    if (w == name) return true;
  return false;
}

bool IsSectionWord(const std::string& text) {
  for (std::string_view w : kSectionWords)
    if (IsKeywordText(text, w)) return true;
  return false;
}

bool IsReserved(const std::string& name) {
  if (IsSectionWord(name) || name == "in" || name == "pi" || name == "oo") return true;
  for (std::string_view w : kKeywords)
    if (IsKeywordText(name, w)) return true;
  return FindUnary(name) || FindBinary(name) || IsUnsupportedFunction(name);
}

std::string FormatDouble(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// Splits text into tokens; comments and whitespace vanish, positions are
// 1-based lines and byte columns.
class Tokenizer {
 public:
  Tokenizer(const std::string& text, const std::string& source) : s_(text), source_(source) {}

  std::vector<Token> Run() {
    std::vector<Token> out;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      const char next = i_ + 1 < s_.size() ? s_[i_ + 1] : '\0';
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        Advance(1);
      } else if (c == '/' && next == '/') {
        while (i_ < s_.size() && s_[i_] != '\n') Advance(1);
      } else if (c == '/' && next == '*') {
        SkipBlockComment();
      } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        out.push_back(Take(TokKind::kIdent, IdentLength()));
      } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                 (c == '.' && std::isdigit(static_cast<unsigned char>(next)))) {
        out.push_back(Take(TokKind::kNumber, NumberLength()));
      } else if ((c == '<' || c == '>') && next == '=') {
        out.push_back(Take(TokKind::kPunct, 2));
      } else if (std::string_view("+-*/^()[],;:=<>").find(c) != std::string_view::npos) {
        out.push_back(Take(TokKind::kPunct, 1));
      } else {
        char what[48];
        if (std::isprint(static_cast<unsigned char>(c)))
          std::snprintf(what, sizeof what, "unexpected character '%c'", c);
        else
          std::snprintf(what, sizeof what, "unexpected byte 0x%02X",
                        static_cast<unsigned>(static_cast<unsigned char>(c)));
        throw MinibexError(source_, line_, column_, what);
      }
    }
    out.push_back(Token{TokKind::kEnd, "", line_, column_});
    return out;
  }

 private:
  bool IsIdentChar(std::size_t k) const {
    return k < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[k])) || s_[k] == '_');
  }
  bool IsDigit(std::size_t k) const {
    return k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]));
  }

  void Advance(std::size_t n) {
    for (std::size_t k = 0; k < n && i_ < s_.size(); ++k, ++i_) {
      if (s_[i_] == '\n') {
        ++line_;
        column_ = 1;
      } else {
        ++column_;
      }
    }
  }

  Token Take(TokKind kind, std::size_t length) {
    Token t{kind, s_.substr(i_, length), line_, column_};
    Advance(length);
    return t;
  }

  void SkipBlockComment() {
    const int line = line_, column = column_;
    Advance(2);
    while (i_ < s_.size() && !(s_[i_] == '*' && i_ + 1 < s_.size() && s_[i_ + 1] == '/'))
      Advance(1);
    if (i_ >= s_.size()) throw MinibexError(source_, line, column, "unterminated /* comment");
    Advance(2);
  }

  std::size_t IdentLength() const {
    std::size_t k = i_;
    while (IsIdentChar(k)) ++k;
    return k - i_;
  }

  // digits [. digits] [e [+-] digits]; a letter, digit or dot glued to the
  // end (as in "2x", "1e", "1.2.3") makes the whole word a bad number.
  std::size_t NumberLength() const {
    std::size_t k = i_;
    while (IsDigit(k)) ++k;
    if (k < s_.size() && s_[k] == '.') {
      ++k;
      while (IsDigit(k)) ++k;
    }
    if (k < s_.size() && (s_[k] == 'e' || s_[k] == 'E')) {
      std::size_t e = k + 1;
      if (e < s_.size() && (s_[e] == '+' || s_[e] == '-')) ++e;
      if (IsDigit(e)) {
        k = e;
        while (IsDigit(k)) ++k;
      }
    }
    if (IsIdentChar(k) || (k < s_.size() && s_[k] == '.')) {
      std::size_t end = k;
      while (IsIdentChar(end) || (end < s_.size() && s_[end] == '.')) ++end;
      const std::size_t shown = std::min<std::size_t>(end - i_, 40);
      throw MinibexError(source_, line_, column_, "bad number '" + s_.substr(i_, shown) + "'");
    }
    return k - i_;
  }

  const std::string& s_;
  const std::string& source_;
  std::size_t i_ = 0;
  int line_ = 1;
  int column_ = 1;
};

// What a token or expression is for, in error messages: text, then 'name'
// if there is one. Assembled only when an error is reported, as the parser
// re-reads loop bodies many times.
struct What {
  What(const char* text) : text(text) {}  // NOLINT: implicit on purpose
  What(std::string_view text, std::string_view name) : text(text), name(name) {}
  std::string_view text;
  std::string_view name;
  std::string str() const {
    std::string s(text);
    if (!name.empty()) s += " '" + std::string(name) + "'";
    return s;
  }
};

// A parsed sub-expression: a constant enclosure (folded) or a DAG node.
struct Value {
  Interval constant;
  std::optional<Expr> expr;
  bool is_constant() const { return !expr.has_value(); }
};

struct Symbol {
  enum Kind { kConstant, kScalarVariable, kVectorVariable, kLoopIndex } kind;
  Interval value;  // kConstant and kLoopIndex
  int first = 0;   // variable index (of component 0 for vectors)
  int size = 1;    // vector length
};

class Parser {
 public:
  Parser(std::vector<Token> tokens, const std::string& source)
      : tokens_(std::move(tokens)), source_(source) {}

  ConstraintSystem Run() {
    try {
      ParseSystem();
    } catch (const std::invalid_argument& e) {
      // ConstraintSystem and ExprGraph reject bad calls this way; the parser
      // should never make one, but a caller must only see MinibexError.
      Fail(Peek(), std::string_view(e.what()));
    }
    return std::move(csp_);
  }

 private:
  // Counts nesting levels so deep input fails cleanly instead of
  // overflowing the stack.
  class DepthGuard {
   public:
    explicit DepthGuard(Parser* p) : p_(p) {
      if (++p_->depth_ > kMaxDepth)
        p_->Fail(p_->Peek(), "nesting too deep (more than ", kMaxDepth, " levels)");
    }
    ~DepthGuard() { --p_->depth_; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;

   private:
    Parser* p_;
  };

  // ---- Token access -------------------------------------------------------

  const Token& Peek(int k = 0) const {
    const std::size_t at = pos_ + k;
    return at < tokens_.size() ? tokens_[at] : tokens_.back();
  }

  const Token& Next() {
    const Token& t = Peek();
    if (t.kind == TokKind::kEnd) return t;
    if (++work_ > kMaxTokenWork)
      Fail(t, "input too large: loops expand to more than ", kMaxTokenWork, " tokens");
    ++pos_;
    return t;
  }

  bool IsPunct(const char* p, int k = 0) const {
    const Token& t = Peek(k);
    return t.kind == TokKind::kPunct && t.text == p;
  }
  bool IsWord(std::string_view keyword, int k = 0) const {
    const Token& t = Peek(k);
    return t.kind == TokKind::kIdent && IsKeywordText(t.text, keyword);
  }
  bool AtEnd() const { return Peek().kind == TokKind::kEnd; }
  // "in" is lower case only in IBEX, unlike the section keywords.
  bool IsIn() const { return Peek().kind == TokKind::kIdent && Peek().text == "in"; }

  bool Accept(const char* p) {
    if (!IsPunct(p)) return false;
    Next();
    return true;
  }

  const Token& Expect(const char* p, const What& context) {
    if (!IsPunct(p))
      Fail(Peek(), "expected '", p, "' ", context, ", found ", Peek());
    return Next();
  }

  // Throws the error at token at, with a message made of parts: text,
  // numbers, intervals, What, and tokens (shown quoted, or "end of input").
  // Parts are joined here, out of line, so that the recursive parse functions
  // keep small stack frames.
  template <typename... Parts>
  [[noreturn, gnu::noinline, gnu::cold]] void Fail(const Token& at,
                                                   const Parts&... parts) const {
    std::string message;
    (Append(message, parts), ...);
    throw MinibexError(source_, at.line, at.column, message);
  }

  template <typename Part>
  static void Append(std::string& out, const Part& part) {
    if constexpr (std::is_same_v<Part, Token>) {
      if (part.kind == TokKind::kEnd) {
        out += "end of input";
      } else {
        out += "'" + part.text.substr(0, 40) + "'";
      }
    } else if constexpr (std::is_same_v<Part, What>) {
      out += part.str();
    } else if constexpr (std::is_same_v<Part, Interval>) {
      std::ostringstream text;
      text << part;
      out += text.str();
    } else if constexpr (std::is_integral_v<Part>) {
      out += std::to_string(part);
    } else if constexpr (std::is_floating_point_v<Part>) {
      out += FormatDouble(part);
    } else {
      out += std::string_view(part);
    }
  }

  // ---- Sections -----------------------------------------------------------

  void ParseSystem() {
    if (IsWord("constants")) {
      Next();
      ParseConstants();
    }
    if (!IsWord("variables")) {
      RejectUnsupportedSection();
      Fail(Peek(), "expected 'Variables', found ", Peek());
    }
    Next();
    ParseVariables();
    RejectUnsupportedSection();
    if (IsWord("constraints")) {
      Next();
      ParseBlockList("Constraints section");  // reads the final 'end' too
    } else {
      if (AtEnd()) Fail(Peek(), "missing 'end' at the end of the system");
      if (!IsWord("end"))
        Fail(Peek(), "expected 'Constraints' or 'end', found ", Peek());
      Next();
    }
    Accept(";");
    if (!AtEnd()) Fail(Peek(), "unexpected ", Peek(), " after the final 'end'");
  }

  void RejectUnsupportedSection() {
    for (std::string_view w : {"parameters", "function", "minimize"})
      if (IsWord(w)) Fail(Peek(), "the '", Peek().text, "' section is not supported");
  }

  // Constants: NAME ('=' | 'in') constant-expression ';' ...
  void ParseConstants() {
    do {
      const Token& name = NewName("constant");
      if (IsPunct("[")) Fail(Peek(), "vector constants are not supported");
      if (IsPunct("=") || IsIn()) {
        Next();
      } else {
        Fail(Peek(), "expected '=' or 'in' after constant '", name.text, "', found ", Peek());
      }
      const Token& start = Peek();
      const Interval value = ParseConstant({"the value of constant", name.text});
      if (value.IsEmpty()) Fail(start, "constant '", name.text, "' is the empty set");
      symbols_[name.text] = Symbol{Symbol::kConstant, value};
      Expect(";", {"after the declaration of constant", name.text});
    } while (!AtEnd() && !IsSectionWord(Peek().text));
  }

  // Variables: NAME ['[' n ']'] ['in' domain], separated by ';' or ',' (as in
  // IBEX, where "x, y in [0,1]" leaves x unbounded), ending with ';'.
  void ParseVariables() {
    while (true) {
      const Token& name = NewName("variable");
      int size = 0;  // 0: scalar
      if (IsPunct("[")) {
        const Token& open = Next();
        const Token& start = Peek();
        const long long n = ParseInteger({"the size of vector", name.text});
        if (n < 1) Fail(start, "vector '", name.text, "' must have a positive size");
        if (n > kMaxVariables) Fail(start, "vector '", name.text, "' is too large");
        Expect("]", {"after the size of vector", name.text});
        if (IsPunct("[")) Fail(open, "matrix variables are not supported");
        size = static_cast<int>(n);
      }
      Interval domain;
      if (IsIn()) {
        Next();
        const Token& start = Peek();
        domain = ParseConstant({"the domain of", name.text});
        if (domain.IsEmpty()) Fail(start, What{"empty domain for", name.text});
      }
      Declare(name, size, domain);
      if (Accept(",")) continue;
      Expect(";", {"after the declaration of", name.text});
      if (AtEnd() || (Peek().kind == TokKind::kIdent && IsSectionWord(Peek().text))) return;
    }
  }

  void Declare(const Token& name, int size, const Interval& domain) {
    if (csp_.num_variables() + std::max(size, 1) > kMaxVariables)
      Fail(name, "too many variables (more than ", kMaxVariables, ")");
    Symbol s{size == 0 ? Symbol::kScalarVariable : Symbol::kVectorVariable, Interval()};
    s.first = csp_.num_variables();
    s.size = std::max(size, 1);
    if (size == 0) {
      csp_.AddVariable(name.text, domain);
    } else {
      for (int i = 0; i < size; ++i)
        csp_.AddVariable(name.text + "[" + std::to_string(i) + "]", domain);
    }
    symbols_[name.text] = s;
  }

  // A name being declared: an identifier, not reserved, not yet used.
  const Token& NewName(const std::string& what) {
    const Token& t = Peek();
    if (t.kind != TokKind::kIdent)
      Fail(t, "expected a ", what, " name, found ", t);
    if (IsReserved(t.text))
      Fail(t, "'", t.text, "' is a reserved word and cannot name a ", what);
    if (symbols_.count(t.text)) Fail(t, "duplicate name '", t.text, "'");
    return Next();
  }

  // block {';' block} [';'], up to and including the closing 'end'.
  void ParseBlockList(const std::string& what) {
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

  // for NAME = lo : hi ; body end. The body is re-read for each index value.
  void ParseLoop() {
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
    symbols_[name.text] = Symbol{Symbol::kLoopIndex, Interval()};
    for (long long i = lo; i <= hi; ++i) {
      symbols_[name.text].value = Interval(static_cast<double>(i));
      pos_ = body;
      ParseBlockList(what);
    }
    symbols_.erase(name.text);
  }

  // An empty loop is not expanded: jump to its 'end' by counting for/end.
  void SkipLoopBody(const std::string& what) {
    int open = 1;
    while (open > 0) {
      if (AtEnd()) Fail(Peek(), "unterminated ", what, ": missing 'end'");
      if (IsWord("for")) ++open;
      if (IsWord("end")) --open;
      Next();
    }
  }

  void ParseConstraint() {
    Value lhs = ParseExpr();
    Relation rel;
    if (IsPunct("=")) {
      rel = Relation::kEq;
    } else if (IsPunct("<=") || IsPunct("<")) {
      rel = Relation::kLeq;  // strict and non-strict are the same on intervals
    } else if (IsPunct(">=") || IsPunct(">")) {
      rel = Relation::kGeq;
    } else {
      Fail(Peek(), "expected '=', '<=' or '>=' in the constraint, found ", Peek());
    }
    Next();
    Value rhs = ParseExpr();
    csp_.AddConstraint(ToExpr(lhs), rel, ToExpr(rhs));
  }

  // ---- Expressions --------------------------------------------------------

  Expr ToExpr(const Value& v) { return v.expr ? *v.expr : csp_.Constant(v.constant); }

  static Value Const(const Interval& x) { return Value{x, std::nullopt}; }
  static Value Node(Expr e) { return Value{Interval(), e}; }

  Value Arithmetic(char op, const Value& a, const Value& b) {
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

  Value ParseExpr() {
    DepthGuard guard(this);
    Value v = ParseTerm();
    while (IsPunct("+") || IsPunct("-")) {
      const char op = Next().text[0];
      v = Arithmetic(op, v, ParseTerm());
    }
    return v;
  }

  Value ParseTerm() {
    Value v = ParseUnary();
    while (IsPunct("*") || IsPunct("/")) {
      const char op = Next().text[0];
      v = Arithmetic(op, v, ParseUnary());
    }
    return v;
  }

  Value ParseUnary() {
    if (IsPunct("-") || IsPunct("+")) {
      DepthGuard guard(this);
      const bool minus = Next().text == "-";
      Value v = ParseUnary();
      if (!minus) return v;
      return v.is_constant() ? Const(-v.constant) : Node(-*v.expr);
    }
    return ParsePower();
  }

  // '^' binds tighter than unary minus (-x^2 is -(x^2)) and takes an integer
  // constant exponent, which may itself be signed (x^-1).
  Value ParsePower() {
    Value base = ParsePrimary();
    if (!IsPunct("^")) return base;
    DepthGuard guard(this);
    Next();
    const Token& start = Peek();
    const Value e = ParseExponent();
    if (!e.is_constant()) Fail(start, "the exponent must be an integer constant");
    const int n = static_cast<int>(ToInteger(e.constant, start, {"the exponent"}, kMaxExponent));
    if (base.is_constant()) return Const(Pow(base.constant, n));
    return Node(Pow(*base.expr, n));
  }

  Value ParseExponent() {
    if (IsPunct("-") || IsPunct("+")) {
      DepthGuard guard(this);
      const bool minus = Next().text == "-";
      Value v = ParseExponent();
      if (!minus) return v;
      return v.is_constant() ? Const(-v.constant) : Node(-*v.expr);
    }
    return ParsePower();
  }

  Value ParsePrimary() {
    const Token& t = Peek();
    switch (t.kind) {
      case TokKind::kNumber: {
        Interval x;
        if (!ParseDecimal(t.text, &x)) Fail(t, "bad number ", t);
        Next();
        return Const(x);
      }
      case TokKind::kPunct:
        if (IsPunct("(")) {
          Next();
          Value v = ParseExpr();
          if (!IsPunct(")"))
            Fail(Peek(), "expected ')' to close the '(' at line ", t.line, ", column ",
                 t.column, ", found ", Peek());
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

  [[gnu::noinline]] Value ParseName() {
    const Token& t = Peek();
    const std::string& name = t.text;
    // Declared names first: they are the common case and are never reserved.
    auto it = symbols_.find(name);
    if (it != symbols_.end()) return ParseSymbol(it->second);
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
      Value b = ParseExpr();
      Expect(")", {"after the second argument of", name});
      if (a.is_constant() && b.is_constant()) return Const(f->on_interval(a.constant, b.constant));
      return Node(f->on_expr(ToExpr(a), ToExpr(b)));
    }
    if (IsUnsupportedFunction(name)) Fail(t, "function '", name, "' is not supported");
    if (IsReserved(name)) Fail(t, What{"expected an expression, found keyword", name});
    if (IsPunct("(", 1)) Fail(t, What{"unknown function", name});
    Fail(t, What{"unknown identifier", name});
  }

  // A constant, loop index, variable or indexed vector component.
  [[gnu::noinline]] Value ParseSymbol(const Symbol& s) {
    const Token& name_token = Next();
    const std::string& name = name_token.text;
    switch (s.kind) {
      case Symbol::kConstant:
      case Symbol::kLoopIndex:
        return Const(s.value);
      case Symbol::kScalarVariable:
        if (IsPunct("(") || IsPunct("["))
          Fail(Peek(), "'", name, "' is a scalar variable and cannot be indexed");
        return Node(csp_.Var(s.first));
      case Symbol::kVectorVariable:
        break;
    }
    // x(i) counts from 1 as in IBEX, x[i] from 0.
    const bool one_based = IsPunct("(");
    if (!one_based && !IsPunct("["))
      Fail(name_token, "vector '", name, "' must be indexed, as in ", name, "(1) or ", name,
           "[0]");
    Next();
    const Token& start = Peek();
    const long long i = ParseInteger({"the index of", name});
    const long long base = one_based ? 1 : 0;
    if (i < base || i >= s.size + base)
      Fail(start, "index ", i, " out of range for '", name, "' (", name,
           one_based ? "(i) takes 1.." : "[i] takes 0..", one_based ? s.size : s.size - 1, ")");
    Expect(one_based ? ")" : "]", {"after the index of", name});
    return Node(csp_.Var(s.first + static_cast<int>(i - base)));
  }

  // [a, b] with a lower bound from a's enclosure and an upper one from b's,
  // so decimals widen outward; a bound may be -oo, +oo or oo.
  [[gnu::noinline]] Interval ParseIntervalLiteral() {
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

  double ParseBound(bool lower) {
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

  Interval ParseConstant(const What& what) {
    const Token& start = Peek();
    const Value v = ParseExpr();
    if (!v.is_constant()) Fail(start, what, " must be a constant expression");
    return v.constant;
  }

  long long ParseInteger(const What& what) {
    const Token& start = Peek();
    return ToInteger(ParseConstant(what), start, what, kMaxInteger);
  }

  long long ToInteger(const Interval& x, const Token& at, const What& what, double limit) {
    if (!x.IsPoint() || std::floor(x.lo()) != x.lo()) {
      Fail(at, what, " must be an integer, got ", x);
    }
    if (std::fabs(x.lo()) > limit)
      Fail(at, what, " is too large (", x.lo(), ")");
    return static_cast<long long>(x.lo());
  }

  std::vector<Token> tokens_;
  const std::string& source_;
  std::size_t pos_ = 0;
  long long work_ = 0;
  int depth_ = 0;
  std::unordered_map<std::string, Symbol> symbols_;
  ConstraintSystem csp_;
};

}  // namespace

ConstraintSystem ParseMinibex(const std::string& text, const std::string& source) {
  return Parser(Tokenizer(text, source).Run(), source).Run();
}

ConstraintSystem ParseMinibexFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw MinibexError(path, 0, 0, "cannot read '" + path + "': it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MinibexError(path, 0, 0, "cannot open '" + path + "'");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw MinibexError(path, 0, 0, "error while reading '" + path + "'");
  return ParseMinibex(text, path);
}

}  // namespace icp
