#include "experiments/thesis003/city_roads.h"

#include <limits>
#include <utility>

#include "harness/spec.h"
#include "problems/city_roads/city_roads.h"
#include "report/report.h"

namespace icp {

namespace {

// The x-y area of a run's last step, or NaN.
double LastArea(const RunRecord& r) {
  return r.steps.empty() ? std::numeric_limits<double>::quiet_NaN() : r.steps.back().area;
}

}  // namespace

const RunRecord* CityRoadsRun(const std::vector<RunRecord>& runs, bool roads) {
  const RunRecord* best = nullptr;
  for (const RunRecord& r : runs) {
    if (r.status != RunStatus::kOk || r.spec.algorithm != "hc4" ||
        ExperimentOf(r) != kThesis003CityRoads || r.spec.problem != "city-roads")
      continue;
    ParamMap params = r.spec.problem_params;
    const ParamMap defaults = ProblemDefaults("city-roads");
    if (!params.count("roads")) params["roads"] = defaults.at("roads");
    if ((params["roads"] == "true") != roads) continue;
    if (!best || r.spec.seed < best->spec.seed) best = &r;
  }
  return best;
}

void CityRoadsFigure(const std::vector<RunRecord>& runs, const std::string& out_dir,
                     PlotOutput* out) {
  FigureText text{"fig4_17_city_roads", "", ""};
  const RunRecord* dead_reckoning = CityRoadsRun(runs, false);
  const RunRecord* roads = CityRoadsRun(runs, true);
  if (!dead_reckoning || !roads) {
    text.skip_reason = std::string("no ok HC4 run of experiment ") + kThesis003CityRoads +
                       " with " + (!dead_reckoning ? "roads=false" : "") +
                       (!dead_reckoning && !roads ? " and " : "") + (!roads ? "roads=true" : "");
    return SkipFigure(text, {}, out);
  }
  const cv::Mat map = DrawCityMap();
  std::vector<std::pair<double, double>> roads_points;
  // The roads' edges only (a road pixel beside a block): the figure stays
  // small and the boxes visible.
  const auto road = [&](int r, int c) {
    return r < 0 || c < 0 || r >= map.rows || c >= map.cols || map.at<unsigned char>(r, c);
  };
  for (int r = 0; r < map.rows; ++r)
    for (int c = 0; c < map.cols; ++c)
      if (map.at<unsigned char>(r, c) &&
          !(road(r - 1, c) && road(r + 1, c) && road(r, c - 1) && road(r, c + 1)))
        roads_points.push_back({(c + 0.5) * kCityPixelSize, (map.rows - r - 0.5) * kCityPixelSize});
  text.title = "Fig. 4.17: a car in the city without GPS (" + RunLabel(*roads) + ")";
  const Interval side(0, kCitySide);
  PlotBoxTrackFigure(
      text, roads_points,
      {{"(a) speed and compass alone: last box " + FormatNumber(LastArea(*dead_reckoning)) +
            " m²",
        dead_reckoning},
       {"(b) on the roads (image contractor): last box " + FormatNumber(LastArea(*roads)) +
            " m²",
        roads}},
      side, side, out_dir, out);
}

}  // namespace icp
