#include "algorithms/three_b/three_b.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algorithms/hc3/hc3.h"
#include "algorithms/registry.h"
#include "problems/chain/chain.h"

namespace icp {
namespace {

Box RunAlgorithm(const std::string& name, const ConstraintSystem& csp, const ParamMap& params = {}) {
  Box box = csp.domains();
  ContractContext context;
  FindAlgorithm(name).contractor(params, csp)->Contract(box, context);
  return box;
}

// Paper 000 §3.5: x + y = 0, x - y = 0 on [-2,2]^2, which 3B contracts to
// [0,0]^2.
ConstraintSystem Paper000Example() {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 2});
  Expr y = csp.AddVariable("y", {-2, 2});
  csp.AddConstraint(x + y, Relation::kEq, csp.Constant(0));
  csp.AddConstraint(x - y, Relation::kEq, csp.Constant(0));
  return csp;
}

TEST(ThreeBTest, Paper000Example) {
  const ConstraintSystem csp = Paper000Example();
  for (const std::string name : {"3b-bc4", "3b-hc4"}) {
    Box box = RunAlgorithm(name, csp);
    EXPECT_TRUE(box.Contains({0, 0})) << name;
    EXPECT_LE(box[0].Width(), 1e-6) << name;
    EXPECT_LE(box[1].Width(), 1e-6) << name;
  }
}

TEST(ThreeBTest, ShavesTheDependencyExampleWithBC4) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {-2, 4});
  Expr y = csp.AddVariable("y", {-1, 1});
  csp.AddConstraint(x * x + Sqr(y), Relation::kEq, csp.Constant(2));
  Box box = RunAlgorithm("3b-bc4", csp);
  EXPECT_GE(box[0].hi(), std::sqrt(2.0));
  EXPECT_LT(box[0].hi(), std::sqrt(2.0) + 1e-4);
}

TEST(ThreeBTest, DetectsInconsistencyThatNoSingleConstraintShows) {
  // x + y = 1, x - y = 0, x in [0, 0.4]: each constraint alone is
  // satisfiable on the box, together they force x = 0.5.
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 0.4});
  Expr y = csp.AddVariable("y", {0, 1});
  csp.AddConstraint(x + y, Relation::kEq, csp.Constant(1));
  csp.AddConstraint(x - y, Relation::kEq, csp.Constant(0));
  EXPECT_TRUE(RunAlgorithm("3b-hc4", csp).IsEmpty());
}

TEST(ThreeBTest, InnerParametersAreNestedAndValidated) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", {0, 1});
  csp.AddConstraint(x, Relation::kEq, csp.Constant(0.5));
  const AlgorithmInfo& info = FindAlgorithm("3b-bc4");
  EXPECT_NO_THROW(info.contractor({{"slices", "20"}, {"inner.epsilon", "1e-9"}}, csp));
  EXPECT_THROW(info.contractor({{"inner.epsilon", "2"}}, csp), ParamError);
  EXPECT_THROW(info.contractor({{"slices", "0"}}, csp), ParamError);
  bool listed = false;
  for (const ParamInfo& p : info.params(info.name)) listed |= p.name == "inner.max_bisections";
  EXPECT_TRUE(listed);
}

// Contracts with HC4 and records which variables each call was told changed
// ({-1} for all of them).
class RecordingHC4 : public Contractor {
 public:
  RecordingHC4(const ConstraintSystem& csp, std::vector<std::vector<int>>* told)
      : hc4_(std::make_shared<CompiledSystem>(csp), HC4Params()), told_(told) {}
  std::string_view Name() const override { return "recording-hc4"; }
  ContractSummary Contract(Box& box, ContractContext& context) override {
    told_->push_back(context.all_changed() ? std::vector<int>{-1} : context.changed());
    return hc4_.Contract(box, context);
  }

 private:
  HC4Contractor hc4_;
  std::vector<std::vector<int>>* told_;
};

// The inner contractor is any Contractor, told through the context which
// variables changed: only the shaved one for a cold trial and a spread, the
// shaved one among others for a warm start; wrapping HC4 changes nothing in
// the result.
TEST(ThreeBTest, TellsAnyInnerContractorWhichVariablesChanged) {
  ChainParams p;
  p.w = 4;
  Step step = MakeChainStep(p, 1);
  for (bool warm_start : {false, true}) {
    SCOPED_TRACE(warm_start ? "warm starts" : "cold trials");
    std::vector<std::vector<int>> told;
    ShavingParams params;
    params.warm_start = warm_start;
    ThreeBContractor three_b("3b-recording",
                             std::make_unique<RecordingHC4>(step.views.csp->csp, &told), params);
    Box box = step.views.csp->csp.domains();
    ContractContext context;
    ContractSummary s = three_b.Contract(box, context);
    EXPECT_EQ(box, RunAlgorithm("3b-hc4", step.views.csp->csp,
                                {{"warm_start", warm_start ? "true" : "false"}}));
    ASSERT_EQ(static_cast<std::int64_t>(told.size()), s.work.inner_calls);
    EXPECT_EQ(told[0], std::vector<int>{-1});
    std::vector<char> shaved(box.size(), 0);
    int several = 0;
    for (std::size_t k = 1; k < told.size(); ++k) {
      ASSERT_FALSE(told[k].empty()) << "call " << k;
      for (int v : told[k]) {
        ASSERT_TRUE(v >= 0 && v < static_cast<int>(box.size())) << "call " << k;
      }
      if (!warm_start) {
        ASSERT_EQ(told[k].size(), 1u) << "call " << k;
      }
      several += told[k].size() > 1;
      for (int v : told[k]) shaved[v] = 1;
    }
    EXPECT_EQ(std::count(shaved.begin(), shaved.end(), 1), static_cast<int>(box.size()));
    if (warm_start) {
      EXPECT_GT(several, 0);
    }
  }
}

// An inner contractor that ignores the changed variables (HC3 starts afresh at
// every call) works too, only slower.
TEST(ThreeBTest, ShavesWithHC3AsInnerContractor) {
  const ConstraintSystem csp = Paper000Example();
  ThreeBContractor three_b("3b-hc3", std::make_unique<HC3Contractor>(csp, HC3Params()),
                           ShavingParams());
  Box box = csp.domains();
  ContractContext context;
  EXPECT_EQ(three_b.Contract(box, context).status, ContractStatus::kContracted);
  EXPECT_TRUE(box.Contains({0, 0}));
  EXPECT_LE(box[0].Width(), 1e-6);
  EXPECT_LE(box[1].Width(), 1e-6);
}

// 3B contracts the chain windows at least as much as BC4 and keeps the truth;
// with the heading unknown it also narrows the start heading.
TEST(ThreeBTest, TighterThanBC4OnChainWindowsAndSound) {
  for (std::uint64_t seed = 0; seed < 3; ++seed) {
    ChainParams p;
    p.w = 6;
    Step step = MakeChainStep(p, seed);
    Box three_b = RunAlgorithm("3b-bc4", step.views.csp->csp);
    Box bc4 = RunAlgorithm("bc4", step.views.csp->csp);
    ASSERT_TRUE(three_b.Contains(step.csp_truth)) << "seed " << seed;
    EXPECT_TRUE(three_b.IsSubsetOf(bc4)) << "seed " << seed;
  }
}

// Warm starts (a trial starting from the same bound's previous trial) keep
// the truth, save most of the later rounds' revisions, and on these car-track
// windows give the boxes of cold trials bit for bit (the golden drive pins
// the same for a whole 300-step run: tests/car_track_golden_test.cc).
TEST(ThreeBTest, WarmStartsKeepTheBoxesOfColdTrialsWithFewerRevisions) {
  for (bool heading_known : {false, true}) {
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
      ChainParams p;
      p.heading_known = heading_known;
      Step step = MakeChainStep(p, seed);
      const ConstraintSystem& csp = step.views.csp->csp;
      const AlgorithmInfo& info = FindAlgorithm("3b-bc4");
      Box warm = csp.domains(), cold = csp.domains();
      ContractContext warm_context, cold_context;
      const ContractSummary w = info.contractor({}, csp)->Contract(warm, warm_context);
      const ContractSummary c =
          info.contractor({{"warm_start", "false"}}, csp)->Contract(cold, cold_context);
      SCOPED_TRACE(testing::Message() << "seed " << seed << ", heading known " << heading_known);
      ASSERT_TRUE(warm.Contains(step.csp_truth));
      ASSERT_TRUE(cold.Contains(step.csp_truth));
      EXPECT_EQ(warm, cold);
      EXPECT_EQ(w.work.inner_calls, c.work.inner_calls);
      EXPECT_LT(w.work.revise_calls, c.work.revise_calls);
    }
  }
}

}  // namespace
}  // namespace icp
