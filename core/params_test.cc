#include "core/params.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "core/near_names.h"

namespace icp {
namespace {

struct InnerParams {
  double ratio = 0.1;
};
void Describe(InnerParams& p, ParamSet& set) {
  set.Add("ratio", &p.ratio, "inner ratio", Range::HalfOpen(0, 1));
}

struct ExampleParams {
  double ratio = 0.01;
  int slices = 10;
  bool verbose = false;
  std::string mode = "fast";
  InnerParams inner;
};
void Describe(ExampleParams& p, ParamSet& set) {
  set.Add("ratio", &p.ratio, "a ratio", Range::HalfOpen(0, 1));
  set.Add("slices", &p.slices, "slice count", Range::Closed(1, 1000));
  set.Add("verbose", &p.verbose, "chatty");
  set.Add("mode", &p.mode, "mode", {"fast", "slow"});
  set.Nest("inner", [&p](ParamSet& s) { Describe(p.inner, s); });
}

TEST(ParamsTest, DefaultsComeFromTheStruct) {
  auto info = DefaultParams<ExampleParams>("example");
  ASSERT_EQ(info.size(), 5u);
  EXPECT_EQ(info[0].name, "ratio");
  EXPECT_EQ(info[0].default_value, "0.01");
  EXPECT_EQ(info[0].range, "[0, 1)");
  EXPECT_EQ(info[1].type, "int");
  EXPECT_EQ(info[2].default_value, "false");
  EXPECT_EQ(info[3].range, "one of fast|slow");
  EXPECT_EQ(ChoicesOf(info[3]), (std::vector<std::string>{"fast", "slow"}));  // read back
  EXPECT_TRUE(ChoicesOf(info[0]).empty());
  EXPECT_EQ(info[4].name, "inner.ratio");
  EXPECT_EQ(info[4].default_value, "0.1");
}

TEST(ParamsTest, SetsFieldsByNameIncludingNestedOnes) {
  auto p = ParseParams<ExampleParams>(
      "example", {{"ratio", "0.5"}, {"slices", "20"}, {"verbose", "true"}, {"mode", "slow"},
                  {"inner.ratio", "0.25"}});
  EXPECT_EQ(p.ratio, 0.5);
  EXPECT_EQ(p.slices, 20);
  EXPECT_TRUE(p.verbose);
  EXPECT_EQ(p.mode, "slow");
  EXPECT_EQ(p.inner.ratio, 0.25);
}

TEST(ParamsTest, RejectsBadInputWithFieldValueAndRule) {
  auto message = [](const ParamMap& m) {
    try {
      ParseParams<ExampleParams>("example", m);
    } catch (const ParamError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({{"ratio", "-1"}}), "example.ratio = -1: must be in [0, 1)");
  EXPECT_EQ(message({{"ratio", "1"}}), "example.ratio = 1: must be in [0, 1)");
  EXPECT_EQ(message({{"ratio", "nan"}}), "example.ratio = nan: not a number");
  EXPECT_EQ(message({{"ratio", "0.1x"}}), "example.ratio = 0.1x: not a number");
  EXPECT_EQ(message({{"slices", "2.5"}}), "example.slices = 2.5: must be an integer in [1, 1000]");
  EXPECT_EQ(message({{"slices", "0"}}), "example.slices = 0: must be in [1, 1000]");
  // "no" is not read as true (a habit of lenient parsers, see STYLE.md).
  EXPECT_EQ(message({{"verbose", "no"}}), "example.verbose = no: must be true or false");
  EXPECT_EQ(message({{"mode", "medium"}}), "example.mode = medium: must be one of fast|slow");
  EXPECT_EQ(message({{"inner.ratio", "2"}}), "example.inner.ratio = 2: must be in [0, 1)");
  EXPECT_EQ(message({{"speed", "1"}}),
            "unknown parameter 'speed' for example (known: ratio, slices, verbose, mode, "
            "inner.ratio)");
  EXPECT_EQ(message({{"ratoi", "1"}}),
            "unknown parameter 'ratoi' for example; did you mean 'ratio'? (known: ratio, slices, "
            "verbose, mode, inner.ratio)");
}

// A likely misspelling is named; a far or ambiguous name is not guessed.
// Two fields of one name would be one key for two values; a name that
// `--param NAME=VALUE` or a spec cannot write could never be set.
TEST(ParamsTest, ANameDeclaredTwiceOrUnwritableIsRefused) {
  double a = 0, b = 0;
  ParamSet set("example");
  set.Add("ratio", &a, "", Range::Closed(0, 1));
  try {
    set.Add("ratio", &b, "", Range::Closed(0, 1));
    ADD_FAILURE() << "a second 'ratio' was accepted";
  } catch (const ParamError& e) {
    EXPECT_STREQ(e.what(), "example: parameter 'ratio' is declared twice");
  }
  for (const std::string bad : {"", "a=b", "a b", "_a", "a.", ".a", "a..b", "a,b", "a|b", "\u00e9"}) {
    ParamSet fresh("example");
    EXPECT_THROW(fresh.Add(bad, &a, "", Range::Closed(0, 1)), ParamError) << bad;
  }
  for (const std::string good : {"x", "max_revise_calls", "inner.epsilon", "3b", "a-b", "Max"}) {
    ParamSet fresh("example");
    EXPECT_NO_THROW(fresh.Add(good, &a, "", Range::Closed(0, 1))) << good;
  }
  // A nested name that meets an outer one is a duplicate too.
  ParamSet outer("example");
  outer.Add("inner.epsilon", &a, "", Range::Closed(0, 1));
  EXPECT_THROW(outer.Nest("inner", [&b](ParamSet& s) { s.Add("epsilon", &b, "", Range::Closed(0, 1)); }),
               ParamError);
}

TEST(NearNamesTest, SuggestsOnlyALikelyMisspelling) {
  const std::vector<std::string> keys = {"seeds", "name", "timeout_s", "algorithms", "problems"};
  EXPECT_EQ(DidYouMean("seed", keys), "; did you mean 'seeds'?");
  EXPECT_EQ(DidYouMean("algoritms", keys), "; did you mean 'algorithms'?");
  EXPECT_EQ(DidYouMean("porblems", keys), "; did you mean 'problems'?");  // a swap is one edit
  EXPECT_EQ(DidYouMean("timeout", keys), "; did you mean 'timeout_s'?");  // 2 of 7 off
  EXPECT_EQ(DidYouMean("time", keys), "");  // 5 off
  EXPECT_EQ(DidYouMean("Seeds", keys), "; did you mean 'seeds'?");  // case ignored
  EXPECT_EQ(DidYouMean("HC4", {"hc3", "hc4", "bc4"}), "; did you mean 'hc4'?");
  EXPECT_EQ(DidYouMean("speed", keys), "");
  EXPECT_EQ(DidYouMean("", keys), "");
  EXPECT_EQ(DidYouMean("ab", {"ac", "ad"}), "");  // tied
  EXPECT_EQ(DidYouMean("hc4", {"hc3", "hc4x"}), "");
  EXPECT_EQ(DidYouMean("hc5", {"hc4", "bc4"}), "; did you mean 'hc4'?");
}

TEST(ParamsTest, ValuesRoundTrip) {
  ExampleParams p;
  p.ratio = 0.1;
  ParamSet set("example");
  Describe(p, set);
  ParamMap values = set.Values();
  EXPECT_EQ(values["ratio"], "0.1");
  auto q = ParseParams<ExampleParams>("example", values);
  EXPECT_EQ(q.ratio, p.ratio);
  EXPECT_EQ(q.slices, p.slices);
}

// Integer parameters: ranges print as the integers they allow (an open end
// or an unbounded one resolved), exact integers written with an exponent
// (YAML's and hand-written specs' 1e7) are read, and every rejection gives
// the range.
struct CountParams {
  int count = 5;
  int positive = 1;
  int big = 10;
};
void Describe(CountParams& p, ParamSet& set) {
  set.Add("count", &p.count, "at least 0", Range::AtLeast(0));
  set.Add("positive", &p.positive, "above 0", Range::Positive(1e7));
  set.Add("big", &p.big, "up to 1e7", Range::Closed(1, 1e7));
}

std::string CountMessage(const std::string& key, const std::string& value) {
  try {
    ParseParams<CountParams>("count", {{key, value}});
  } catch (const ParamError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ParamsTest, IntegerRangesPrintAsIntegers) {
  const std::vector<ParamInfo> info = DefaultParams<CountParams>("count");
  EXPECT_EQ(info[0].range, "[0, 2147483647]");
  EXPECT_EQ(info[1].range, "[1, 10000000]");
  EXPECT_EQ(info[2].range, "[1, 10000000]");
}

TEST(ParamsTest, IntegersWithAnExponentAreReadWhenExact) {
  const auto p = ParseParams<CountParams>(
      "count", {{"count", "1e7"}, {"positive", "2.5e3"}, {"big", "+10000000.0"}});
  EXPECT_EQ(p.count, 10000000);
  EXPECT_EQ(p.positive, 2500);
  EXPECT_EQ(p.big, 10000000);
  // One canonical spelling: 1e7 and 10000000 are one run.
  EXPECT_EQ(ResolveParams<CountParams>("count", {{"count", "1e7"}}).at("count"), "10000000");
  EXPECT_EQ(ParseParams<CountParams>("count", {{"count", "2147483647"}}).count, 2147483647);
  EXPECT_EQ(ParseParams<CountParams>("count", {{"count", "00"}}).count, 0);
}

TEST(ParamsTest, IntegerRejectionsSayWhyAndGiveTheRange) {
  EXPECT_EQ(CountMessage("count", "1.5"),
            "count.count = 1.5: must be an integer in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", "1e-1"),
            "count.count = 1e-1: must be an integer in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", "+oo"),
            "count.count = +oo: must be an integer in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", "inf"),
            "count.count = inf: must be an integer in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", "0x10"),
            "count.count = 0x10: must be an integer in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", " 5"), "count.count =  5: must be an integer in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", ""), "count.count = : must be an integer in [0, 2147483647]");
  // Integers out of range, inside the int type or beyond it, are out of range.
  EXPECT_EQ(CountMessage("count", "-1"), "count.count = -1: must be in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", "2147483648"),
            "count.count = 2147483648: must be in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", "1e300"), "count.count = 1e300: must be in [0, 2147483647]");
  EXPECT_EQ(CountMessage("count", "99999999999999999999999"),
            "count.count = 99999999999999999999999: must be in [0, 2147483647]");
  EXPECT_EQ(CountMessage("positive", "0"), "count.positive = 0: must be in [1, 10000000]");
  EXPECT_EQ(CountMessage("big", "1.0000001e7"),
            "count.big = 1.0000001e7: must be in [1, 10000000]");
  EXPECT_EQ(CountMessage("big", "10000000.5"),
            "count.big = 10000000.5: must be an integer in [1, 10000000]");
}

TEST(ParamsTest, FormatDoubleIsShortestRoundTrip) {
  EXPECT_EQ(FormatDouble(0.1), "0.1");
  EXPECT_EQ(FormatDouble(1e-300), "1e-300");
  EXPECT_EQ(std::stod(FormatDouble(1.0 / 3)), 1.0 / 3);
  EXPECT_EQ(FormatDouble(-std::numeric_limits<double>::infinity()), "-oo");
}

}  // namespace
}  // namespace icp
