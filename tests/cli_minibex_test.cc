// `icpbench solve` on Minibex files with user functions: inlining a function
// gives the boxes its body written out by hand gives (docs/cli.md).
#include <gtest/gtest.h>

#include <string>

#include "tests/cli_helpers.h"

namespace {

using icp::testing::Result;
using icp::testing::WriteFile;

Result Icpbench(const std::string& args) { return icp::testing::RunCommand(ICPBENCH_BINARY, args); }

TEST(CliMinibexTest, AFunctionSolvesAsItsBodyWrittenByHand) {
  const std::string with_functions = WriteFile("with_functions.bch", R"(
Constants
  a[2] = (1; 2);
  r in [0.9, 1.1];
function dist(xa, ya, xb, yb)
  dx = xa - xb;
  dy = ya - yb;
  return sqrt(dx^2 + dy^2);
end
Variables
  p[2] in [-5, 5];
function ring(v[2]) return dist(v(1), v(2), a(1), a(2)) - r; end
Constraints
  ring(p) = 0;
  dist(p(1), p(2), 0, 0) <= 2;
  t = p(1) + p(2) * [0.5, 0.6];
  t >= 1;
end
)");
  const std::string by_hand = WriteFile("by_hand.bch", R"(
Constants
  r in [0.9, 1.1];
Variables
  p[2] in [-5, 5];
Constraints
  sqrt((p(1) - 1)^2 + (p(2) - 2)^2) - r = 0;
  sqrt((p(1) - 0)^2 + (p(2) - 0)^2) <= 2;
  p(1) + p(2) * [0.5, 0.6] >= 1;
end
)");
  for (const std::string algorithm : {"hc4", "bc4"}) {
    const Result a = Icpbench("solve " + with_functions + " -a " + algorithm + " -f json");
    const Result b = Icpbench("solve " + by_hand + " -a " + algorithm + " -f json");
    ASSERT_EQ(a.exit_code, 0) << a.out;
    ASSERT_EQ(b.exit_code, 0) << b.out;
    const std::size_t box_a = a.out.find("\"box\""), box_b = b.out.find("\"box\"");
    ASSERT_NE(box_a, std::string::npos) << a.out;
    const std::string tail_a = a.out.substr(box_a, a.out.find('}', box_a) - box_a);
    const std::string tail_b = b.out.substr(box_b, b.out.find('}', box_b) - box_b);
    EXPECT_EQ(tail_a, tail_b) << algorithm;
    EXPECT_NE(tail_a.find("p[1]"), std::string::npos) << a.out;
  }
}

}  // namespace
