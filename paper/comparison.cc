#include "paper/comparison.h"

#include <cmath>

namespace icp {

std::string_view ToString(Verdict verdict) {
  switch (verdict) {
    case Verdict::kMatch:
      return "match";
    case Verdict::kDiffers:
      return "differs";
    case Verdict::kNoData:
      return "no data";
  }
  return "?";
}

VerdictTally Tally(const std::vector<ComparisonRow>& rows) {
  VerdictTally tally;
  for (const ComparisonRow& r : rows) {
    switch (r.verdict) {
      case Verdict::kMatch:
        ++tally.match;
        break;
      case Verdict::kDiffers:
        ++tally.differ;
        break;
      case Verdict::kNoData:
        ++tally.no_data;
        break;
    }
  }
  return tally;
}

std::string ToString(const VerdictTally& tally) {
  return "Verdicts: " + std::to_string(tally.match) + " match, " + std::to_string(tally.differ) +
         " differ, " + std::to_string(tally.no_data) + " no data";
}

bool WithinFactor(double measured, double published, double factor) {
  if (!(measured > 0) || !(published > 0) || !std::isfinite(measured) || !std::isfinite(published))
    return false;
  return std::fabs(std::log(measured / published)) <= std::log(factor) * (1 + 1e-12);
}

TextTable ComparisonTable(const std::string& title, const std::vector<ComparisonRow>& rows) {
  TextTable t;
  t.title = title;
  t.headers = {"#", "what", "published", "measured", "verdict"};
  t.numeric = {true, false, false, false, false};
  // In print the claim, published and measured texts wrap within their
  // columns (17 cm of text width) rather than becoming notes.
  t.wrap_cm = {0, 4.4, 3.2, 5.6, 0};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ComparisonRow& r = rows[i];
    const std::string n = std::to_string(i + 1);
    t.rows.push_back({n, r.item, r.published, r.measured, std::string(ToString(r.verdict))});
    // The rule and the reason below the table keep its columns narrow.
    std::string item = n + ". " + r.item;
    if (!r.quote.empty()) item += " (" + r.where + ": \"" + r.quote + "\")";
    item += ": " + std::string(ToString(r.verdict)) + " (rule: " + r.rule + ")" +
            (r.reason.empty() ? "" : "; " + r.reason);
    if (!r.note.empty()) item += " Note: " + r.note;
    t.items.push_back(item);
  }
  t.notes.push_back(
      "Each verdict follows its rule, applied by paper/ to the numbers of this store; the rules, "
      "and why a row differs or which spec produces its runs:");
  return t;
}

}  // namespace icp
