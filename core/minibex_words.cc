// The words of Minibex: section keywords, reserved words, and the functions
// this reader supports (with their interval and DAG forms) or rejects.
#include <string>
#include <string_view>

#include "core/argument_contractor.h"
#include "core/minibex_parser_internal.h"

namespace icp::detail::minibex {
namespace {

constexpr std::string_view kSectionWords[] = {"constants", "variables", "constraints", "end",
                                              "parameters", "function", "minimize"};
constexpr std::string_view kKeywords[] = {"for", "begin", "return"};
// Words IBEX reserves for functions this reader does not support: calling one
// is a clear "not supported" error rather than "unknown identifier".
constexpr std::string_view kUnsupportedFunctions[] = {
    "sign", "floor", "ceil", "integer", "chi", "diff", "inf", "mid", "sup", "sum"};

// IBEX's inverse trigonometric and hyperbolic functions, written with the
// operations a tape has (for an interval constant and for an expression
// alike): each identity holds on the function's domain, and the domains of
// sqrt and log cut the rest, so the enclosures are sound; x occurring twice
// makes them wider than a dedicated operation's would be.
template <class T>
T AsinOf(const T& x) { return Atan2(x, Sqrt(1.0 - Sqr(x))); }  // in [-pi/2, pi/2]
template <class T>
T AcosOf(const T& x) {  // in [0, pi]; both arguments >= 0, away from atan2's cut at pi
  return 2.0 * Atan2(Sqrt(1.0 - x), Sqrt(1.0 + x));
}
template <class T>
T AsinhOf(const T& x) { return Log(x + Sqrt(Sqr(x) + 1.0)); }
template <class T>
T AcoshOf(const T& x) { return Log(x + Sqrt(Sqr(x) - 1.0)); }  // x <= -1 leaves a negative log argument
template <class T>
T AtanhOf(const T& x) { return 0.5 * Log((1.0 + x) / (1.0 - x)); }

const UnaryFunction kUnaryFunctions[] = {
    {"sqr", Sqr, Sqr},     {"sqrt", Sqrt, Sqrt}, {"exp", Exp, Exp},    {"log", Log, Log},
    {"ln", Log, Log},      {"sin", Sin, Sin},    {"cos", Cos, Cos},    {"tan", Tan, Tan},
    {"atan", Atan, Atan},  {"sinh", Sinh, Sinh}, {"cosh", Cosh, Cosh}, {"tanh", Tanh, Tanh},
    {"abs", Abs, Abs},
    {"asin", AsinOf<Interval>, [](Expr x) { return AsinOf(x); }},
    {"acos", AcosOf<Interval>, [](Expr x) { return AcosOf(x); }},
    {"asinh", AsinhOf<Interval>, [](Expr x) { return AsinhOf(x); }},
    {"acosh", AcoshOf<Interval>, [](Expr x) { return AcoshOf(x); }},
    {"atanh", AtanhOf<Interval>, [](Expr x) { return AtanhOf(x); }},
};

const BinaryFunction kBinaryFunctions[] = {
    {"min", Min, Min}, {"max", Max, Max}, {"atan2", Atan2, Atan2}};

}  // namespace

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

}  // namespace icp::detail::minibex
