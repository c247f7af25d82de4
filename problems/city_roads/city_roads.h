// The city-roads problem (paper 003 §4.8.7, Fig. 4.17): a car localized in a
// city without GPS, from its speed (the speed panel or the CAN bus) and a
// magnetic compass, both with bounded errors, and the road map as a binary
// image: "the vehicle is on the road", through the image contractor. The
// state is the position (x, y) in metres; motion from step k to k + 1 is
//   x_k+1 = x_k + v_k cos(th_k) dt,   y_k+1 = y_k + v_k sin(th_k) dt
// with [v_k] = speed reading ± speed_error and [th_k] = compass reading ±
// compass_error. The start is known to ± start_error.
//
// The map (data/city.png, frame in data/city.yaml, drawn by DrawCityMap and
// written by the `city_map` tool): a 300 m square at 1 m per pixel, six
// 10 m wide streets each way (centre lines at 25, 75, ..., 275 m), set
// pixels on the roads. The simulator drives a closed 1500 m route along the
// centre lines at speed ± 10 % (a new speed each step), each step a straight
// chord between two points of the route, so every true position is on a
// road. Every reading lies within 0.9 of its bound of the truth.
//
// Views of step k (with roads=false the map is left out of all three: dead
// reckoning alone):
//   - CSP: the motion constraints over the window of states max(0, k - w)..
//     k (2 per motion), domains the map's bounds (state 0: the start box),
//     and one image contractor per state in extra_contractors;
//   - measurement set: prior = the map's bounds (step 0: the start box),
//     one measurement, the road map (never an outlier); predict = previous
//     box + the motion's displacement interval;
//   - probabilistic: motion drawn uniformly within the readings' bounds; the
//     likelihood of a position is 1 on a road and falls off with the
//     distance to the nearest road pixel (sigma 1 m, floor 0.01).
#ifndef ICPBENCH_PROBLEMS_CITY_ROADS_CITY_ROADS_H_
#define ICPBENCH_PROBLEMS_CITY_ROADS_CITY_ROADS_H_

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/image_contractor.h"
#include "core/params.h"
#include "problems/problem.h"

namespace icp {

struct CityRoadsParams {
  // Number of steps (the 1500 m route is driven in about 150 at the default
  // speed, then again).
  int steps = 150;
  // Time step, s.
  double dt = 1;
  // Mean speed of the car, m/s; it varies by ±10 % from step to step.
  double speed = 10;
  // Half-width of the speed reading, m/s.
  double speed_error = 0.5;
  // Half-width of the compass reading, rad.
  double compass_error = 0.05;
  // Half-width of the known start box on x and y, m.
  double start_error = 2;
  // Window length of the CSP view, in steps (2w motion constraints).
  int w = 5;
  // Whether the car is known to be on the roads (the image contractor);
  // false: dead reckoning alone (Fig. 4.17 (a)).
  bool roads = true;
};
void Describe(CityRoadsParams& p, ParamSet& set);

// The shipped map's frame.
inline constexpr double kCityPixelSize = 1;  // m
inline constexpr double kCitySide = 300;     // m
// The shipped map: CV_8UC1, 255 on roads, row 0 the northern edge.
cv::Mat DrawCityMap();
ImageFrame CityMapFrame();
std::string ShippedCityMapPath();

// The simulator's closed route along the street centre lines.
std::vector<std::vector<double>> CityRoute();

// One step of a drive: the true position, and the readings for the motion
// to the next step.
struct CityRecord {
  double truth_x = 0, truth_y = 0;
  double speed = 0;    // m/s, reading
  double heading = 0;  // rad, compass reading, counterclockwise from x (east)
};
std::vector<CityRecord> SimulateCityRoads(const CityRoadsParams& params, std::uint64_t seed);

ParamMap ResolveCityRoads(const std::string& owner, const ParamMap& values);
std::unique_ptr<Problem> MakeCityRoads(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_CITY_ROADS_CITY_ROADS_H_
