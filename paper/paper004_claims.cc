// Paper 004's own measure (experiments/paper004/claims.yaml): real-time
// localization against post-localization (§4.2) over the car track's window
// sweep and the visual-landmarks repeat runs, as experiments/paper004 pools
// them (Paper004PostLocalization, Paper004RepeatPostLocalization).
#include <cmath>
#include <string>

#include "experiments/paper004/paper004.h"
#include "experiments/paper004/visual.h"
#include "paper/claim_measures.h"

namespace icp {

namespace {

// Whether a selector picks some ok run of the point.
bool Picks(const std::vector<RunSelector>& selectors, const SweepPoint& p) {
  for (const RunRecord* run : p.ok_runs)
    for (const RunSelector& s : selectors)
      if (Selects(s, run->spec, ExperimentOf(*run))) return true;
  return false;
}

double WidthSum(const RunMetrics& m) { return CorridorWidth(m, "x") + CorridorWidth(m, "y"); }

// quantity: consistency (the lowest share of post-localized states holding
// the truth, each configuration and w pooled over its seeds: 1 means every
// state) or width_ratio (the highest post-localized over real-time mean
// corridor width, x plus y).
Measurement MeasurePostLocalization(const YAML::Node& measure, const ClaimContext& context) {
  const std::string quantity = measure["quantity"] ? measure["quantity"].as<std::string>() : "";
  if (quantity != "consistency" && quantity != "width_ratio")
    throw ClaimsError("post_localization needs 'quantity': consistency or width_ratio");
  const std::vector<RunSelector> selectors = SelectorsOf(measure);
  Measurement m;
  int points = 0;
  std::string which;
  const auto& all_points = Cached<std::vector<PostLocalizationPoint>>(
      context, "paper004/post_localization",
      [&] {
        std::vector<PostLocalizationPoint> points = Paper004PostLocalization(context.runs);
        for (PostLocalizationPoint& p : Paper004RepeatPostLocalization(context.runs))
          points.push_back(std::move(p));
        return points;
      });
  for (const PostLocalizationPoint& p : all_points) {
    if (!Picks(selectors, p.point)) continue;
    const double v = quantity == "consistency" ? p.post.consistency_rate
                                               : WidthSum(p.post) / WidthSum(p.real_time);
    if (std::isnan(v)) continue;
    ++points;
    const bool worse = quantity == "consistency" ? v < m.value : v > m.value;
    if (std::isnan(m.value) || worse)
      m.value = v, which = p.point.label + ", w = " + FormatNumber(p.point.value);
  }
  if (points == 0) {
    m.missing = MissingRuns(context, selectors.front());
    return m;
  }
  m.text = std::string(quantity == "consistency" ? "lowest " : "highest ") +
           FormatNumber(m.value) + " (" + which + ") over " + std::to_string(points) +
           " configurations and w";
  return m;
}

}  // namespace

void AddPaper004ClaimFunctions(ClaimFunctions* functions) {
  functions->measures["post_localization"] = MeasurePostLocalization;
}

}  // namespace icp
