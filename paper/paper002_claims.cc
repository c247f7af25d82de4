// Paper 002's own measure (experiments/paper002/claims.yaml): `indoor`,
// over the indoor-landmarks runs a selector picks (every seed and path),
// from each run's steps (IndoorStats) or association totals:
//   growth          the lowest share of steps whose 3-D box (x, y, theta)
//                   grew (1: every step of every run)
//   widest_xy       the widest box in x or y over every step of every run, m
//   widest_theta    the same in theta, degrees
//   position_error  the median over runs of the mean centre-to-truth
//                   distance, m
//   heading_error   the same of the heading, degrees
//   wrong_ratio     the wrong associations of runs over those of `of`,
//                   summed over their runs (the same seeds and paths)
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "experiments/paper002/paper002.h"
#include "paper/claim_measures.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<const RunRecord*> OkRuns(const ClaimContext& context,
                                     const std::vector<RunSelector>& selectors) {
  std::vector<const RunRecord*> runs;
  for (const RunSelector& s : selectors)
    for (const GroupSummary* g : Matching(context, s))
      for (const RunRecord* r : g->ok_runs)
        if (std::find(runs.begin(), runs.end(), r) == runs.end()) runs.push_back(r);
  return runs;
}

double WrongAssociations(const std::vector<const RunRecord*>& runs) {
  double total = 0;
  for (const RunRecord* r : runs) {
    const std::optional<double> v = NumberProperty(r->properties, "associations_wrong");
    if (!v) return kNaN;
    total += *v;
  }
  return total;
}

// The per-run quantities (IndoorStats) and which of the runs' values each
// claim judges.
enum class Pick { kLowest, kWidest, kMedian };
struct Quantity {
  const char* name;
  double (*of)(const IndoorRunStats&);
  Pick pick;
  const char* unit;
};
const Quantity kQuantities[] = {
    {"growth", [](const IndoorRunStats& s) { return s.growth_share; }, Pick::kLowest, ""},
    {"widest_xy", [](const IndoorRunStats& s) { return std::max(s.widest_x, s.widest_y); },
     Pick::kWidest, " m"},
    {"widest_theta", [](const IndoorRunStats& s) { return s.widest_theta_deg; }, Pick::kWidest, "°"},
    {"position_error", [](const IndoorRunStats& s) { return s.position_error; }, Pick::kMedian,
     " m"},
    {"heading_error", [](const IndoorRunStats& s) { return s.heading_error_deg; }, Pick::kMedian,
     "°"},
};

Measurement MeasureIndoor(const YAML::Node& measure, const ClaimContext& context) {
  const std::string quantity = measure["quantity"] ? measure["quantity"].as<std::string>() : "";
  const std::vector<RunSelector> selectors = SelectorsUnder(measure, "runs");
  if (selectors.empty()) throw ClaimsError("the measure needs 'runs'");
  const std::vector<const RunRecord*> runs = OkRuns(context, selectors);
  Measurement m;
  if (runs.empty()) {
    m.missing = MissingRuns(context, selectors.front());
    return m;
  }
  const std::string over = " over " + std::to_string(runs.size()) + " runs";
  if (quantity == "wrong_ratio") {
    const std::vector<RunSelector> of = SelectorsUnder(measure, "of");
    if (of.empty()) throw ClaimsError("wrong_ratio needs 'of'");
    const std::vector<const RunRecord*> baseline = OkRuns(context, of);
    if (baseline.empty()) {
      m.missing = MissingRuns(context, of.front());
      return m;
    }
    const double a = WrongAssociations(runs), b = WrongAssociations(baseline);
    if (std::isnan(a) || std::isnan(b)) {
      m.missing = "the runs record no associations_wrong: rerun " + context.spec;
      return m;
    }
    m.value = b > 0 ? a / b : (a > 0 ? std::numeric_limits<double>::infinity() : kNaN);
    m.text = FormatNumber(a) + " / " + FormatNumber(b) + " wrong associations = " +
             FormatNumber(m.value) + " (" + std::to_string(runs.size()) + " and " +
             std::to_string(baseline.size()) + " runs)";
    if (std::isnan(m.value)) m.missing = "neither rule made a wrong association" + over;
    return m;
  }
  const auto quantity_it = std::find_if(std::begin(kQuantities), std::end(kQuantities),
                                        [&](const Quantity& q) { return quantity == q.name; });
  if (quantity_it == std::end(kQuantities))
    throw ClaimsError("indoor needs 'quantity': growth, widest_xy, widest_theta, position_error, "
                      "heading_error or wrong_ratio");
  const Quantity& q = *quantity_it;
  std::vector<double> values;
  for (const RunRecord* r : runs)
    if (const double v = q.of(IndoorStats(*r)); !std::isnan(v)) values.push_back(v);
  if (values.empty()) {
    m.missing = "the runs have no step rows (record: runs?): rerun " + context.spec;
    return m;
  }
  std::sort(values.begin(), values.end());
  switch (q.pick) {
    case Pick::kLowest: m.value = values.front(), m.text = "lowest "; break;
    case Pick::kWidest: m.value = values.back(), m.text = "widest "; break;
    case Pick::kMedian: m.value = MedianWithInterval(values).median, m.text = "median "; break;
  }
  m.text += FormatNumber(m.value) + q.unit + over;
  return m;
}

}  // namespace

void AddPaper002ClaimFunctions(ClaimFunctions* functions) {
  functions->measures["indoor"] = MeasureIndoor;
}

}  // namespace icp
