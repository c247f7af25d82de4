// A parameter's documented range is a contract (issue 31): for every
// registered algorithm and problem, every numeric parameter at its range's
// ends and inside it gives a run that finishes (ok or timed out) or fails
// alone with a documented reason, and a value just outside is rejected with
// the range in the message. Runs are short: the problems are made small and
// every run has a wall-clock limit, so an end that means "a lot of work" is a
// timeout, which is a result.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "core/params.h"
#include "harness/results_store.h"
#include "harness/spec.h"
#include "problems/registry.h"
#include "tests/cli_helpers.h"

namespace icp {
namespace {

namespace fs = std::filesystem;

// A numeric range read back from its printed form, "[0, 1)", "(0, +oo]".
struct ParsedRange {
  double lo, hi;
  bool lo_open, hi_open;
};

double ParseBound(std::string text) {
  text = std::regex_replace(text, std::regex("^\\s+|\\s+$"), "");
  if (text == "+oo" || text == "oo" || text == "inf") return HUGE_VAL;
  if (text == "-oo" || text == "-inf") return -HUGE_VAL;
  return std::stod(text);
}

bool ParseRange(const std::string& range, ParsedRange* out) {
  static const std::regex kInterval("^([\\[(])([^,]+),([^\\])]+)([\\])])$");
  std::smatch m;
  if (!std::regex_match(range, m, kInterval)) return false;
  *out = {ParseBound(m[2]), ParseBound(m[3]), m[1] == "(", m[4] == ")"};
  return true;
}

bool Numeric(const ParamInfo& p) { return p.type == "double" || p.type == "int"; }

// A value "infinitely" large for the type: the top of a range like [1, +oo]
// or [1, 1e308].
double TopOf(const ParamInfo& p, const ParsedRange& r) {
  const double top = p.type == "int" ? std::numeric_limits<int>::max() : 1e300;
  return std::min(r.hi, top);
}

std::string Text(const ParamInfo& p, double v) {
  if (p.type == "int") return std::to_string(static_cast<long long>(v));
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The values inside the range a run is made with: both ends (just inside an
// open end), and two interior points.
std::vector<std::string> InsideValues(const ParamInfo& p, const ParsedRange& r) {
  const double hi = TopOf(p, r);
  double lo = r.lo;
  double top = hi;
  if (p.type == "int") {
    if (r.lo_open) lo = std::floor(lo) + 1;
    if (r.hi_open) top = std::ceil(hi) - 1;
  } else {
    if (r.lo_open) lo = std::nextafter(lo, HUGE_VAL);
    if (r.hi_open) top = std::nextafter(top, -HUGE_VAL);
  }
  std::set<std::string> values{Text(p, lo), Text(p, top)};
  const double span = top - lo;
  for (double f : {0.1, 0.5}) {
    double v = lo + f * span;
    if (p.type == "int") v = std::round(v);
    values.insert(Text(p, v));
  }
  return {values.begin(), values.end()};
}

// Values just outside the range: below its low end and, when finite, above
// its high end.
std::vector<std::string> OutsideValues(const ParamInfo& p, const ParsedRange& r) {
  std::vector<std::string> out;
  if (std::isfinite(r.lo)) {
    const double below = r.lo_open ? r.lo : (p.type == "int" ? r.lo - 1
                                                              : std::nextafter(r.lo, -HUGE_VAL));
    out.push_back(Text(p, below));
  }
  if (r.hi < 1e300 && !(p.type == "int" && r.hi >= std::numeric_limits<int>::max())) {
    const double above = r.hi_open ? r.hi : (p.type == "int" ? r.hi + 1
                                                              : std::nextafter(r.hi, HUGE_VAL));
    out.push_back(Text(p, above));
  }
  return out;
}

std::vector<std::pair<std::string, ParamInfo>> NumericParams(
    const std::vector<ParamInfo>& params, const std::string& owner,
    std::vector<std::string>* unparsed) {
  std::vector<std::pair<std::string, ParamInfo>> out;
  for (const ParamInfo& p : params) {
    if (!Numeric(p)) continue;
    ParsedRange r;
    if (!ParseRange(p.range, &r)) {
      unparsed->push_back(owner + "." + p.name + " range '" + p.range + "'");
      continue;
    }
    out.push_back({owner, p});
  }
  return out;
}

TEST(ParamRangeTest, AValueOutsideTheRangeIsRejectedWithTheRange) {
  std::vector<std::string> unparsed;
  int checked = 0;
  auto check = [&](const std::string& owner, const std::vector<ParamInfo>& params,
                   ParamResolver resolve) {
    for (const auto& [o, p] : NumericParams(params, owner, &unparsed)) {
      ParsedRange r;
      ParseRange(p.range, &r);
      for (const std::string& v : OutsideValues(p, r)) {
        ++checked;
        try {
          resolve(owner, {{p.name, v}});
          ADD_FAILURE() << owner << "." << p.name << " = " << v << " accepted, range "
                        << p.range;
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find(p.range), std::string::npos)
              << owner << "." << p.name << " = " << v << ": '" << e.what()
              << "' does not give the range " << p.range;
        }
      }
    }
  };
  for (const AlgorithmInfo& a : Algorithms())
    if (!a.test_only) check(a.name, a.params(a.name), a.resolve);
  for (const ProblemInfo& p : Problems()) check(p.name, p.params(p.name), p.resolve);
  EXPECT_TRUE(unparsed.empty()) << unparsed.front();
  EXPECT_GT(checked, 40);
}

// A small instance of a problem for an algorithm's parameter sweep, per view.
std::string SmallProblemFor(View needs) {
  switch (needs) {
    case View::kCsp: return "{name: chain, params: {w: 5}}";
    case View::kMeasurementSet: return "{name: line-intersection, params: {lines: 8, outliers: 2}}";
    case View::kProbabilistic: return "{name: car-track, params: {steps: 5}}";
    case View::kLandmarkObservations: return "{name: indoor-landmarks, params: {steps: 5}}";
  }
  return "";
}

// An algorithm that runs on a problem's view, cheaply, for its sweep.
std::string AlgorithmFor(const ProblemInfo& p) {
  auto offers = [&](View v) {
    return std::find(p.offers.begin(), p.offers.end(), v) != p.offers.end();
  };
  if (offers(View::kCsp)) return "hc4";
  if (offers(View::kMeasurementSet)) return "{name: q-relaxed, params: {mode: contract}}";
  return "{name: particle-filter, params: {particles: 100}}";
}

// What a run may fail with and still be a documented outcome (docs/specs.md,
// "timeout_s and memory_limit_mb"): the worker's memory limit, reached or
// foreseen before a user-sized allocation.
bool DocumentedFailure(const std::string& reason) {
  static const std::regex kDocumented("^out of memory at step [0-9]+");
  return std::regex_search(reason, kDocumented);
}

// Whether a value inside its range is accepted alone (the others at their
// defaults). A value may be refused only by a rule that ties it to another
// parameter of the same plugin ("radius_error ... must be below
// wheel_radius"), and the message must name that parameter.
bool Accepted(const std::string& owner, const std::vector<ParamInfo>& params,
              ParamResolver resolve, const ParamInfo& p, const std::string& value) {
  try {
    resolve(owner, {{p.name, value}});
    return true;
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    bool names_another = false;
    for (const ParamInfo& other : params)
      names_another |= other.name != p.name && message.find(other.name) != std::string::npos;
    EXPECT_TRUE(names_another) << owner << "." << p.name << " = " << value
                               << " is inside its range " << p.range << " but refused: "
                               << message;
    return false;
  }
}

TEST(ParamRangeTest, EveryValueInsideTheRangeRunsOrFailsAloneWithADocumentedReason) {
  std::vector<std::string> unparsed;
  std::ostringstream spec;
  spec << "name: ranges\ntimeout_s: 4\nmemory_limit_mb: 1024\nrecord: runs\nexperiments:\n";
  int planned = 0;
  auto experiment = [&](const std::string& name, const std::string& algorithm,
                        const std::string& problem) {
    spec << "  - name: " << name << "\n    algorithms: [" << algorithm
         << "]\n    problems: [" << problem << "]\n";
    ++planned;
  };
  for (const AlgorithmInfo& a : Algorithms()) {
    if (a.test_only) continue;
    const std::vector<ParamInfo> params = a.params(a.name);
    for (const auto& [owner, p] : NumericParams(params, a.name, &unparsed)) {
      ParsedRange r;
      ParseRange(p.range, &r);
      for (const std::string& v : InsideValues(p, r))
        if (Accepted(a.name, params, a.resolve, p, v))
          experiment(a.name + "-" + std::to_string(planned),
                   "{name: " + a.name + ", params: {\"" + p.name + "\": " + v + "}}",
                   SmallProblemFor(a.needs));
    }
  }
  for (const ProblemInfo& pr : Problems()) {
    const std::vector<ParamInfo> params = pr.params(pr.name);
    for (const auto& [owner, p] : NumericParams(params, pr.name, &unparsed)) {
      ParsedRange r;
      ParseRange(p.range, &r);
      for (const std::string& v : InsideValues(p, r))
        if (Accepted(pr.name, params, pr.resolve, p, v))
          experiment(pr.name + "-" + std::to_string(planned), AlgorithmFor(pr),
                   "{name: " + pr.name + ", params: {\"" + p.name + "\": " + v + "}}");
    }
  }
  ASSERT_TRUE(unparsed.empty()) << unparsed.front();

  const std::string dir = ::testing::TempDir() + "param_ranges";
  fs::remove_all(dir);
  const std::string spec_path = testing::WriteFile("param_ranges.yaml", spec.str());
  const testing::Result run =
      testing::RunCommand(ICPBENCH_BINARY, "run " + spec_path + " --out " + dir + " --jobs 2");
  ASSERT_EQ(run.exit_code, 0) << run.out.substr(0, 4000);

  const auto store = ResultsStore::OpenReadOnly(dir + "/results.sqlite");
  const std::vector<RunRecord> runs = store->LoadRuns(false);
  // Equal values (a default written out) share a run key: one run each.
  EXPECT_EQ(runs.size(), ParseSpec(spec.str(), spec_path).runs.size());
  EXPECT_GE(static_cast<int>(runs.size()), planned / 2);
  for (const RunRecord& r : runs) {
    const bool finished = r.status == RunStatus::kOk || r.status == RunStatus::kTimeout;
    const bool documented = r.status == RunStatus::kFailed && DocumentedFailure(r.reason);
    EXPECT_TRUE(finished || documented)
        << r.spec.Key() << ": " << ToString(r.status) << ": " << r.reason;
  }
}

}  // namespace
}  // namespace icp
