// Reader for the Minibex subset used by IBEX benchmark files:
//
//   // comment
//   Constants
//     c = 0.1;  r in [1, 2];  k = 2*pi;   (scalar constant expressions)
//   Variables
//     x in [-1, 1];  y in [-oo, +oo];  p[3] in [0, 10];
//   Constraints
//     x^2 + y^2 = 2;  x(1) <= y;  p[0] >= min(x, y);
//     for i=1:3; p(i) - x = 0; end;
//   end
//
// Decimal constants are enclosed (ParseDecimal), never rounded to nearest.
// A vector variable p[n] becomes scalars named "p[0]" .. "p[n-1]"; p(i) is
// 1-based and p[i] 0-based. Errors throw MinibexError with line and column.
#ifndef ICPBENCH_CORE_MINIBEX_PARSER_H_
#define ICPBENCH_CORE_MINIBEX_PARSER_H_

#include <stdexcept>
#include <string>

#include "core/constraint_system.h"

namespace icp {

class MinibexError : public std::runtime_error {
 public:
  MinibexError(const std::string& source, int line, int column, const std::string& message);
  int line() const { return line_; }
  int column() const { return column_; }

 private:
  int line_;
  int column_;
};

// Parses Minibex text; source names the input in error messages.
ConstraintSystem ParseMinibex(const std::string& text, const std::string& source = "<input>");
// The text of a Minibex file; an unreadable one (missing, a directory, a
// pipe or a device, a read error) is a MinibexError at line 0.
std::string ReadMinibexFile(const std::string& path);
// ParseMinibex(ReadMinibexFile(path), path).
ConstraintSystem ParseMinibexFile(const std::string& path);

}  // namespace icp

#endif  // ICPBENCH_CORE_MINIBEX_PARSER_H_
