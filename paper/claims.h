// Published claims as data (DESIGN.md, "Published claims are data"): each
// paper's claims live in experiments/<paper>/claims.yaml, written before the
// runs are read, and are evaluated here against a store into the rows of the
// paper's "published vs measured" table. A claim is
//
//   - id: table1-bc3-ratio            # unique in its file
//     item: "Table 1: BC3 / HC4"      # the row's name
//     where: "Table 1"                # where in the paper
//     quote: "BC3 is twice slower than HC4 and BC4."
//     published: 1.96                 # a number, or a text (same_text rules)
//     published_text: "1.02 / 0.52 ms"   # optional: how the row shows it
//     measure: {kind: ratio, metric: time_ms, runs: {...}, of: {...}}
//     rule: {within_factor: 1.5}
//     tolerance: "ratios cancel the machine; 1.5 allows another implementation"
//     if_differs: {explain: bc3_work}   # or {because: "..."}: by construction
//     note: "..."                       # optional: e.g. where the source contradicts itself
//     spec: specs/marina.yaml           # optional: the spec making this claim's runs,
//                                       # when not the file's
//
// Rules: within_factor F (|log(m/p)| <= log F; both positive), at_least X,
// at_most X, below X, between [lo, hi], equals X, same_text (the measured
// text equals the published one). Every rule but same_text and equals needs
// `tolerance`, the reason for its number. A claim that can differ names how
// the difference is explained: `explain` (a function that measures the
// reason from the store) or `because` (a difference by construction: another
// machine, implementation or data set).
//
// Runs are chosen by selectors: {experiment: NAME or [NAMES], algorithm,
// algorithm_params: {...} (exactly these non-default parameters; none: the
// defaults), problem, problem_params: {...} (at least these)}. A run two
// experiments plan is stored under the first (ExperimentOf), so a selector
// lists both where that matters.
#ifndef ICPBENCH_PAPER_CLAIMS_H_
#define ICPBENCH_PAPER_CLAIMS_H_

#include <yaml-cpp/yaml.h>

#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "harness/run_record.h"
#include "harness/spec.h"
#include "paper/comparison.h"
#include "report/report.h"

namespace icp {

class ClaimsError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct RunSelector {
  std::vector<std::string> experiments;  // at least one
  std::string algorithm;                 // "": any
  ParamMap algorithm_params;             // exactly these non-default ones
  bool any_algorithm_params = false;     // `algorithm_params: any`
  std::string problem;                   // "": any
  ParamMap problem_params;               // at least these
  std::string label;                     // how measured texts name it; "" : from the config
};

struct Claim {
  std::string id, item, where, quote, note;
  double published = std::numeric_limits<double>::quiet_NaN();
  std::string published_text;  // the row's published cell
  YAML::Node measure;          // kind + the measure's own keys
  std::string rule;            // within_factor, at_least, ...
  std::vector<double> bounds;  // the rule's numbers
  std::string tolerance;       // why the rule's number is what it is
  std::string explain;         // a registered explainer (its keys in if_differs), or
  std::string because;         // a difference by construction
  YAML::Node if_differs;       // the explainer's keys
  std::string spec;            // the spec making its runs; "": the file's
};

struct ClaimsFile {
  std::string paper;  // "paper000"
  std::string title;  // the section's table title
  std::string spec;   // the spec whose runs the claims read ("specs/default.yaml")
  std::string source; // where the text came from (errors)
  std::vector<Claim> claims;
  // The spec that makes a claim's runs: its own, else the file's.
  const std::string& SpecOf(const Claim& claim) const;
};

// Parses and checks a claims file: every key known, every measure and
// explainer registered, every selector well formed, a tolerance where the
// rule has one. Throws ClaimsError("SOURCE: claim 'ID': ...").
ClaimsFile ParseClaims(const std::string& text, const std::string& source);

// The claims files compiled into the binary (experiments/*/claims.yaml), in
// paper order; parsed once.
const std::vector<ClaimsFile>& BuiltInClaims();
// The built-in claims of one paper; throws std::out_of_range when none.
const ClaimsFile& ClaimsOf(const std::string& paper);

// What a measure found: the value the rule judges and the measured cell, or
// why there is no data (which spec makes the runs).
struct Measurement {
  double value = std::numeric_limits<double>::quiet_NaN();
  std::string key;      // what a same_text rule compares ("HC4")
  std::string text;     // the measured cell
  std::string missing;  // non-empty: no data
};

// What measures and explainers see: the store's runs and their groups,
// summarised once per store, and the spec that makes the runs of the claim
// being evaluated (MissingRuns names it). Measures that pool runs a costly
// way keep the result in `cache` (Cached).
struct ClaimContext {
  const std::vector<RunRecord>& runs;
  std::vector<GroupSummary> groups;  // SummariseGroups(runs)
  std::string spec;
  mutable std::map<std::string, std::shared_ptr<const void>> cache;
  explicit ClaimContext(const std::vector<RunRecord>& r);
};

// What make() returns, computed once per context under key.
template <typename T, typename Make>
const T& Cached(const ClaimContext& context, const std::string& key, Make make) {
  std::shared_ptr<const void>& slot = context.cache[key];
  if (!slot) slot = std::make_shared<const T>(make());
  return *static_cast<const T*>(slot.get());
}

using MeasureFn = Measurement (*)(const YAML::Node& measure, const ClaimContext& context);
// The measured reason of a difference; "" when the store cannot tell.
using ExplainFn = std::string (*)(const Claim& claim, const Measurement& measured,
                                  const ClaimContext& context);
struct ClaimFunctions {
  std::map<std::string, MeasureFn> measures;
  std::map<std::string, ExplainFn> explainers;
};
// Every registered measure and explainer (paper/claim_measures.cc and each
// paper's *_claims.cc).
const ClaimFunctions& ClaimFunctionsRegistry();

RunSelector ParseSelector(const YAML::Node& node);
bool Selects(const RunSelector& selector, const RunSpec& spec, const std::string& experiment);
// "{experiment window, hc4 {carry=none}, car-track {w=20}}".
std::string SelectorText(const RunSelector& selector);
// The selectors under one key of a measure (one or a list); none when the
// key is absent.
std::vector<RunSelector> SelectorsUnder(const YAML::Node& node, const char* key);
// The selectors a measure (or an if_differs) names under runs, of, from and
// to.
std::vector<RunSelector> SelectorsOf(const YAML::Node& measure);

// The messages for selectors of a claims file that no run of the claim's
// spec (read under source_dir) matches ("claim 'ID': no run of
// specs/default.yaml matches {...}").
std::vector<std::string> UnplannedSelectors(const ClaimsFile& file, const std::string& source_dir);

// Evaluates every claim of the file against the context's runs.
std::vector<ComparisonRow> EvaluateClaims(const ClaimsFile& file, ClaimContext& context);
// The same with a context of its own (one file, or a test).
std::vector<ComparisonRow> EvaluateClaims(const ClaimsFile& file,
                                          const std::vector<RunRecord>& runs);

// Whether measured satisfies the claim's rule (both sides known).
bool RuleHolds(const Claim& claim, const Measurement& measured);
// "within a factor 1.5", "at least 0.95", ...
std::string RuleText(const Claim& claim);

}  // namespace icp

#endif  // ICPBENCH_PAPER_CLAIMS_H_
