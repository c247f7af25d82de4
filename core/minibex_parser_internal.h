// Internals of the Minibex reader shared by its .cc files: tokens, the words
// of the language, and the Parser class whose grammar those files define.
#ifndef ICPBENCH_CORE_MINIBEX_PARSER_INTERNAL_H_
#define ICPBENCH_CORE_MINIBEX_PARSER_INTERNAL_H_

#include <cctype>
#include <cstddef>
#include <deque>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/constraint_system.h"
#include "core/minibex_parser.h"

namespace icp::detail::minibex {

// Bounds that keep hostile input from exhausting the stack, memory or time.
// Nesting levels ((), [], functions, signs, ^, for loops). A level costs
// about 1.3 KB of stack in release builds and 8 KB with sanitizers, so 500
// levels fit a 4 MB thread stack; benchmark files nest fewer than 20.
inline constexpr int kMaxDepth = 500;
// Tokens read, counting each re-reading of a loop body, a function body or
// a temporary: a bound on the parse's time (about 1 s here, 5 s under the
// sanitizers, whose fuzzing stops an input at 10 s), reached by nested
// temporaries or calls that double at each level, far above real files.
inline constexpr long long kMaxTokenWork = 4'000'000;
// ConstraintSystem::AddVariable checks names linearly, so n variables cost
// O(n^2); IBEX benchmarks have at most a few thousand.
inline constexpr int kMaxVariables = 1'000'000;
inline constexpr int kMaxExponent = 1 << 30;
// Integers (indices, loop bounds, exponents) must be exact doubles.
inline constexpr double kMaxInteger = 9007199254740992.0;  // 2^53

// ---- Tokens (minibex_tokenizer.cc) ------------------------------------------

enum class TokKind { kIdent, kNumber, kPunct, kEnd };

struct Token {
  TokKind kind;
  std::string text;
  int line;
  int column;
};

// Splits text into tokens, ending with one kEnd token; comments and
// whitespace vanish, positions are 1-based lines and byte columns.
std::vector<Token> Tokenize(const std::string& text, const std::string& source);

// ---- Words (minibex_words.cc) -----------------------------------------------

// IBEX accepts keywords as "end", "End" or "END". Inline: the parser asks it
// for every block of every loop iteration.
inline bool IsKeywordText(const std::string& text, std::string_view word) {
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

struct UnaryFunction {
  std::string_view name;
  Interval (*on_interval)(const Interval&);
  Expr (*on_expr)(Expr);
};

struct BinaryFunction {
  std::string_view name;
  Interval (*on_interval)(const Interval&, const Interval&);
  Expr (*on_expr)(Expr, Expr);
};

// The function called name, or nullptr.
const UnaryFunction* FindUnary(const std::string& name);
const BinaryFunction* FindBinary(const std::string& name);
// A function IBEX has and this reader does not support.
bool IsUnsupportedFunction(const std::string& name);
// Constants, Variables, Constraints, end, and the unsupported sections.
bool IsSectionWord(const std::string& text);
// A word that cannot name a constant, variable or loop index.
bool IsReserved(const std::string& name);

// ---- Parser (minibex_parser.cc and the files named below) ------------------

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

// The shape of a declared name: rows = 0 for a scalar, cols = 0 for a
// vector of rows components, both positive for a rows x cols matrix.
struct Shape {
  int rows = 0;
  int cols = 0;
  bool is_scalar() const { return rows == 0; }
  bool is_matrix() const { return cols > 0; }
  int size() const { return is_scalar() ? 1 : is_matrix() ? rows * cols : rows; }
  bool operator==(const Shape&) const = default;
  // "x", "x[3]" or "x[2][3]", for messages.
  std::string Describe(const std::string& name) const;
};

// A name bound to an expression (a function argument, a temporary): the
// tokens [begin, end) read in function scope `scope` (0: the system's) at
// each use, as if written there, so an interval constant in it stays a real
// of its own at each occurrence. value caches the result once it is known
// to hold no interval constant (then every reading gives the same node).
struct Binding {
  std::optional<Value> value;
  std::size_t begin = 0;
  std::size_t end = 0;
  int scope = 0;
};

struct Symbol {
  enum Kind { kConstant, kVariable, kLoopIndex, kBound };
  explicit Symbol(Kind kind = kConstant, Shape shape = {}) : kind(kind), shape(shape) {}
  Kind kind;
  Shape shape;
  std::vector<Interval> values;   // kConstant (row by row), kLoopIndex (one)
  int first = 0;                  // kVariable: the variable index of component 0
  std::vector<Binding> bindings;  // kBound: one per component
};

// A user function: its parameters and where its body starts (the token
// after the closing parenthesis of the parameter list).
struct Function {
  std::vector<std::pair<std::string, Shape>> parameters;
  std::size_t body = 0;
};

// A parenthesised list: (e1; e2) a column, (e1, e2) a row, ((a, b); (c, d))
// a matrix by rows; its components row by row.
struct Array {
  Shape shape;
  std::vector<Binding> components;
  std::vector<const Token*> starts;  // where each component starts, for messages
};

// %.17g, for doubles in error messages.
std::string FormatDouble(double x);

// Recursive descent over the tokens, building the expression DAG directly.
// The sections, declarations and loops are in minibex_parser.cc, the
// expressions in minibex_expression.cc.
class Parser {
 public:
  Parser(std::vector<Token> tokens, const std::string& source)
      : tokens_(std::move(tokens)), source_(source) {}

  ConstraintSystem Run();

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
      Fail(t, "input too large: loops, functions and temporaries expand to more than ", kMaxTokenWork,
           " tokens");
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

  // ---- Sections, declarations, loops (minibex_parser.cc) ------------------

  void ParseSystem();
  void ParseFunctions();
  void ParseEnding();
  void RejectUnsupportedSection();
  void ParseConstants();
  void ParseVariables();
  Shape ParseShape(const Token& name, const char* what);
  void Declare(const Token& name, const Shape& shape, const Interval& domain);
  const Token& NewName(const std::string& what);
  void ParseBlockList(const std::string& what);
  void ParseLoop();
  void SkipLoopBody(const std::string& what);
  bool AssignmentAhead() const;
  void ParseAssignment(const std::string& what);
  void ParseConstraint();
  bool ParenthesisedConstraintAhead() const;

  // ---- Names, indices, constant arrays (minibex_symbols.cc) ---------------

  // The symbol name denotes here: in a function body its parameters and
  // temporaries, then the system's constants; elsewhere the system's names.
  Symbol* Lookup(const std::string& name);
  Value Component(Symbol& s, int k);
  int ParseComponentIndex(const Symbol& s, const Token& name_token);
  int ParseIndex(const std::string& name, bool one_based, int size);
  std::vector<Interval> ParseConstantValue(const Token& name, const Shape& shape);
  bool ListAhead() const;
  Array ParseArray();
  Array ParseArrayItem();
  Binding BindExpression();
  Value Resolve(Binding& b);
  bool HoldsNoIntervalConstant(const Value& v) const;

  // ---- User functions (minibex_functions.cc) ------------------------------

  void ParseFunctionDefinition();
  Value ParseFunctionBody(const std::string& name);
  Value ParseCall(const std::string& name, const Function& f);
  std::vector<Binding> ParseArgument(const std::string& function, std::size_t k,
                                     const std::string& parameter, const Shape& shape);
  std::vector<Binding> WholeSymbolArgument(Symbol& s);

  // ---- Expressions (minibex_expression.cc) --------------------------------

  Expr ToExpr(const Value& v) { return v.expr ? *v.expr : csp_.Constant(v.constant); }

  static Value Const(const Interval& x) { return Value{x, std::nullopt}; }
  static Value Node(Expr e) { return Value{Interval(), e}; }

  // Inline, as only minibex_expression.cc calls them: their frames then merge
  // into their callers', which keeps a nesting level's stack small.
  inline Value Arithmetic(char op, const Value& a, const Value& b);
  inline Value ParseTerm();
  inline Value ParsePrimary();
  Value ParseExpr();
  Value ParseUnary();
  Value ParsePower();
  [[gnu::noinline]] Value ParseName();
  [[gnu::noinline]] Value ParseSymbol(Symbol& s);
  [[gnu::noinline]] Interval ParseIntervalLiteral();
  Interval ParseNumber(const Token& t);
  double ParseBound(bool lower);
  Interval ParseConstant(const What& what);
  long long ParseInteger(const What& what);
  long long ToInteger(const Interval& x, const Token& at, const What& what, double limit);

  std::vector<Token> tokens_;
  const std::string& source_;
  std::size_t pos_ = 0;
  long long work_ = 0;
  int depth_ = 0;
  std::unordered_map<std::string, Symbol> symbols_;
  std::unordered_map<std::string, Function> functions_;
  // The scopes of the function calls being read, innermost last (a deque:
  // pushing keeps references to the others' symbols valid); scope_ is the
  // one names are looked up in, 1-based, 0 for the system's names.
  std::deque<std::unordered_map<std::string, Symbol>> function_scopes_;
  int scope_ = 0;
  std::string function_being_defined_;  // to report recursion
  // Temporaries of the Constraints section, in order, so that a loop
  // iteration drops its own.
  std::vector<std::string> temporaries_;
  ConstraintSystem csp_;
};

}  // namespace icp::detail::minibex

#endif  // ICPBENCH_CORE_MINIBEX_PARSER_INTERNAL_H_
