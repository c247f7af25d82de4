// The parts of the paper made from the comparison rows of every seed paper:
// the tally the abstract states, each paper's discussion of its
// differences, the limitations and the conclusion.
#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "paper/claims.h"
#include "paper/sections.h"
#include "report/performance_profile.h"
#include "report/report.h"

namespace icp {

namespace {

std::string Paragraph(const std::string& text) { return TexEscape(text) + "\n\n"; }

std::string Bold(const std::string& text) { return "\\textbf{" + TexEscape(text) + "}"; }

// "Row 3", "Rows 3 and 5", "Rows 3, 5 and 8".
std::string RowNumbers(const std::vector<std::size_t>& rows) {
  std::string out = rows.size() == 1 ? "Row " : "Rows ";
  for (std::size_t i = 0; i < rows.size(); ++i)
    out += (i == 0 ? "" : i + 1 == rows.size() ? " and " : ", ") + std::to_string(rows[i] + 1);
  return out;
}

// The rows (indices) of one verdict grouped by their reason, in the order
// of each reason's first row.
std::vector<std::pair<std::string, std::vector<std::size_t>>> ByReason(
    const std::vector<ComparisonRow>& rows, Verdict verdict) {
  std::vector<std::pair<std::string, std::vector<std::size_t>>> groups;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].verdict != verdict) continue;
    auto g = groups.begin();
    while (g != groups.end() && g->first != rows[i].reason) ++g;
    if (g == groups.end()) g = groups.insert(groups.end(), {rows[i].reason, {}});
    g->second.push_back(i);
  }
  return groups;
}

std::string TallyOf(const std::vector<ComparisonRow>& rows) { return ToString(Tally(rows)); }

// text ending in one full stop (a reason may end with its own).
std::string Sentence(const std::string& text) {
  return !text.empty() && text.back() == '.' ? text : text + ".";
}

}  // namespace

std::vector<ComparisonRow> PaperComparisons::All() const {
  std::vector<ComparisonRow> all = paper000;
  all.insert(all.end(), paper002.begin(), paper002.end());
  all.insert(all.end(), thesis003.begin(), thesis003.end());
  all.insert(all.end(), paper004.begin(), paper004.end());
  return all;
}

PaperComparisons ComparePapers(const std::vector<RunRecord>& runs) {
  ClaimContext context(runs);  // one summary of the store for every paper
  return {EvaluateClaims(ClaimsOf("paper000"), context),
          EvaluateClaims(ClaimsOf("paper002"), context),
          EvaluateClaims(ClaimsOf("thesis003"), context),
          EvaluateClaims(ClaimsOf("paper004"), context)};
}

std::string TallyTex(const PaperComparisons& comparisons) {
  const std::vector<ComparisonRow> all = comparisons.All();
  return "\\newcommand{\\icpbenchtally}{" + TexEscape(TallyOf(all)) +
         "}\n\\newcommand{\\icpbenchclaims}{" + std::to_string(all.size()) + "}\n";
}

std::string ClaimsJson(const PaperComparisons& comparisons) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [paper, rows] : {std::pair{"paper000", &comparisons.paper000},
                                    std::pair{"paper002", &comparisons.paper002},
                                    std::pair{"thesis003", &comparisons.thesis003},
                                    std::pair{"paper004", &comparisons.paper004}})
    for (const ComparisonRow& r : *rows)
      out.push_back({{"paper", paper},
                     {"id", r.id},
                     {"item", r.item},
                     {"where", r.where},
                     {"quote", r.quote},
                     {"published", r.published},
                     {"measured", r.measured},
                     {"rule", r.rule},
                     {"verdict", std::string(ToString(r.verdict))},
                     {"reason", r.reason},
                     {"note", r.note}});
  return out.dump(2) + "\n";
}

std::string DiscussionTex(const std::vector<ComparisonRow>& rows) {
  std::ostringstream out;
  const auto differ = ByReason(rows, Verdict::kDiffers);
  if (differ.empty())
    out << Paragraph("No row of this paper differs from what this store measures (" +
                     TallyOf(rows) + ").");
  for (const auto& [reason, numbers] : differ) {
    // What each row publishes and measures, then the one reason.
    std::string text;
    for (std::size_t i : numbers) {
      const ComparisonRow& r = rows[i];
      text += (text.empty() ? "" : " ") + r.item + ": the paper gives " + r.published +
              ", this store " + r.measured + ", outside the rule (" + r.rule + ").";
    }
    out << Bold(RowNumbers(numbers) + ".") << " " << TexEscape(text + " Why: " + Sentence(reason))
        << "\n\n";
  }
  for (const auto& [reason, numbers] : ByReason(rows, Verdict::kNoData)) {
    std::string items;
    for (std::size_t i : numbers) items += (items.empty() ? "" : "; ") + rows[i].item;
    out << Bold(RowNumbers(numbers) + ", no data.") << " "
        << TexEscape(items + ": " + Sentence(reason)) << "\n\n";
  }
  return out.str();
}

std::string LimitationsTex(const std::vector<RunRecord>& runs,
                           const PaperComparisons& comparisons) {
  std::set<std::string> machines;
  for (const RunRecord& r : runs) machines.insert(r.provenance.machine);
  std::ostringstream out;
  out << Bold("Simulated data.") << " "
      << Paragraph(
             "Every problem is simulated, with bounded errors and a known truth: the car's lap, "
             "the lines and beacons, the city and the marina. The papers measured recorded data "
             "(paper 000 a lap driven by a car, thesis 003 the robot of its chapter 6 in the "
             "Girona marina, whose data set is not available here). Absolute areas and errors "
             "therefore follow our simulators' noise and geometry, not the papers'; where they "
             "cannot agree, the rules judge orders, ratios and trends, and each row's rule "
             "says which.");
  out << Bold("The machine.") << " "
      << Paragraph("Every time was measured on " +
                   std::string(machines.size() == 1 ? "the machine" : "the " +
                               std::to_string(machines.size()) + " machines") +
                   " of the first page, by icpbench's own implementations, where the papers ran "
                   "RealPaver, C/C++ or Matlab on theirs; absolute times do not compare, ratios "
                   "between algorithms measured on one machine do.");
  const std::vector<ComparisonRow> all = comparisons.All();
  const VerdictTally tally = Tally(all);
  out << Bold("Not reproduced.") << " ";
  if (tally.no_data == 0) {
    out << Paragraph("Every claim compared here has runs in this store.");
  } else {
    out << Paragraph(std::to_string(tally.no_data) + " of the " + std::to_string(all.size()) +
                     " claims have no runs in this store; each paper's discussion says which "
                     "spec makes them.");
  }
  out << Paragraph(
      "Beyond the claims compared here: paper 004's camera system (landmarks as interval cones, "
      "the DIGO graph, teach and repeat) is not reimplemented, and paper 002 has no section "
      "here (docs/reproduction/ lists what is open, paper by paper).");
  return out.str();
}

std::string ConclusionTex(const std::vector<RunRecord>& runs,
                          const PaperComparisons& comparisons) {
  std::ostringstream out;
  const std::vector<ComparisonRow> all = comparisons.All();
  out << Paragraph("Of the " + std::to_string(all.size()) +
                   " published claims compared with this store: " + TallyOf(all) + ".");
  TextTable t;
  t.title = "Verdicts per paper";
  t.headers = {"paper", "claims", "match", "differ", "no data"};
  t.numeric = {false, true, true, true, true};
  for (const auto& [paper, rows] :
       {std::pair<std::string, const std::vector<ComparisonRow>*>{"000", &comparisons.paper000},
        {"002", &comparisons.paper002},
        {"thesis 003", &comparisons.thesis003},
        {"004", &comparisons.paper004}}) {
    const VerdictTally v = Tally(*rows);
    t.rows.push_back({paper, std::to_string(rows->size()), std::to_string(v.match),
                      std::to_string(v.differ), std::to_string(v.no_data)});
  }
  out << TexTable(t);
  out << Paragraph(
      "Each difference is discussed in its paper's section with the reason the store measures "
      "for it, or said to have none measured yet.");
  // What the performance profiles show: the configuration most often best.
  for (const ProfileMetric metric : {ProfileMetric::kTime, ProfileMetric::kArea}) {
    const PerformanceProfile profile = RunsProfile(runs, metric);
    double most = 0;
    for (const SolverProfile& s : profile.solvers) most = std::max(most, Rho(profile, s, 1));
    std::string best;
    for (const SolverProfile& s : profile.solvers)
      if (most > 0 && Rho(profile, s, 1) == most)
        best += (best.empty() ? "" : ", ") + s.solver + " (solves " + std::to_string(s.solved) +
                ")";
    if (best.empty()) continue;
    out << Paragraph("Over the store's " + std::to_string(profile.instances) +
                     " problem instances, the best " + ProfileMetricName(metric) +
                     " most often (ρ(1) = " + FormatShare(most) + ") is that of " + best + ".");
  }
  return out.str();
}

}  // namespace icp
