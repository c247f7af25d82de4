// What the Minibex parser's tests share: evaluating a parsed constraint, the
// enclosure of a decimal, and checking the errors of rejected texts.
#ifndef ICPBENCH_CORE_MINIBEX_PARSER_TESTING_H_
#define ICPBENCH_CORE_MINIBEX_PARSER_TESTING_H_

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/constraint_system.h"
#include "core/minibex_parser.h"
#include "core/tape.h"

namespace icp::testing {

// Enclosure of constraint c's function at box.
inline Interval Eval(const ConstraintSystem& csp, int c, const Box& box) {
  std::vector<Interval> slots;
  return Tape(csp.graph(), csp.constraints()[c]).Forward(box, slots);
}

inline Box PointBox(const std::vector<double>& point) {
  Box box;
  for (double v : point) box.push_back(Interval(v));
  return box;
}

inline Interval Decimal(const std::string& text) {
  Interval x;
  EXPECT_TRUE(ParseDecimal(text, &x)) << text;
  return x;
}

// Parses text that must be rejected; returns the error.
inline MinibexError ErrorOf(const std::string& text) {
  try {
    ParseMinibex(text, "t.mbx");
  } catch (const MinibexError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return MinibexError("t.mbx", -1, -1, "accepted");
}

// A text the parser must reject, where and why.
struct BadInput {
  std::string text;
  int line;  // 0: do not check the position
  int column;
  std::string message_part;
};

inline void ExpectRejected(const std::vector<BadInput>& cases) {
  for (const BadInput& c : cases) {
    SCOPED_TRACE(c.text);
    const MinibexError e = ErrorOf(c.text);
    EXPECT_NE(std::string(e.what()).find(c.message_part), std::string::npos) << e.what();
    if (c.line > 0) {
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_EQ(e.column(), c.column) << e.what();
    }
  }
}

}  // namespace icp::testing

#endif  // ICPBENCH_CORE_MINIBEX_PARSER_TESTING_H_
