#include "experiments/thesis003/guarantee_columns.h"

#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "harness/guarantee.h"
#include "harness/metrics.h"

namespace icp {

double GuaranteeSummary::ConsistencyWhereHeld() const {
  return held == 0 ? std::numeric_limits<double>::quiet_NaN()
                   : static_cast<double>(held_contained) / held;
}

GuaranteeSummary SummariseGuarantee(const GroupSummary& g) {
  GuaranteeSummary out;
  std::vector<double> reacquire;
  for (const RunRecord* r : g.ok_runs) {
    LossEpisodes episodes;
    for (const StepRecord& s : r->steps) {
      episodes.Add(s.contained);
      if (const std::optional<double> held = NumberProperty(s.properties, "assumption_held")) {
        ++out.judged;
        if (*held == 1) ++out.held, out.held_contained += s.contained == 1;
      }
      for (const Property& p : s.properties)
        if (p.name == "miss_reason" && std::holds_alternative<std::string>(p.value)) {
          ++out.misses;
          ++out.miss_categories[MissCategory(std::get<std::string>(p.value))];
        }
    }
    reacquire.insert(reacquire.end(), episodes.reacquire_steps().begin(),
                     episodes.reacquire_steps().end());
  }
  for (const auto& [category, count] : out.miss_categories)
    if (count > out.dominant_count) out.dominant = category, out.dominant_count = count;
  out.median_reacquire = Quantile(reacquire, 0.5);
  return out;
}

std::vector<std::string> GuaranteeHeaders() {
  return {"assumption held (steps)", "consistency where held", "median steps to re-acquire",
          "dominant miss reason"};
}

std::vector<bool> GuaranteeNumeric() { return {false, true, true, false}; }

std::vector<std::string> GuaranteeCells(const GroupSummary& g) {
  const GuaranteeSummary s = SummariseGuarantee(g);
  const std::string dash = "—";
  return {s.judged == 0 ? dash : std::to_string(s.held) + " of " + std::to_string(s.judged),
          FormatNumber(s.ConsistencyWhereHeld()), FormatNumber(s.median_reacquire),
          s.misses == 0 ? dash
                        : s.dominant + " (" + std::to_string(s.dominant_count) + " of " +
                              std::to_string(s.misses) + " misses)"};
}

std::string GuaranteeNote() {
  return "Assumption held: the steps where the relaxed solver's outlier assumption (at most "
         "q_bound = max(q, floor(outlier_share m)) wrong returns) held at that step and at every "
         "step since its last restart, of the steps whose true outliers are known (step property "
         "assumption_held); without auto_q the set is then guaranteed to hold the truth, so its "
         "consistency where held is 1. Re-acquire: the length of each loss of the truth that "
         "ended. Miss reason: why the steps that missed the truth missed it (step property "
         "miss_reason: the assumption violated, auto_q taking fewer outliers than there were, "
         "or the loss an earlier step began).";
}

}  // namespace icp
