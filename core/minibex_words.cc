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
    "acos", "asin", "acosh", "asinh", "atanh", "sign", "floor", "ceil",
    "integer", "chi", "diff", "inf", "mid", "sup", "sum"};

const UnaryFunction kUnaryFunctions[] = {
    {"sqr", Sqr, Sqr},     {"sqrt", Sqrt, Sqrt}, {"exp", Exp, Exp},    {"log", Log, Log},
    {"ln", Log, Log},      {"sin", Sin, Sin},    {"cos", Cos, Cos},    {"tan", Tan, Tan},
    {"atan", Atan, Atan},  {"sinh", Sinh, Sinh}, {"cosh", Cosh, Cosh}, {"tanh", Tanh, Tanh},
    {"abs", Abs, Abs},
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
