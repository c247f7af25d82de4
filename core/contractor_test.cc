#include "core/contractor.h"
#include "core/contractor_algebra.h"

#include <gtest/gtest.h>

#include <limits>
#include <thread>
#include <vector>

namespace icp {
namespace {

// Halves the upper bound of component i each call (a slowly converging
// contractor, as propagation on x = y / 2 is).
class HalveUpper : public Contractor {
 public:
  explicit HalveUpper(std::size_t i) : i_(i) {}
  std::string_view Name() const override { return "halve"; }
  ContractSummary Contract(Box& box, ContractContext&) override {
    ContractSummary s;
    s.work.revise_calls = 1;
    box[i_] = Interval(box[i_].lo(), box[i_].lo() + box[i_].Width() / 2);
    s.status = ContractStatus::kContracted;
    return s;
  }

 private:
  std::size_t i_;
};

class MakeEmpty : public Contractor {
 public:
  std::string_view Name() const override { return "empty"; }
  ContractSummary Contract(Box& box, ContractContext&) override {
    box.SetEmpty();
    return {ContractStatus::kEmpty, "", {}};
  }
};

// Records whether it was told that every variable changed.
class RecordAllChanged : public Contractor {
 public:
  explicit RecordAllChanged(std::vector<bool>* seen) : seen_(seen) {}
  std::string_view Name() const override { return "record"; }
  ContractSummary Contract(Box&, ContractContext& context) override {
    seen_->push_back(context.all_changed());
    return {};
  }

 private:
  std::vector<bool>* seen_;
};

TEST(ContractorTest, AFreshContextSaysEveryVariableChanged) {
  ContractContext context;
  EXPECT_TRUE(context.all_changed());
  const int vars[] = {3, 1};
  context.SetChanged(vars);
  EXPECT_FALSE(context.all_changed());
  EXPECT_EQ(context.changed(), (std::vector<int>{3, 1}));
}

// The later parts of a sequence see what the earlier ones changed as well.
TEST(ContractorTest, SequenceTellsOnlyItsFirstPartWhatChanged) {
  std::vector<bool> seen;
  SharedContractors parts;
  parts.push_back(std::make_unique<RecordAllChanged>(&seen));
  parts.push_back(std::make_unique<RecordAllChanged>(&seen));
  SequenceContractor seq(std::move(parts));
  Box box{{0, 1}};
  ContractContext context;
  const int vars[] = {0};
  context.SetChanged(vars);
  seq.Contract(box, context);
  EXPECT_EQ(seen, (std::vector<bool>{false, true}));
}

TEST(ContractorTest, SequenceAppliesEachPartOnceAndAddsTheirWork) {
  SharedContractors parts;
  parts.push_back(std::make_unique<HalveUpper>(0));
  parts.push_back(std::make_unique<HalveUpper>(1));
  SequenceContractor seq(std::move(parts));
  Box box{{0, 8}, {0, 4}};
  ContractContext context;
  ContractSummary s = seq.Contract(box, context);
  EXPECT_EQ(s.status, ContractStatus::kContracted);
  EXPECT_EQ(s.work.revise_calls, 2);
  EXPECT_EQ(box[0], Interval(0, 4));
  EXPECT_EQ(box[1], Interval(0, 2));
}

TEST(ContractorTest, SequenceStopsAtAnEmptyBox) {
  SharedContractors parts;
  parts.push_back(std::make_unique<MakeEmpty>());
  parts.push_back(std::make_unique<HalveUpper>(0));
  SequenceContractor seq(std::move(parts));
  Box box{{0, 8}};
  ContractContext context;
  EXPECT_EQ(seq.Contract(box, context).status, ContractStatus::kEmpty);
  EXPECT_TRUE(box.IsEmpty());
}

TEST(ContractorTest, FixpointRepeatsUntilTheRatio) {
  // Each call removes half of the width. With ratio 0.6 that is not enough
  // to go on, so one call; with ratio 0.4 it goes on to the iteration bound.
  Box a{{0, 1}};
  FixpointContractor loose(std::make_unique<HalveUpper>(0), 0.6, 100);
  ContractContext context;
  ContractSummary s = loose.Contract(a, context);
  EXPECT_EQ(s.work.revise_calls, 1);
  Box b{{0, 1}};
  FixpointContractor tight(std::make_unique<HalveUpper>(0), 0.4, 10);
  s = tight.Contract(b, context);
  EXPECT_EQ(s.work.revise_calls, 10);
  EXPECT_EQ(b[0], Interval(0, 1.0 / 1024));
  EXPECT_EQ(s.status, ContractStatus::kContracted);
}

TEST(ContractorTest, StopConditionHonoursDeadlineAndCancelFlag) {
  EXPECT_FALSE(StopCondition().ShouldStop());
  StopCondition soon = StopCondition::After(std::chrono::milliseconds(1));
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_TRUE(soon.ShouldStop());
  std::atomic<bool> cancel{false};
  StopCondition flag;
  flag.WithCancelFlag(&cancel);
  EXPECT_FALSE(flag.ShouldStop());
  cancel = true;
  EXPECT_TRUE(flag.ShouldStop());
}

// timeout_s: inf (or 1e10) once overflowed the deadline into the past.
TEST(ContractorTest, StopConditionWithAHugeBudgetNeverStops) {
  for (double s : {std::numeric_limits<double>::infinity(), 1e10, 1e300})
    EXPECT_FALSE(StopCondition::After(std::chrono::duration<double>(s)).ShouldStop()) << s;
  EXPECT_TRUE(StopCondition::After(std::chrono::duration<double>(-1)).ShouldStop());
}

TEST(ContractorTest, ShrankByMoreThanUsesRelativeWidth) {
  EXPECT_TRUE(ShrankByMoreThan(Interval(0, 1), Interval(0, 0.5), 0.1));
  EXPECT_FALSE(ShrankByMoreThan(Interval(0, 1), Interval(0, 0.95), 0.1));
  EXPECT_TRUE(ShrankByMoreThan(Interval(), Interval(0, 1e300), 0.1));  // became bounded
  EXPECT_FALSE(ShrankByMoreThan(Interval(), Interval(0, kInf), 0.1));
  EXPECT_TRUE(ShrankByMoreThan(Interval(0, 1), Interval::Empty(), 0.1));
}

}  // namespace
}  // namespace icp
