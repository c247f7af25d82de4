// Reader for the Minibex subset used by IBEX benchmark files:
//
//   // comment
//   Constants
//     c = 0.1;  r in [1, 2];  k = 2*pi;  h = #3FB999999999999A;
//     v[3] = (1; 2; 3);  M[2][2] = ((1, 2); (3, 4));  d[2] in [0, 1];
//   function dist(a, b) t = a - b; return sqrt(t^2); end
//   Variables
//     x in [-1, 1];  y in [-oo, +oo];  p[3] in [0, 10];  A[2][2] in [0, 1];
//   Constraints
//     x^2 + y^2 = 2;  x(1) <= y;  p[0] >= min(x, y);  A(1,2) + A[1][1] = v(2);
//     for i=1:3; p(i) - x = 0; end;
//     s = x + y;  dist(s, M(2,1)) <= 1;
//   end
//
// Decimal constants are enclosed (ParseDecimal), never rounded to nearest;
// '#' and 16 hex digits is the double with those bits. A vector variable p[n]
// becomes scalars named "p[0]" .. "p[n-1]", a matrix A[m][n] "A[0][0]" ..
// "A[m-1][n-1]" row by row; p(i), A(i,j) are 1-based and p[i], A[i][j]
// 0-based. Functions and temporaries are inlined: the result is the DAG of
// the expressions written out by hand. The Constraints section is optional.
// Errors throw MinibexError with line and column (docs/cli.md lists what is
// not supported).
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
