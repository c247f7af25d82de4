// Minibex user functions (IBEX's "function f(x, y[3]) ... return e; end"):
// a definition is read once to check it, and each call reads the body again
// with the parameters bound to the arguments, so a call builds the same DAG
// as its body written out by hand at the call.
#include <string>
#include <utility>
#include <vector>

#include "core/minibex_parser_internal.h"

namespace icp::detail::minibex {

// function NAME '(' NAME [shape] {',' NAME [shape]} ')' body. The body is
// read with each parameter bound to fresh variables of a scratch system, so
// that its errors are reported here and the system's graph is untouched.
void Parser::ParseFunctionDefinition() {
  Next();  // 'function'
  const Token& name = NewName("function");
  function_being_defined_ = name.text;
  Expect("(", {"after the name of function", name.text});
  Function f;
  ConstraintSystem scratch;
  std::swap(csp_, scratch);
  function_scopes_.emplace_back();
  const int scope = scope_;
  scope_ = static_cast<int>(function_scopes_.size());
  do {
    const Token& parameter = NewName("parameter");
    const Shape shape = ParseShape(parameter, "parameter");
    Symbol s{Symbol::kBound, shape};
    for (int k = 0; k < shape.size(); ++k) {
      Binding b;
      b.value = Node(csp_.AddVariable(parameter.text + "[" + std::to_string(k) + "]", Interval()));
      s.bindings.push_back(std::move(b));
    }
    function_scopes_.back()[parameter.text] = std::move(s);
    f.parameters.emplace_back(parameter.text, shape);
  } while (Accept(","));
  Expect(")", {"after the parameters of function", name.text});
  f.body = pos_;
  ParseFunctionBody(name.text);
  function_scopes_.pop_back();
  scope_ = scope;
  std::swap(csp_, scratch);
  function_being_defined_.clear();
  functions_[name.text] = std::move(f);
}

// {NAME '=' expr ';'} return expr [';'] end, in the current function scope.
Value Parser::ParseFunctionBody(const std::string& name) {
  while (!IsWord("return")) {
    if (AtEnd() || IsSectionWord(Peek().text))
      Fail(Peek(), "expected 'return' in function '", name, "', found ", Peek());
    const Token& temporary = NewName("temporary");
    Expect("=", {"after the temporary", temporary.text});
    Symbol s{Symbol::kBound};
    s.bindings.push_back(BindExpression());
    function_scopes_[scope_ - 1][temporary.text] = std::move(s);
    Expect(";", {"after the expression of", temporary.text});
  }
  Next();  // 'return'
  const Token& start = Peek();
  if (IsPunct("(") && ListAhead())
    Fail(start, "function '", name, "' returns a vector or matrix, which is not supported");
  const Value result = ParseExpr();
  Accept(";");
  if (!IsWord("end")) Fail(Peek(), "expected 'end' after the return value of '", name, "', found ", Peek());
  Next();
  return result;
}

// NAME '(' arg {',' arg} ')': the body read again, in a scope of its own,
// with the parameters bound to the arguments.
Value Parser::ParseCall(const std::string& name, const Function& f) {
  DepthGuard guard(this);
  Next();
  Expect("(", {"after", name});
  std::unordered_map<std::string, Symbol> arguments;
  std::size_t k = 0;
  do {
    if (k == f.parameters.size()) {
      Fail(Peek(), "function '", name, "' takes ", f.parameters.size(),
           f.parameters.size() == 1 ? " argument" : " arguments", ", got more");
    }
    const auto& [parameter, shape] = f.parameters[k];
    Symbol s{Symbol::kBound, shape};
    s.bindings = ParseArgument(name, k, parameter, shape);
    arguments[parameter] = std::move(s);
    ++k;
  } while (Accept(","));
  if (k < f.parameters.size()) {
    Fail(Peek(), "function '", name, "' takes ", f.parameters.size(), " arguments, got ", k);
  }
  Expect(")", {"after the arguments of", name});
  const std::size_t resume = pos_;
  const int scope = scope_;
  function_scopes_.push_back(std::move(arguments));
  scope_ = static_cast<int>(function_scopes_.size());
  pos_ = f.body;
  const Value result = ParseFunctionBody(name);
  function_scopes_.pop_back();
  scope_ = scope;
  pos_ = resume;
  return result;
}

// A scalar argument is any expression; a vector or matrix one is the name
// of a vector or matrix of that shape, or an array such as (a; b; c).
std::vector<Binding> Parser::ParseArgument(const std::string& function, std::size_t k,
                                           const std::string& parameter, const Shape& shape) {
  if (shape.is_scalar()) return {BindExpression()};
  const Token& start = Peek();
  if (start.kind == TokKind::kIdent && (IsPunct(",", 1) || IsPunct(")", 1))) {
    if (Symbol* s = Lookup(start.text); s && !s->shape.is_scalar()) {
      Next();
      if (!(s->shape == shape))
        Fail(start, "argument ", k + 1, " of '", function, "' must have the shape of ",
             shape.Describe(parameter), ", not ", s->shape.Describe(start.text));
      return WholeSymbolArgument(*s);
    }
  }
  if (IsPunct("(") && ListAhead()) {
    Array array = ParseArray();
    if (!(array.shape == shape))
      Fail(start, "argument ", k + 1, " of '", function, "' must have the shape of ",
           shape.Describe(parameter), ", not ", array.shape.Describe("(...)"));
    return std::move(array.components);
  }
  Fail(start, "argument ", k + 1, " of '", function, "' must be ", shape.Describe(parameter),
       ": the name of one, or an array such as (a; b)");
}

// Each component of a vector or matrix passed whole.
std::vector<Binding> Parser::WholeSymbolArgument(Symbol& s) {
  if (s.kind == Symbol::kBound) return s.bindings;
  std::vector<Binding> out(s.shape.size());
  for (int i = 0; i < s.shape.size(); ++i) out[i].value = Component(s, i);
  return out;
}

}  // namespace icp::detail::minibex
