#include "core/params.h"

#include <gtest/gtest.h>

#include <limits>

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
  EXPECT_EQ(message({{"slices", "2.5"}}), "example.slices = 2.5: not an integer");
  EXPECT_EQ(message({{"slices", "0"}}), "example.slices = 0: must be in [1, 1000]");
  // "no" is not read as true (a habit of lenient parsers, see STYLE.md).
  EXPECT_EQ(message({{"verbose", "no"}}), "example.verbose = no: must be true or false");
  EXPECT_EQ(message({{"mode", "medium"}}), "example.mode = medium: must be one of fast|slow");
  EXPECT_EQ(message({{"inner.ratio", "2"}}), "example.inner.ratio = 2: must be in [0, 1)");
  EXPECT_EQ(message({{"speed", "1"}}),
            "unknown parameter 'speed' for example (known: ratio, slices, verbose, mode, "
            "inner.ratio)");
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

TEST(ParamsTest, FormatDoubleIsShortestRoundTrip) {
  EXPECT_EQ(FormatDouble(0.1), "0.1");
  EXPECT_EQ(FormatDouble(1e-300), "1e-300");
  EXPECT_EQ(std::stod(FormatDouble(1.0 / 3)), 1.0 / 3);
  EXPECT_EQ(FormatDouble(-std::numeric_limits<double>::infinity()), "-oo");
}

}  // namespace
}  // namespace icp
