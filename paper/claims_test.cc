// Claims files (paper/claims.h): the parser's errors, the rules, the built-in
// files against the default spec, and paper 000's claims on synthetic runs,
// where every difference carries a measured reason.
#include "paper/claims.h"

#include <gtest/gtest.h>

#include <cmath>

#include <string>
#include <vector>

#include "paper/claim_measures.h"
#include "paper/claims_testing.h"
#include "report/report_testing.h"

namespace icp {
namespace {

using testing::ClaimRow;
using testing::InExperiment;
using testing::MakeRun;

// A claims file of one claim: the lines given, indented under "- ".
std::string OneClaim(const std::string& body) {
  return "paper: test\ntitle: T\nspec: specs/default.yaml\nclaims:\n  - " + body;
}

constexpr char kValid[] =
    "id: a\n    item: A\n    where: Table 1\n    quote: q\n    published: 2\n"
    "    measure: {kind: metric, metric: time_ms, runs: {experiment: table1, algorithm: hc4}}\n"
    "    rule: {within_factor: 1.5}\n    tolerance: because\n"
    "    if_differs: {because: another machine}\n";

std::string ErrorOf(const std::string& text) {
  try {
    ParseClaims(text, "test.yaml");
  } catch (const ClaimsError& e) {
    return e.what();
  }
  return "";
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(ClaimsParseTest, AValidClaimParses) {
  const ClaimsFile f = ParseClaims(OneClaim(kValid), "test.yaml");
  ASSERT_EQ(f.claims.size(), 1u);
  EXPECT_EQ(f.paper, "test");
  EXPECT_EQ(f.claims[0].rule, "within_factor");
  EXPECT_EQ(f.claims[0].published, 2);
  EXPECT_EQ(RuleText(f.claims[0]), "within a factor 1.5 (because)");
}

TEST(ClaimsParseTest, ErrorsNameTheFileTheClaimAndTheProblem) {
  const std::string valid = OneClaim(kValid);
  struct Case {
    std::string text, error;
  };
  const std::vector<Case> cases = {
      {Replace(valid, "quote: q", "quote: q\n    colour: red"), "unknown key 'colour'"},
      {Replace(valid, "    tolerance: because\n", ""), "needs 'tolerance'"},
      {Replace(valid, "kind: metric", "kind: guess"), "unknown measure kind 'guess'"},
      {Replace(valid, "within_factor: 1.5", "roughly: 1.5"), "unknown rule 'roughly'"},
      {Replace(valid, "{because: another machine}", "{explain: luck}"), "unknown explainer 'luck'"},
      {Replace(valid, "{because: another machine}", "{}"), "exactly one of 'explain' and 'because'"},
      {Replace(valid, "    if_differs: {because: another machine}\n", ""), "needs 'if_differs'"},
      {Replace(valid, "published: 2", "published: many"), "within_factor needs a numeric"},
      {Replace(valid, "{experiment: table1, algorithm: hc4}", "{algorithm: hc4}"),
       "needs 'experiment'"},
      {valid + "  - " + kValid, "claim id 'a' given twice"},
      {"paper: p\ntitle: t\nspec: s\nclaims: [", "test.yaml:"},
  };
  for (const Case& c : cases) {
    const std::string error = ErrorOf(c.text);
    EXPECT_NE(error.find(c.error), std::string::npos) << "got: " << error << "\n" << c.text;
    EXPECT_EQ(error.rfind("test.yaml", 0), 0u) << error;
  }
  // An equals or same_text rule needs no tolerance.
  EXPECT_EQ(ErrorOf(Replace(Replace(valid, "within_factor: 1.5", "equals: 2"),
                            "    tolerance: because\n", "")),
            "");
}

Claim RuleClaim(const std::string& rule, std::vector<double> bounds, double published = 2) {
  Claim c;
  c.rule = rule, c.bounds = std::move(bounds), c.published = published;
  return c;
}

Measurement Value(double v) { return {v, "", "", ""}; }

TEST(ClaimsRuleTest, EachRuleDecidesOnItsBounds) {
  EXPECT_TRUE(RuleHolds(RuleClaim("within_factor", {1.5}), Value(3)));
  EXPECT_FALSE(RuleHolds(RuleClaim("within_factor", {1.5}), Value(3.01)));
  EXPECT_TRUE(RuleHolds(RuleClaim("at_least", {200}), Value(200)));
  EXPECT_FALSE(RuleHolds(RuleClaim("at_least", {200}), Value(4.5)));
  EXPECT_TRUE(RuleHolds(RuleClaim("at_most", {1.1}), Value(1.1)));
  EXPECT_FALSE(RuleHolds(RuleClaim("below", {1}), Value(1)));
  EXPECT_TRUE(RuleHolds(RuleClaim("between", {0.8, 1}), Value(0.9)));
  EXPECT_FALSE(RuleHolds(RuleClaim("between", {0.8, 1}), Value(0.4)));
  EXPECT_TRUE(RuleHolds(RuleClaim("equals", {1}), Value(1)));
  EXPECT_FALSE(RuleHolds(RuleClaim("equals", {1}), Value(0.9995)));
  EXPECT_FALSE(RuleHolds(RuleClaim("at_least", {0}), Value(std::nan(""))));
  Claim text = RuleClaim("same_text", {});
  text.published_text = "HC4";
  EXPECT_TRUE(RuleHolds(text, {1, "HC4", "", ""}));
  EXPECT_FALSE(RuleHolds(text, {1, "BC4", "", ""}));
  EXPECT_EQ(RuleText(RuleClaim("between", {0.8, 1})), "between 0.8 and 1");
}

TEST(BuiltInClaimsTest, EveryFileParsesAndEverySelectorIsPlannedByItsSpec) {
  ASSERT_FALSE(BuiltInClaims().empty());
  for (const ClaimsFile& f : BuiltInClaims()) {
    EXPECT_FALSE(f.claims.empty()) << f.source;
    for (const std::string& message : UnplannedSelectors(f, ICPBENCH_TEST_SOURCE_DIR))
      ADD_FAILURE() << message;
  }
  EXPECT_EQ(ClaimsOf("paper000").paper, "paper000");
  EXPECT_THROW(ClaimsOf("paper999"), std::out_of_range);
}

TEST(SelectorTest, MatchesExperimentAlgorithmAndParameters) {
  const RunSelector s = ParseSelector(YAML::Load(
      "{experiment: [window, table1], algorithm: hc4, algorithm_params: {carry: none}, "
      "problem_params: {w: 20}}"));
  RunSpec spec{"hc4", {{"carry", "none"}}, "car-track", {{"w", "20.0"}}, 1};
  EXPECT_TRUE(Selects(s, spec, "window"));
  EXPECT_TRUE(Selects(s, spec, "table1"));
  EXPECT_FALSE(Selects(s, spec, "start"));
  spec.algorithm_params.clear();  // the selector asks exactly carry=none
  EXPECT_FALSE(Selects(s, spec, "window"));
  // A problem parameter left at its default matches the default's value.
  const RunSelector by_default = ParseSelector(YAML::Load(
      "{experiment: window, problem_params: {w: " + ProblemDefaults("car-track")["w"] + "}}"));
  EXPECT_TRUE(Selects(by_default, {"hc4", {}, "car-track", {}, 1}, "window"));
}

// A run whose every step has the given x-y area and GPS box widths.
RunRecord WithArea(RunRecord run, double area, double gps_width = 0) {
  for (StepRecord& s : run.steps) {
    s.area = area;
    if (gps_width > 0)
      for (const char* v : {"x", "y"}) {
        s.properties.push_back({std::string("gps_") + v + "_lo", -gps_width / 2});
        s.properties.push_back({std::string("gps_") + v + "_hi", gps_width / 2});
      }
  }
  run.metrics = ComputeMetrics(run.steps);
  return run;
}

// Table 1's four algorithms over seeds 1..seeds, times in seconds per CSP,
// at window w (the paper's: 20).
std::vector<RunRecord> Table1(double hc4, double bc3, double bc4, double three_b, int seeds = 3,
                              const std::string& w = "20") {
  std::vector<RunRecord> runs;
  for (int seed = 1; seed <= seeds; ++seed)
    for (const auto& [a, t] : std::vector<std::pair<std::string, double>>{
             {"hc4", hc4}, {"bc3", bc3}, {"bc4", bc4}, {"3b-bc4", three_b}})
      runs.push_back(InExperiment(WithArea(MakeRun(a, {}, {{"w", w}}, seed, {t, t}), 16), "table1"));
  return runs;
}

// Another spec's table1 at another window: the claims about the paper's
// w = 20 have no data, rather than a verdict on a setting it never ran.
TEST(Paper000ClaimsTest, ATable1AtAnotherWindowGivesNoDataForTheW20Claims) {
  const std::vector<ComparisonRow> rows =
      EvaluateClaims(ClaimsOf("paper000"), Table1(0.4e-3, 0.8e-3, 0.45e-3, 1.2, 3, "5"));
  for (const char* id : {"table1-hc4-ms", "table1-bc3-ratio", "table1-quickest", "fig4-similar"})
    EXPECT_EQ(ClaimRow(rows, id).verdict, Verdict::kNoData) << id;
  EXPECT_EQ(ClaimRow(rows, "fig3-consistent").verdict, Verdict::kMatch);  // every configuration's boxes
}

TEST(Paper000ClaimsTest, AnEmptyStoreGivesNoDataRowsThatNameTheSpec) {
  const std::vector<ComparisonRow> rows = EvaluateClaims(ClaimsOf("paper000"), {});
  ASSERT_EQ(rows.size(), ClaimsOf("paper000").claims.size());
  for (const ComparisonRow& r : rows) {
    EXPECT_EQ(r.verdict, Verdict::kNoData) << r.id;
    EXPECT_NE(r.reason.find("icpbench run specs/default.yaml"), std::string::npos) << r.reason;
    EXPECT_FALSE(r.quote.empty()) << r.id;
  }
}

TEST(Paper000ClaimsTest, Table1RatiosArePairedBySeedAndDecideTheVerdicts) {
  std::vector<RunRecord> runs = Table1(0.4e-3, 0.8e-3, 0.45e-3, 1.2);
  std::vector<ComparisonRow> rows = EvaluateClaims(ClaimsOf("paper000"), runs);
  EXPECT_EQ(ClaimRow(rows, "table1-bc3-ratio").verdict, Verdict::kMatch);
  EXPECT_NE(ClaimRow(rows, "table1-bc3-ratio").measured.find("2"), std::string::npos);
  EXPECT_EQ(ClaimRow(rows, "table1-3b-ratio").verdict, Verdict::kMatch);  // 3000 vs 2692
  EXPECT_FALSE(ClaimRow(rows, "table1-3b-ratio").note.empty());          // the source's contradiction
  EXPECT_EQ(ClaimRow(rows, "table1-quickest").verdict, Verdict::kMatch);
  EXPECT_EQ(ClaimRow(rows, "table1-hc4-ms").verdict, Verdict::kMatch);  // 0.4 against 0.52
  EXPECT_EQ(ClaimRow(rows, "table1-3b-not-real-time").verdict, Verdict::kMatch);  // 1200 ms
  EXPECT_EQ(ClaimRow(rows, "fig3-consistent").verdict, Verdict::kMatch);
  EXPECT_EQ(ClaimRow(rows, "fig4-similar").verdict, Verdict::kMatch);
  // Equal areas: 3B-BC4 is not better; 2.5 times smaller is not "slightly".
  EXPECT_EQ(ClaimRow(rows, "fig4-3b-slightly-better").verdict, Verdict::kDiffers);
  for (RunRecord& r : runs)
    if (r.spec.algorithm == "3b-bc4") r = WithArea(std::move(r), 6.4);
  const ComparisonRow better = ClaimRow(EvaluateClaims(ClaimsOf("paper000"), runs), "fig4-3b-slightly-better");
  EXPECT_EQ(better.verdict, Verdict::kDiffers);
  EXPECT_NE(better.reason.find("measured mean widths, 3B-BC4 against HC4: x 2 against 2;"),
            std::string::npos)
      << better.reason;

  // BC3 50x HC4; 3B-BC4 fast enough for 5 Hz; one box misses the truth.
  runs = Table1(0.02e-3, 1e-3, 0.02e-3, 4e-3);
  for (RunRecord& r : runs) {
    if (r.spec.algorithm == "hc4") r.properties = {{"revise_calls", std::int64_t{480}}};
    if (r.spec.algorithm == "bc3")
      r.properties = {{"revise_calls", std::int64_t{560}},
                      {"newton_steps", std::int64_t{320}},
                      {"bisections", std::int64_t{80}}};
    if (r.spec.algorithm == "3b-bc4")
      r.properties = {{"inner_calls", std::int64_t{600}}, {"revise_calls", std::int64_t{48000}}};
  }
  runs[0].steps[1].contained = 0;
  runs[0].metrics = ComputeMetrics(runs[0].steps);
  rows = EvaluateClaims(ClaimsOf("paper000"), runs);
  const ComparisonRow& bc3 = ClaimRow(rows, "table1-bc3-ratio");
  EXPECT_EQ(bc3.verdict, Verdict::kDiffers);
  EXPECT_NE(bc3.reason.find("BC3 revised 280 constraints (HC4 240)"), std::string::npos)
      << bc3.reason;
  EXPECT_NE(bc3.reason.find("160 Newton steps and 40 bisections"), std::string::npos);
  const ComparisonRow& real_time = ClaimRow(rows, "table1-3b-not-real-time");
  EXPECT_EQ(real_time.verdict, Verdict::kDiffers);
  EXPECT_NE(real_time.reason.find("ran 300 inner contractions (shaving trials) with 24000 "
                                  "revisions, 100x HC4's, and a revision cost 2x one of HC4's"),
            std::string::npos)
      << real_time.reason;
  const ComparisonRow& consistent = ClaimRow(rows, "fig3-consistent");
  EXPECT_EQ(consistent.verdict, Verdict::kDiffers);  // one step of one seed is enough
  EXPECT_NE(consistent.measured.find("lowest 0.8333"), std::string::npos) << consistent.measured;
  EXPECT_EQ(ClaimRow(rows, "table1-hc4-ms").verdict, Verdict::kDiffers);
  EXPECT_NE(ClaimRow(rows, "table1-hc4-ms").reason.find("by construction"), std::string::npos);
}

TEST(Paper000ClaimsTest, FlatCarriedWindowsDifferWithTheMemorylessFallAsTheirReason) {
  auto window = [](const std::string& carry, double w, double area, int seed) {
    ParamMap params;
    if (!carry.empty()) params["carry"] = carry;
    return InExperiment(WithArea(MakeRun("hc4", params,
                                         {{"w", FormatNumber(w)}, {"steps", "1000"}}, seed,
                                         {1e-5 * w, 1e-5 * w}),
                                 area),
                        "window");
  };
  std::vector<RunRecord> runs;
  for (int seed = 1; seed <= 3; ++seed)
    for (const auto& [carry, w, area] : std::vector<std::tuple<std::string, double, double>>{
             {"", 1, 16}, {"", 20, 16}, {"", 200, 16},
             {"none", 1, 21.3}, {"none", 20, 17.8}, {"none", 200, 17.1}})
      runs.push_back(window(carry, w, area, seed));
  const std::vector<ComparisonRow> rows = EvaluateClaims(ClaimsOf("paper000"), runs);
  const ComparisonRow& fall = ClaimRow(rows, "fig2-fall-1-20");
  EXPECT_EQ(fall.verdict, Verdict::kDiffers);
  EXPECT_NE(fall.measured.find("0 %"), std::string::npos) << fall.measured;
  EXPECT_NE(fall.reason.find("16.43 %"), std::string::npos) << fall.reason;  // 1 - 17.8 / 21.3
  EXPECT_NE(fall.reason.find("which the rule accepts"), std::string::npos) << fall.reason;
  EXPECT_NE(fall.reason.find("eq. 14"), std::string::npos);
  const ComparisonRow& further = ClaimRow(rows, "fig2-fall-20-200");
  EXPECT_EQ(further.verdict, Verdict::kDiffers);  // 3.9 % memoryless
  EXPECT_NE(further.reason.find("which the rule accepts"), std::string::npos) << further.reason;
}

// Whatever the runs say, a claim that differs gives a reason other than
// "not yet measured": every claim here is made to differ.
TEST(Paper000ClaimsTest, EveryDifferenceHasAReason) {
  std::vector<RunRecord> runs = Table1(1e-3, 1e-3, 1e-3, 1e-3);
  for (RunRecord& r : runs) {
    r = WithArea(std::move(r), r.spec.algorithm == "hc4" ? 2000 : 40, 1);
    r.properties = {{"revise_calls", std::int64_t{10}},
                    {"newton_steps", std::int64_t{1}},
                    {"bisections", std::int64_t{1}},
                    {"inner_calls", std::int64_t{1}}};
  }
  for (int seed = 1; seed <= 3; ++seed)
    for (const char* carry : {"", "none"})
      for (double w : {1, 20, 50, 200}) {
        ParamMap params;
        if (*carry) params["carry"] = carry;
        for (const char* a : {"hc4", "bc4"})
          runs.push_back(InExperiment(
              WithArea(MakeRun(a, params, {{"w", FormatNumber(w)}, {"steps", "1000"}}, seed,
                               {w == 50 ? 1 : 1e-5, 1e-5}),
                       10 + w),
              "window"));
      }
  int differ = 0;
  for (const ComparisonRow& r : EvaluateClaims(ClaimsOf("paper000"), runs)) {
    if (r.verdict != Verdict::kDiffers) continue;
    ++differ;
    EXPECT_EQ(r.reason.find(kNotMeasured), std::string::npos) << r.id << ": " << r.reason;
    EXPECT_FALSE(r.reason.empty()) << r.id;
  }
  EXPECT_GE(differ, 8);
}

// A store made with `record: runs` keeps run metrics but no steps: a claim
// on the area still gets its verdict, and an explainer that reads steps
// says that is why it cannot explain.
TEST(Paper000ClaimsTest, AnExplainerWithoutStepsSaysSo) {
  std::vector<RunRecord> runs = Table1(1e-3, 1e-3, 1e-3, 1e-3);
  for (RunRecord& r : runs) {
    r = WithArea(std::move(r), 2000, 1);
    r.steps.clear();  // what record: runs stores; metrics stay
  }
  const ComparisonRow r = ClaimRow(EvaluateClaims(ClaimsOf("paper000"), runs), "fig2-area-w20");
  ASSERT_EQ(r.verdict, Verdict::kDiffers) << r.measured;
  EXPECT_NE(r.reason.find("record: runs"), std::string::npos) << r.reason;
}

TEST(Paper004ClaimsTest, ConsistencyIsJudgedOnEveryStep) {
  std::vector<RunRecord> runs = {InExperiment(MakeRun("hc4", {}, {}, 1, {1e-5, 1e-5}), "table1")};
  EXPECT_EQ(ClaimRow(EvaluateClaims(ClaimsOf("paper004"), runs), "eq31-consistent").verdict,
            Verdict::kMatch);
  runs[0].steps[1].contained = 0;
  runs[0].metrics = ComputeMetrics(runs[0].steps);
  const ComparisonRow r = ClaimRow(EvaluateClaims(ClaimsOf("paper004"), runs), "eq31-consistent");
  EXPECT_EQ(r.verdict, Verdict::kDiffers);
  EXPECT_NE(r.measured.find("lowest 0.5"), std::string::npos) << r.measured;
  EXPECT_FALSE(r.reason.empty());
  // Post-localization needs the window sweep: no data, naming the spec.
  const ComparisonRow pl = ClaimRow(EvaluateClaims(ClaimsOf("paper004"), runs), "pl-narrower");
  EXPECT_EQ(pl.verdict, Verdict::kNoData);
  EXPECT_NE(pl.reason.find("experiment window"), std::string::npos) << pl.reason;
}

// Runs without a truth give no consistency: no data, not a difference (it
// had read "differs: a box that loses the truth is unsound").
TEST(Paper004ClaimsTest, RunsWithoutATruthAreNoData) {
  std::vector<RunRecord> runs = {InExperiment(MakeRun("hc4", {}, {}, 1, {1e-5, 1e-5}), "table1")};
  for (StepRecord& s : runs[0].steps) s.contained = -1;
  runs[0].metrics = ComputeMetrics(runs[0].steps);
  ASSERT_TRUE(std::isnan(runs[0].metrics.consistency_rate));
  const ComparisonRow r = ClaimRow(EvaluateClaims(ClaimsOf("paper004"), runs), "eq31-consistent");
  EXPECT_EQ(r.verdict, Verdict::kNoData) << r.measured << ": " << r.reason;
  EXPECT_NE(r.reason.find("give no value"), std::string::npos) << r.reason;
}

}  // namespace
}  // namespace icp
