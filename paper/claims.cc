#include "paper/claims.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "paper/claim_measures.h"
#include "paper/claims_files.h"

namespace icp {

namespace {

const std::set<std::string> kRules = {"within_factor", "at_least", "at_most", "below",
                                      "between",       "equals",   "same_text"};

[[noreturn]] void Fail(const std::string& where, const std::string& what) {
  throw ClaimsError(where + ": " + what);
}

std::string At(const std::string& source, const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? source + ":" + std::to_string(mark.line + 1) : source;
}

void CheckKeys(const YAML::Node& map, const std::set<std::string>& known,
               const std::string& where) {
  if (!map.IsMap()) Fail(where, "expected a map");
  for (const auto& kv : map) {
    const std::string key = kv.first.as<std::string>();
    if (!known.count(key)) Fail(where, "unknown key '" + key + "'");
  }
}

std::string Text(const YAML::Node& map, const std::string& key, const std::string& where,
                 bool required = true) {
  const YAML::Node n = map[key];
  if (!n) {
    if (required) Fail(where, "needs '" + key + "'");
    return "";
  }
  if (!n.IsScalar()) Fail(where, "'" + key + "' must be a text");
  return n.as<std::string>();
}

bool AsNumber(const std::string& text, double* value) {
  try {
    std::size_t used = 0;
    *value = std::stod(text, &used);
    return used == text.size();
  } catch (const std::exception&) {
    return false;
  }
}

// Parameter values compare as numbers when both are ("20" = "20.0").
bool SameValue(const std::string& a, const std::string& b) {
  double x, y;
  if (AsNumber(a, &x) && AsNumber(b, &y)) return x == y;
  return a == b;
}

ParamMap ParseParams(const YAML::Node& node, const std::string& where) {
  ParamMap out;
  if (!node) return out;
  if (!node.IsMap()) Fail(where, "parameters must be a map");
  for (const auto& kv : node) {
    if (!kv.second.IsScalar()) Fail(where, "parameter '" + kv.first.as<std::string>() +
                                               "' must be one value");
    out[kv.first.as<std::string>()] = kv.second.as<std::string>();
  }
  return out;
}

Claim ParseClaim(const YAML::Node& node, const std::string& source) {
  std::string where = At(source, node);
  CheckKeys(node,
            {"id", "item", "where", "quote", "published", "published_text", "measure", "rule",
             "tolerance", "if_differs", "note", "spec"},
            where);
  Claim c;
  c.id = Text(node, "id", where);
  where += ": claim '" + c.id + "'";
  c.item = Text(node, "item", where);
  c.where = Text(node, "where", where);
  c.quote = Text(node, "quote", where);
  c.note = Text(node, "note", where, false);
  c.spec = Text(node, "spec", where, false);
  const std::string published = Text(node, "published", where);
  if (!AsNumber(published, &c.published)) c.published_text = published;
  if (node["published_text"]) c.published_text = Text(node, "published_text", where);
  if (c.published_text.empty()) c.published_text = FormatNumber(c.published);

  // A missing key's node is invalid: assigning it would throw.
  if (node["measure"]) c.measure = node["measure"];
  if (!c.measure || !c.measure.IsMap()) Fail(where, "needs 'measure', a map with a 'kind'");
  const std::string kind = Text(c.measure, "kind", where + ": measure");
  if (!ClaimFunctionsRegistry().measures.count(kind))
    Fail(where, "unknown measure kind '" + kind + "'");
  try {
    SelectorsOf(c.measure);
  } catch (const std::exception& e) {
    Fail(where, std::string("measure: ") + e.what());
  }
  const YAML::Node rule = node["rule"];
  if (!rule || !rule.IsMap() || rule.size() != 1) Fail(where, "needs 'rule', one of its kinds");
  c.rule = rule.begin()->first.as<std::string>();
  if (!kRules.count(c.rule)) Fail(where, "unknown rule '" + c.rule + "'");
  const YAML::Node bound = rule.begin()->second;
  if (c.rule == "between") {
    if (!bound.IsSequence() || bound.size() != 2) Fail(where, "between takes [lo, hi]");
    c.bounds = {bound[0].as<double>(), bound[1].as<double>()};
  } else if (c.rule != "same_text") {
    if (!bound.IsScalar()) Fail(where, c.rule + " takes a number");
    c.bounds = {bound.as<double>()};
  }
  if (c.rule == "within_factor" && std::isnan(c.published))
    Fail(where, "within_factor needs a numeric 'published'");
  if (c.rule == "same_text" && c.published_text.empty())
    Fail(where, "same_text needs a text 'published'");
  c.tolerance = Text(node, "tolerance", where, false);
  if (c.tolerance.empty() && c.rule != "same_text" && c.rule != "equals")
    Fail(where, "rule " + c.rule + " needs 'tolerance': why its number is what it is");

  if (node["if_differs"]) c.if_differs = node["if_differs"];
  if (!c.if_differs || !c.if_differs.IsMap())
    Fail(where, "needs 'if_differs': {explain: NAME} or {because: TEXT}");
  c.explain = Text(c.if_differs, "explain", where, false);
  c.because = Text(c.if_differs, "because", where, false);
  if (c.explain.empty() == c.because.empty())
    Fail(where, "if_differs needs exactly one of 'explain' and 'because'");
  if (!c.explain.empty() && !ClaimFunctionsRegistry().explainers.count(c.explain))
    Fail(where, "unknown explainer '" + c.explain + "'");
  try {
    SelectorsOf(c.if_differs);
  } catch (const std::exception& e) {
    Fail(where, std::string("if_differs: ") + e.what());
  }
  return c;
}

}  // namespace

std::string SelectorText(const RunSelector& s) {
  std::string out = "{experiment ";
  for (std::size_t i = 0; i < s.experiments.size(); ++i)
    out += (i ? "|" : "") + s.experiments[i];
  if (!s.algorithm.empty())
    out += ", " + WithParams(s.algorithm, s.any_algorithm_params ? ParamMap{} : s.algorithm_params);
  if (!s.problem.empty()) out += ", " + WithParams(s.problem, s.problem_params);
  return out + "}";
}

RunSelector ParseSelector(const YAML::Node& node) {
  const std::string where = "selector";
  CheckKeys(node,
            {"experiment", "algorithm", "algorithm_params", "problem", "problem_params", "label"},
            where);
  RunSelector s;
  const YAML::Node e = node["experiment"];
  if (!e) Fail(where, "needs 'experiment'");
  if (e.IsSequence())
    for (const YAML::Node& x : e) s.experiments.push_back(x.as<std::string>());
  else
    s.experiments.push_back(e.as<std::string>());
  s.algorithm = Text(node, "algorithm", where, false);
  s.problem = Text(node, "problem", where, false);
  s.label = Text(node, "label", where, false);
  const YAML::Node a = node["algorithm_params"];
  if (a && a.IsScalar() && a.as<std::string>() == "any")
    s.any_algorithm_params = true;
  else
    s.algorithm_params = ParseParams(a, where);
  s.problem_params = ParseParams(node["problem_params"], where);
  return s;
}

bool Selects(const RunSelector& s, const RunSpec& spec, const std::string& experiment) {
  if (std::find(s.experiments.begin(), s.experiments.end(), experiment) == s.experiments.end())
    return false;
  if (!s.algorithm.empty() && spec.algorithm != s.algorithm) return false;
  if (!s.problem.empty() && spec.problem != s.problem) return false;
  if (!s.any_algorithm_params) {
    if (spec.algorithm_params.size() != s.algorithm_params.size()) return false;
    for (const auto& [k, v] : s.algorithm_params) {
      const auto it = spec.algorithm_params.find(k);
      if (it == spec.algorithm_params.end() || !SameValue(it->second, v)) return false;
    }
  }
  for (const auto& [k, v] : s.problem_params) {
    const auto it = spec.problem_params.find(k);
    const std::string given =
        it != spec.problem_params.end() ? it->second : ProblemDefaults(spec.problem)[k];
    if (!SameValue(given, v)) return false;
  }
  return true;
}

std::vector<RunSelector> SelectorsUnder(const YAML::Node& node, const char* key) {
  std::vector<RunSelector> out;
  const YAML::Node n = node[key];
  if (!n) return out;
  if (n.IsSequence())
    for (const YAML::Node& e : n) out.push_back(ParseSelector(e));
  else
    out.push_back(ParseSelector(n));
  return out;
}

std::vector<RunSelector> SelectorsOf(const YAML::Node& measure) {
  std::vector<RunSelector> out;
  for (const char* key : {"runs", "of", "from", "to"})
    for (RunSelector& s : SelectorsUnder(measure, key)) out.push_back(std::move(s));
  return out;
}

ClaimsFile ParseClaims(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    Fail(source + ":" + std::to_string(e.mark.line + 1), e.msg);
  }
  CheckKeys(root, {"paper", "title", "spec", "claims"}, source);
  ClaimsFile f;
  f.source = source;
  f.paper = Text(root, "paper", source);
  f.title = Text(root, "title", source);
  f.spec = Text(root, "spec", source);
  if (!root["claims"] || !root["claims"].IsSequence()) Fail(source, "needs 'claims', a list");
  std::set<std::string> ids;
  for (const YAML::Node& node : root["claims"]) {
    f.claims.push_back(ParseClaim(node, source));
    if (!ids.insert(f.claims.back().id).second)
      Fail(source, "claim id '" + f.claims.back().id + "' given twice");
  }
  return f;
}

const std::vector<ClaimsFile>& BuiltInClaims() {
  static const std::vector<ClaimsFile> files = [] {
    std::vector<ClaimsFile> out;
    for (const EmbeddedClaims& e : EmbeddedClaimsFiles()) out.push_back(ParseClaims(e.text, e.path));
    return out;
  }();
  return files;
}

const ClaimsFile& ClaimsOf(const std::string& paper) {
  for (const ClaimsFile& f : BuiltInClaims())
    if (f.paper == paper) return f;
  throw std::out_of_range("no claims file for " + paper);
}

const std::string& ClaimsFile::SpecOf(const Claim& claim) const {
  return claim.spec.empty() ? spec : claim.spec;
}

ClaimContext::ClaimContext(const std::vector<RunRecord>& r)
    : runs(r), groups(SummariseGroups(r)) {}

std::vector<std::string> UnplannedSelectors(const ClaimsFile& file, const std::string& source_dir) {
  std::vector<std::string> out;
  std::map<std::string, Spec> specs;
  for (const Claim& c : file.claims) {
    const std::string& path = file.SpecOf(c);
    if (!specs.count(path)) specs.emplace(path, LoadSpec(source_dir + "/" + path));
    const Spec& spec = specs.at(path);
    std::vector<RunSelector> selectors = SelectorsOf(c.measure);
    for (const RunSelector& s : SelectorsOf(c.if_differs)) selectors.push_back(s);
    for (const RunSelector& s : selectors) {
      const bool planned = std::any_of(spec.runs.begin(), spec.runs.end(), [&](const PlannedRun& p) {
        return p.skip_reason.empty() && Selects(s, WithoutDefaults(p.spec), p.experiment);
      });
      if (!planned)
        out.push_back("claim '" + c.id + "': no run of " + path + " matches " +
                      SelectorText(s));
    }
  }
  return out;
}

bool RuleHolds(const Claim& c, const Measurement& m) {
  if (c.rule == "same_text") return !m.key.empty() && m.key == c.published_text;
  const double v = m.value;
  if (std::isnan(v)) return false;
  if (c.rule == "within_factor") return WithinFactor(v, c.published, c.bounds[0]);
  if (c.rule == "at_least") return v >= c.bounds[0];
  if (c.rule == "at_most") return v <= c.bounds[0];
  if (c.rule == "below") return v < c.bounds[0];
  if (c.rule == "between") return v >= c.bounds[0] && v <= c.bounds[1];
  if (c.rule == "equals") return v == c.bounds[0];
  return false;
}

std::string RuleText(const Claim& c) {
  std::string out;
  if (c.rule == "same_text") out = "the same";
  else if (c.rule == "within_factor") out = "within a factor " + FormatNumber(c.bounds[0]);
  else if (c.rule == "at_least") out = "at least " + FormatNumber(c.bounds[0]);
  else if (c.rule == "at_most") out = "at most " + FormatNumber(c.bounds[0]);
  else if (c.rule == "below") out = "below " + FormatNumber(c.bounds[0]);
  else if (c.rule == "between")
    out = "between " + FormatNumber(c.bounds[0]) + " and " + FormatNumber(c.bounds[1]);
  else if (c.rule == "equals") out = "exactly " + FormatNumber(c.bounds[0]);
  return c.tolerance.empty() ? out : out + " (" + c.tolerance + ")";
}

std::vector<ComparisonRow> EvaluateClaims(const ClaimsFile& file,
                                          const std::vector<RunRecord>& runs) {
  ClaimContext context(runs);
  return EvaluateClaims(file, context);
}

std::vector<ComparisonRow> EvaluateClaims(const ClaimsFile& file, ClaimContext& context) {
  const ClaimFunctions& functions = ClaimFunctionsRegistry();
  std::vector<ComparisonRow> rows;
  for (const Claim& c : file.claims) {
    context.spec = file.SpecOf(c);
    ComparisonRow r{c.item, c.published_text, "—", RuleText(c), Verdict::kNoData, ""};
    r.id = c.id, r.where = c.where, r.quote = c.quote, r.note = c.note;
    Measurement m;
    try {
      m = functions.measures.at(c.measure["kind"].as<std::string>())(c.measure, context);
    } catch (const std::exception& e) {
      m.missing = std::string("cannot be measured: ") + e.what();
    }
    if (!m.missing.empty()) {
      r.reason = m.missing;
    } else if (c.rule != "same_text" && std::isnan(m.value)) {
      // Runs were found but give no value (no truth to compare with, no
      // seed with the metric): nothing to judge, not a difference.
      r.measured = m.text.empty() ? "—" : m.text;
      r.reason = "the runs it reads give no value (e.g. no truth to compare with)";
    } else {
      r.measured = m.text.empty() ? FormatNumber(m.value) : m.text;
      r.verdict = RuleHolds(c, m) ? Verdict::kMatch : Verdict::kDiffers;
      if (r.verdict == Verdict::kDiffers) {
        r.reason = c.because;
        if (!c.explain.empty()) {
          try {
            r.reason = functions.explainers.at(c.explain)(c, m, context);
          } catch (const std::exception& e) {
            r.reason = std::string(kNotMeasured) + " (" + e.what() + ")";
          }
        }
        if (r.reason.empty()) {
          const std::string because = c.explain.empty() ? "" : UnexplainedBecause(c, context);
          r.reason = because.empty() ? kNotMeasured : std::string(kNotMeasured) + " (" + because + ")";
        }
      }
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace icp
