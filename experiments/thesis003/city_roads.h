// Thesis 003 Fig. 4.17 (§4.8.7): a car in a city without GPS, localized from
// its speed and compass by dead reckoning (a), then with the road map
// through the image contractor (b). The runs are those of experiment
// city-roads (specs/default.yaml): every ICP algorithm, the relaxed solver
// and the particle filter on problem city-roads with roads=true and false.
// The figure draws the HC4 run of each (the ok one with the smallest seed).
#ifndef ICPBENCH_EXPERIMENTS_THESIS003_CITY_ROADS_H_
#define ICPBENCH_EXPERIMENTS_THESIS003_CITY_ROADS_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "plots/figures.h"

namespace icp {

inline constexpr char kThesis003CityRoads[] = "city-roads";

// The ok HC4 run of experiment city-roads with roads (true: the road map;
// false: dead reckoning) with the smallest seed; nullptr when none.
const RunRecord* CityRoadsRun(const std::vector<RunRecord>& runs, bool roads);

// The figure fig4_17_city_roads: dead-reckoning boxes against map-
// constrained boxes along the route, on the map; skipped with a message
// naming the runs it lacks.
void CityRoadsFigure(const std::vector<RunRecord>& runs, const std::string& out_dir,
                     PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_THESIS003_CITY_ROADS_H_
