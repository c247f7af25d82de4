// The median over runs with its order-statistic interval, its rounding, the
// column units and the long cells moved under a TeX table.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "report/report.h"
#include "report/report_testing.h"

namespace icp {
namespace {

using testing::MakeRun;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(MedianWithIntervalTest, BelowSixValuesNoIntervalReaches95Percent) {
  const MedianInterval m = MedianWithInterval({3, 1, 2, 5, 4});
  EXPECT_EQ(m.n, 5);
  EXPECT_DOUBLE_EQ(m.median, 3);
  // [min, max] of 5 covers the median with 1 - 2/32 = 93.75 % only.
  EXPECT_TRUE(std::isnan(m.lo));
  EXPECT_TRUE(std::isnan(m.hi));
  EXPECT_TRUE(std::isnan(m.coverage));
}

TEST(MedianWithIntervalTest, SixValuesGiveMinAndMaxAt96Point9Percent) {
  const MedianInterval m = MedianWithInterval({6, 1, 5, 2, 4, 3});
  EXPECT_EQ(m.n, 6);
  EXPECT_DOUBLE_EQ(m.median, 3.5);
  EXPECT_DOUBLE_EQ(m.lo, 1);
  EXPECT_DOUBLE_EQ(m.hi, 6);
  EXPECT_NEAR(m.coverage, 1 - 2.0 / 64, 1e-12);
}

TEST(MedianWithIntervalTest, MoreValuesNarrowToInnerOrderStatistics) {
  // n = 9: k = 2 covers 1 - 2 (1 + 9) / 512 = 96.1 %, k = 3 only 82.0 %.
  const MedianInterval nine = MedianWithInterval({9, 8, 7, 6, 5, 4, 3, 2, 1});
  EXPECT_DOUBLE_EQ(nine.lo, 2);
  EXPECT_DOUBLE_EQ(nine.hi, 8);
  EXPECT_NEAR(nine.coverage, 1 - 2 * 10.0 / 512, 1e-12);
  // n = 100: the textbook pair is x_(40), x_(61) (coverage 96.5 %).
  std::vector<double> hundred;
  for (int i = 1; i <= 100; ++i) hundred.push_back(i);
  const MedianInterval h = MedianWithInterval(hundred);
  EXPECT_DOUBLE_EQ(h.lo, 40);
  EXPECT_DOUBLE_EQ(h.hi, 61);
  EXPECT_GE(h.coverage, 0.95);
  EXPECT_LT(h.coverage, 0.97);
}

TEST(MedianWithIntervalTest, NaNValuesAreLeftOut) {
  const MedianInterval m = MedianWithInterval({kNaN, 2, kNaN});
  EXPECT_EQ(m.n, 1);
  EXPECT_DOUBLE_EQ(m.median, 2);
  EXPECT_TRUE(std::isnan(MedianWithInterval({}).median));
}

TEST(FormatWithIntervalTest, RoundsToTheLeadingDigitOfTheHalfWidth) {
  MedianInterval m;
  m.median = 18.2234, m.lo = 17.91, m.hi = 18.62;  // half-width 0.355: tenths
  EXPECT_EQ(FormatWithInterval(m), "18.2 [17.9, 18.7]");  // bounds rounded outward
  m.median = 0.07123, m.lo = 0.07004, m.hi = 0.07311;  // 0.00154: leading 1, one more digit
  EXPECT_EQ(FormatWithInterval(m), "0.0712 [0.0700, 0.0732]");
  m.median = 1412, m.lo = 1310, m.hi = 1540;  // 115: tens
  EXPECT_EQ(FormatWithInterval(m), "1410 [1310, 1540]");
  m.median = 1.8223e-5, m.lo = 1.791e-5, m.hi = 1.862e-5;  // seconds shown in µs
  EXPECT_EQ(FormatWithInterval(m, 1e6), "18.2 [17.9, 18.7]");
  m.median = -0.04, m.lo = -0.3, m.hi = 0.2;  // no "-0"
  EXPECT_EQ(FormatWithInterval(m), "0.0 [-0.3, 0.2]");
}

TEST(FormatWithIntervalTest, WithoutAnIntervalTheMedianAlone) {
  MedianInterval m;
  EXPECT_EQ(FormatWithInterval(m), "—");
  m.median = 0.0177;
  EXPECT_EQ(FormatWithInterval(m), "0.0177");
  m.lo = m.hi = 0.0177;  // every run agrees
  EXPECT_EQ(FormatWithInterval(m, 1e3), "17.7");
}

TEST(TimeUnitTest, OneUnitPerColumnFromTheMedianMagnitude) {
  EXPECT_EQ(TimeUnit({7.7e-7, 1.8e-5, 3.1e-4}).name, "µs");  // not 7.677e-04 ms
  EXPECT_EQ(TimeUnit({0.0018, 0.0044, 0.3}).name, "ms");
  EXPECT_EQ(TimeUnit({2.5, 4200}).name, "s");
  EXPECT_EQ(TimeUnit({3e-10, 5e-10}).name, "ns");
  EXPECT_EQ(TimeUnit({0, kNaN}).name, "µs");
  EXPECT_DOUBLE_EQ(TimeUnit({0.0018}).scale, 1e3);
}

TEST(RunMedianTest, MediansOverRunsAndRatiosPairedBySeed) {
  std::vector<RunRecord> hc4, bc4;
  for (int seed = 1; seed <= 6; ++seed) {
    hc4.push_back(MakeRun("hc4", {}, {}, seed, {seed * 1e-5}));
    bc4.push_back(MakeRun("bc4", {}, {}, seed, {seed * 2e-5}));
  }
  bc4.push_back(MakeRun("bc4", {}, {}, 7, {1}));  // no HC4 run of seed 7 to pair with
  std::vector<const RunRecord*> h, b;
  for (const RunRecord& r : hc4) h.push_back(&r);
  for (const RunRecord& r : bc4) b.push_back(&r);
  const GroupSummary hg = Summarise(h), bg = Summarise(b);
  const MedianInterval time = RunMedian(hg, RunMeanTime);
  EXPECT_EQ(time.n, 6);
  EXPECT_DOUBLE_EQ(time.median, 3.5e-5);
  EXPECT_DOUBLE_EQ(time.lo, 1e-5);
  EXPECT_DOUBLE_EQ(time.hi, 6e-5);
  // Every seed's BC4 takes twice its HC4: the ratio is 2 exactly, though
  // the times themselves spread sixfold.
  const MedianInterval ratio = PairedRatio(bg, hg, RunMeanTime);
  EXPECT_EQ(ratio.n, 6);
  EXPECT_DOUBLE_EQ(ratio.median, 2);
  EXPECT_DOUBLE_EQ(ratio.lo, 2);
  EXPECT_DOUBLE_EQ(ratio.hi, 2);
  EXPECT_EQ(FormatWithInterval(ratio), "2");
}

TEST(LongCellsTest, MovedUnderTheTableWithSharedMarkers) {
  TextTable t;
  t.title = "t";
  t.headers = {"configuration", "value"};
  t.numeric = {false, true};
  const std::string long_text = "q-relaxed {auto_q=false,epsilon=2,mode=pave,outlier_share=0.3}";
  t.rows = {{long_text, "1"}, {"hc4", "2"}, {long_text, "3"}, {"particle filter, 600 particles, Matlab", "4"}};
  t.notes = {"A note."};
  const TextTable moved = WithLongCellsAsNotes(t, 20);
  EXPECT_EQ(moved.rows[0][0], "(a)");
  EXPECT_EQ(moved.rows[1][0], "hc4");
  EXPECT_EQ(moved.rows[2][0], "(a)");
  EXPECT_EQ(moved.rows[3][0], "(b)");
  ASSERT_EQ(moved.notes.size(), 3u);
  EXPECT_EQ(moved.notes[0], "(a) " + long_text);
  EXPECT_EQ(moved.notes[2], "A note.");
  // Numeric cells stay, however long; short text stays in TeX too.
  t.rows = {{"hc4", "18.2 [17.9, 18.7] and more text than twenty"}};
  EXPECT_EQ(WithLongCellsAsNotes(t, 20).rows[0][1], t.rows[0][1]);
  const std::string tex = TexTable(t);
  EXPECT_NE(tex.find("hc4 & 18.2"), std::string::npos) << tex;
  // Characters, not bytes, are counted: 36 "²" fit in kMaxTexCellChars.
  std::string squares;
  for (int i = 0; i < 36; ++i) squares += "²";
  t.rows = {{squares, "1"}};
  EXPECT_EQ(WithLongCellsAsNotes(t, kMaxTexCellChars).rows[0][0], squares);
}

TEST(LongCellsTest, WrappedColumnsKeepTheirCellsAndBreakAfterCommas) {
  TextTable t;
  t.title = "t";
  t.headers = {"configuration", "value"};
  t.numeric = {false, true};
  t.wrap_cm = {4.5, 0};
  const std::string long_text = "q-relaxed {auto_q=false,epsilon=2,mode=pave,outlier_share=0.3}";
  t.rows = {{long_text, "1"}};
  EXPECT_EQ(WithLongCellsAsNotes(t, 20).rows[0][0], long_text);
  const std::string tex = TexTable(t);
  EXPECT_NE(tex.find("\\begin{tabular}{>{\\raggedright\\arraybackslash}p{4.5cm}r}"),
            std::string::npos)
      << tex;
  EXPECT_NE(tex.find("\\{auto\\_q=false,\\allowbreak{}epsilon=2,"), std::string::npos) << tex;
  EXPECT_EQ(tex.find("(a)"), std::string::npos) << tex;
}

}  // namespace
}  // namespace icp
