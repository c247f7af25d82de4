// The published-vs-measured table: the factor rule, the tally and the
// table's rows and reasons (the claims themselves: claims_test.cc and
// thesis003_claims_test.cc).
#include "paper/comparison.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace icp {
namespace {

TEST(ComparisonTest, WithinFactorIsSymmetricAndRejectsNonPositive) {
  EXPECT_TRUE(WithinFactor(1.5, 1, 1.5));
  EXPECT_TRUE(WithinFactor(1, 1.5, 1.5));
  EXPECT_FALSE(WithinFactor(1.51, 1, 1.5));
  EXPECT_FALSE(WithinFactor(0, 1, 1.5));
  EXPECT_FALSE(WithinFactor(std::numeric_limits<double>::quiet_NaN(), 1, 1.5));
}

TEST(ComparisonTest, TallyCountsEachVerdict) {
  const auto row = [](Verdict v) { return ComparisonRow{"item", "1", "2", "rule", v, ""}; };
  const VerdictTally tally = Tally({row(Verdict::kMatch), row(Verdict::kNoData),
                                    row(Verdict::kDiffers), row(Verdict::kMatch),
                                    row(Verdict::kMatch), row(Verdict::kNoData)});
  EXPECT_EQ(tally.match, 3);
  EXPECT_EQ(tally.differ, 1);
  EXPECT_EQ(tally.no_data, 2);
  EXPECT_EQ(ToString(tally), "Verdicts: 3 match, 1 differ, 2 no data");
  EXPECT_EQ(ToString(Tally({})), "Verdicts: 0 match, 0 differ, 0 no data");
}

TEST(ComparisonTest, TheTableNumbersRowsAndListsReasons) {
  const TextTable t =
      ComparisonTable("T", {{"a", "1", "1", "equal", Verdict::kMatch, ""},
                            {"b", "1", "2", "equal", Verdict::kDiffers, kNotMeasured}});
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"2", "b", "1", "2", "differs"}));
  ASSERT_EQ(t.items.size(), 2u);
  EXPECT_EQ(t.items[0], "1. a: match (rule: equal)");
  EXPECT_EQ(t.items[1], std::string("2. b: differs (rule: equal); ") + kNotMeasured);
}

}  // namespace
}  // namespace icp
