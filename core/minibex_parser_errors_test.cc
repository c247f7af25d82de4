// Minibex parser tests on input it must reject: error messages and
// positions, nesting and size limits, files, and randomly damaged text.
#include "core/minibex_parser.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/minibex_parser_testing.h"
#include "core/random.h"
#include "core/tape.h"

namespace icp {
namespace {

using testing::BadInput;
using testing::ErrorOf;
using testing::ExpectRejected;

TEST(MinibexParserTest, ErrorMessageFormat) {
  const MinibexError e = ErrorOf("Variables x in [0,1];\nConstraints\n  x + q = 0;\nend");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.column(), 7);
  EXPECT_EQ(std::string(e.what()), "t.mbx:3:7: unknown identifier 'q'");
}

TEST(MinibexParserTest, RejectsBadInputWithPosition) {
  const std::vector<BadInput> cases = {
      {"", 1, 1, "expected 'Variables'"},
      {"Variables x in [0,1]; Constraints x = 1;", 1, 41, "unterminated Constraints"},
      {"Variables x in [0,1]; Constraints x = 1; end end", 1, 46, "after the final 'end'"},
      {"Variables x in [0,1] y in [0,1]; end", 1, 22, "expected ';'"},
      {"Variables x in [0,1];\nConstraints\n x = 1\n x = 2; end", 4, 2, "expected ';'"},
      {"Variables x in [0,1]; x in [2,3]; end", 1, 23, "duplicate name 'x'"},
      {"Constants c = 1; Variables c; end", 1, 28, "duplicate name 'c'"},
      {"Variables x in [2,1]; end", 1, 16, "empty interval"},
      {"Variables x in [+oo,+oo]; end", 1, 16, "empty interval"},
      {"Variables x in [0,1];\nConstraints x^4e9 = 1; end", 2, 15, "the exponent is too large"},
      {"Variables x in [0,1]; Constraints foo(x) = 1; end", 1, 35, "unknown function 'foo'"},
      {"Variables x in [0,1]; Constraints floor(x) = 1; end", 1, 35, "not supported"},
      {"Variables x[3] in [0,1];\nConstraints\n  x(4) = 1; end", 3, 5, "out of range"},
      {"Variables x[3] in [0,1]; Constraints x(0) = 1; end", 1, 40, "out of range"},
      {"Variables x[3] in [0,1]; Constraints x[3] = 1; end", 1, 40, "out of range"},
      {"Variables x[3] in [0,1];\nConstraints\n for i=1:3;\n  x(i+1) = 1;\n end;\nend", 4, 5,
       "index 4 out of range"},
      {"Variables x[3] in [0,1]; Constraints x = 1; end", 1, 38, "must be indexed"},
      {"Variables x in [0,1]; Constraints x(1) = 1; end", 1, 36, "is a scalar and cannot be indexed"},
      {"Variables x in [0,1]; Constraints x = 1e; end", 1, 39, "bad number"},
      {"Variables x in [0,1]; Constraints x = 2x; end", 1, 39, "bad number"},
      {"Variables x in [0,1]; Constraints x = 1.2.3; end", 1, 39, "bad number"},
      {"Variables x in [0,1]; Constraints x = 1 # 2; end", 1, 41, "unexpected character '#'"},
      {"Variables x in [0,1]; Constraints x = 1; /* open", 1, 42, "unterminated /* comment"},
      {"Variables x in [0,1]; Constraints x + 1; end", 1, 40, "expected '=', 'in', '<=' or '>='"},
      {"Variables x in [0,1]; Minimize y; end", 1, 32, "unknown identifier 'y'"},
      {"Variables x in [0,1]; Minimize x; Minimize x; end", 1, 35, "expected 'Constraints'"},
      {"Variables x in [0,1]; Constraints x = max(x, 1,); end", 1, 48, "expected an expression"},
      {"Variables x in [0,1]; Constraints x = atan2(x, 1, 2); end", 1, 49,
       "after the second argument of 'atan2'"},
      {"Variables x in [0,1]; Constraints x = (1 + x; end", 1, 45, "expected ')'"},
      {"Variables x in [0,1]; Constraints x = sin x; end", 1, 43, "expected '('"},
      {"Variables x in [0,1]; Constraints x = min(x); end", 1, 44, "expected ','"},
      {"Variables x in [0,1]; Constraints x = sqrt(x, x); end", 1, 45, "one argument"},
      {"Variables x in [0,1]; Constraints = 1; end", 1, 35, "expected an expression"},
      {"Variables x in [0,1]; Constraints end", 1, 35, "expected a constraint"},
      {"Variables x in [0,1]; Constraints x = oo; end", 1, 39, "interval bound"},
      {"Variables end", 1, 11, "reserved word"},
      {"Variables 2; end", 1, 11, "expected a variable name"},
      {"Variables sin in [0,1]; end", 1, 11, "reserved word"},
      {"Variables x in [0,1]; Constraints\n for i=1:2; x = i;", 2, 19, "unterminated for loop"},
      {"Variables x in [0,1]; Constraints for i=2:1; x = 0;", 1, 52, "unterminated for loop"},
      {"Variables x in [0,1]; Constraints for i=1:2.5; x = 0; end; end", 1, 43,
       "must be an integer"},
      {"Variables x in [0,1]; Constraints for x=1:2; x = 0; end; end", 1, 39, "duplicate"},
      {"Variables x in [0,1]; Constraints for i=1:2; for i=1:2; x=0; end; end; end", 1, 50,
       "duplicate"},
      {"Variables x in [0,1]; Constraints x = i; end", 1, 39, "unknown identifier 'i'"},
      {"Constants c = x; Variables x; end", 1, 15, "unknown identifier 'x'"},
      {"Constants v[2] = (1, 2); Variables x; end", 1, 18, "wrong shape"},
      {"Constants c = sqrt(-1); Variables x; end", 1, 15, "empty set"},
      {"Variables x; y in [x, 1]; end", 1, 20, "constant expression"},
      {"Variables x[0]; end", 1, 13, "positive dimensions"},
      {"Variables x[2][2][2]; end", 1, 18, "three dimensions"},
      {"Variables x[1e12]; end", 1, 13, "too large"},
      {"Variables x in [0,1]; Parameters p; end", 1, 23, "not supported"},
      {"Constraints x = 1; end", 1, 1, "expected 'Variables'"},
      {"Variables x in [0,1]; Constraints x = 1; end\n;;", 2, 2, "after the final 'end'"},
      {"Variables\n\tx in [0,1]\xff; end", 2, 12, "unexpected byte 0xFF"},
      // Only a byte order mark that starts the text is skipped.
      {"Variables x\xEF\xBB\xBF in [0,1]; end", 1, 12, "unexpected byte 0xEF"},
      {"\xEF\xBB\xBF\xEF\xBB\xBFVariables x; end", 1, 1, "unexpected byte 0xEF"},
      {"Variables x in [0,1]; Constraints x = [1, 2; end", 1, 44, "expected ']'"},
      {"Variables x in [0,1]; Constraints x = 2^40000000000; end", 1, 41, "too large"},
  };
  ExpectRejected(cases);
}

// Loops, temporaries and calls that double at each level expand
// exponentially: past a bound on the tokens read, the parse stops with an
// error (in about a second) instead of running for hours.
TEST(MinibexParserTest, AnExpansionPastTheTokenBoundIsAnError) {
  std::string temporaries = "Variables x; Constraints t0 = x + [1, 2];\n";
  for (int i = 1; i < 40; ++i)
    temporaries += "t" + std::to_string(i) + " = t" + std::to_string(i - 1) + " - t" + std::to_string(i - 1) + ";\n";
  auto calls = [](int levels) {  // f_i calls f_(i-1) twice
    std::string text = "function f0(a) return a + [1, 2]; end\n";
    for (int i = 1; i < levels; ++i)
      text += "function f" + std::to_string(i) + "(a) return f" + std::to_string(i - 1) + "(a) * f" +
              std::to_string(i - 1) + "(a); end\n";
    return text + "Variables x; Constraints f" + std::to_string(levels - 1) + "(x) <= 1; end";
  };
  const std::vector<BadInput> cases = {
      {temporaries + "t39 <= 1; end", 0, 0, "input too large"},
      {calls(40), 0, 0, "input too large"},
      {"Variables x; Constraints for i = 1:1e9; x <= i; end; end", 0, 0, "input too large"},
  };
  ExpectRejected(cases);
  // Ten levels are fine.
  EXPECT_EQ(ParseMinibex(calls(10)).constraints().size(), 1u);
}

TEST(MinibexParserTest, DeepNestingIsAnErrorNotACrash) {
  auto nested = [](int depth) {
    return "Variables x in [0,1]; Constraints " + std::string(depth, '(') + "x" +
           std::string(depth, ')') + " = 0; end";
  };
  EXPECT_NO_THROW(ParseMinibex(nested(200)));
  // Just under the limit (500 levels): no stack overflow.
  EXPECT_NO_THROW(ParseMinibex(nested(495)));
  EXPECT_THROW(ParseMinibex(nested(505)), MinibexError);
  std::string calls = "Variables x; Constraints ";
  for (int i = 0; i < 495; ++i) calls += i % 2 ? "sin(" : "max(x, ";
  EXPECT_NO_THROW(ParseMinibex(calls + "x" + std::string(495, ')') + " = 0; end"));
  std::string loops = "Variables x; Constraints ";
  for (int i = 0; i < 495; ++i) loops += "for i" + std::to_string(i) + "=1:1; ";
  loops += "x = 0" + std::string(495, ' ');
  for (int i = 0; i < 495; ++i) loops += "end; ";
  EXPECT_EQ(ParseMinibex(loops + "end").constraints().size(), 1u);
  EXPECT_THROW(ParseMinibex(nested(100000)), MinibexError);
  const std::string minus = "Variables x; Constraints " + std::string(100000, '-') + "x = 0; end";
  EXPECT_THROW(ParseMinibex(minus), MinibexError);
  // '^' is left-associative: a long chain is a loop, not a recursion.
  std::string powers = "Variables x; Constraints x";
  for (int i = 0; i < 100000; ++i) powers += "^1";
  EXPECT_NO_THROW(ParseMinibex(powers + " = 0; end"));
  // Signed exponents nest (x^-1^-1 is x^(-(1^(-1)))): a long chain is deep.
  std::string signed_powers = "Variables x; Constraints x";
  for (int i = 0; i < 100000; ++i) signed_powers += "^-1";
  EXPECT_THROW(ParseMinibex(signed_powers + " = 0; end"), MinibexError);
  std::string deep_loops = "Variables x; Constraints ";
  for (int i = 0; i < 5000; ++i) deep_loops += "for i" + std::to_string(i) + "=1:1; ";
  EXPECT_THROW(ParseMinibex(deep_loops + "x = 0;"), MinibexError);
  // Parenthesised constraints nest too.
  const std::string deep_constraint =
      "Variables x; Constraints " + std::string(100000, '(') + "x <= 1" + std::string(100000, ')') + "; end";
  EXPECT_THROW(ParseMinibex(deep_constraint), MinibexError);
}

TEST(MinibexParserTest, HugeLoopIsAnErrorNotAHang) {
  // Each outer iteration re-reads the (skipped) inner loop until the token
  // budget runs out.
  EXPECT_THROW(
      ParseMinibex("Variables x; Constraints for i=1:1e15; for j=2:1; x = 0; end; end; end"),
      MinibexError);
}

TEST(MinibexParserTest, ParseMinibexFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::string missing = (dir / "icpbench_no_such_file.mbx").string();
  try {
    ParseMinibexFile(missing);
    ADD_FAILURE() << "missing file accepted";
  } catch (const MinibexError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_THROW(ParseMinibexFile(dir.string()), MinibexError);
  // A pipe is refused by its kind: opening it would wait for a writer.
  const std::string fifo = (dir / ("icpbench_fifo_" + std::to_string(::getpid()) + ".bch")).string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  try {
    ParseMinibexFile(fifo);
    ADD_FAILURE() << "a pipe accepted";
  } catch (const MinibexError& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
  std::filesystem::remove(fifo);

  const std::string path =
      (dir / ("icpbench_parser_test_" + std::to_string(::getpid()) + ".mbx")).string();
  {
    std::ofstream out(path);
    out << "Variables\n  x in [0, 1];\nConstraints\n  x = y;\nend\n";
  }
  try {
    ParseMinibexFile(path);
    ADD_FAILURE() << "bad file accepted";
  } catch (const MinibexError& e) {
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.column(), 7);
    EXPECT_EQ(std::string(e.what()).rfind(path + ":4:7: ", 0), 0u) << e.what();
  }
  {
    std::ofstream out(path);
    out << "Variables\n  x in [0, 1];\nConstraints\n  x = 0.5;\nend\n";
  }
  ConstraintSystem csp = ParseMinibexFile(path);
  EXPECT_EQ(csp.num_variables(), 1);
  EXPECT_EQ(csp.constraints().size(), 1u);
  std::filesystem::remove(path);
}

// Random truncations and character edits of a valid file must either parse or
// throw MinibexError: never crash, hang or throw anything else.
TEST(MinibexParserTest, FuzzedInputsParseOrThrowMinibexError) {
  const std::string base = R"(// fuzz seed
Constants
  n = 3;
  c = 0.1;
  r in [1, 2.5];
Variables
  x[n] in [-1e3, +oo];
  y in [-oo, 1];
  z;
Constraints
  for i=1:n;
    x(i)^2 + c*y >= i*0.5;
    for j=i:n; x[j-1] - x(i) <= r; end;
  end;
  sin(y)*exp(-z) + ln(2 + abs(z)) - sqrt(sqr(y)) = min(y, max(z, -2));
  /* block */ y^-1 + z^(n-1) < pi;
end
)";
  ASSERT_NO_THROW(ParseMinibex(base));
  const std::string alphabet =
      "xyzncrij0123456789.e+-*/^()[]{},;:=<>! \n\t/#_aAoO";
  const std::vector<std::string> words = {"for", "end", "oo", "in", "Variables", "Constraints",
                                          "1e308", "1e-400", "99999999999", "sqrt(", "pi", "//",
                                          "/*", "x(", "x[", "0", "-", "^"};
  RandomEngine rng(12345);
  auto pick = [&rng](std::size_t n) { return UniformIndex(rng, n); };
  int parsed = 0, rejected = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string text = base;
    const int edits = 1 + static_cast<int>(pick(3));
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = pick(text.size() + 1);
      switch (pick(5)) {
        case 0:
          text.resize(at);
          break;
        case 1:
          if (at < text.size()) text[at] = alphabet[pick(alphabet.size())];
          break;
        case 2:
          if (at < text.size()) text[at] = static_cast<char>(pick(256));
          break;
        case 3:
          text.insert(at, words[pick(words.size())]);
          break;
        default:
          text.erase(at, pick(8));
          break;
      }
    }
    try {
      ConstraintSystem csp = ParseMinibex(text, "fuzz");
      CompiledSystem compiled(csp);  // the graph must be well formed
      EXPECT_EQ(compiled.num_variables(), csp.num_variables());
      ++parsed;
    } catch (const MinibexError& e) {
      ++rejected;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected " << e.what() << " on:\n" << text;
    }
  }
  // Both outcomes must occur, or the mutations are not exercising anything.
  EXPECT_GT(parsed, 50);
  EXPECT_GT(rejected, 500);
}

}  // namespace
}  // namespace icp
