#include "problems/registry.h"

#include <stdexcept>

#include "core/near_names.h"
#include "problems/beacon_ranges/beacon_ranges.h"
#include "problems/car_track/car_track.h"
#include "problems/chain/chain.h"
#include "problems/city_roads/city_roads.h"
#include "problems/indoor_landmarks/indoor_landmarks.h"
#include "problems/line_intersection/line_intersection.h"
#include "problems/marina_sonar/marina_sonar.h"
#include "problems/minibex_file/minibex_file.h"
#include "problems/visual_landmarks/visual_landmarks.h"

namespace icp {

namespace {
std::deque<ProblemInfo>& Table() {
  static std::deque<ProblemInfo> table = {
      {"car-track", "a simulated lap (or a CSV log) of the car-track CSP, paper 000 eq. 9-14, window w",
       &MakeCarTrack, &DefaultParams<CarTrackParams>, &ResolveCarTrack,
       {View::kCsp, View::kProbabilistic}, &NoteCarTrack},
      {"chain", "car-track-shaped window CSP (paper 000 eq. 14) with a simulated truth",
       &MakeChain, &DefaultParams<ChainParams>, &ResolveParams<ChainParams>, {View::kCsp}},
      {"minibex-file", "one CSP read from a Minibex file (IBEX benchmark syntax)",
       &MakeMinibexFile, &DefaultParams<MinibexFileParams>, &ResolveMinibexFile,
       {View::kCsp, View::kMeasurementSet}},
      {"line-intersection", "m lines through one point, k of them outliers, paper 003 §5.1.4 (Fig. 5.2)",
       &MakeLineIntersection, &DefaultParams<LineIntersectionParams>, &ResolveLineIntersection,
       {View::kCsp, View::kMeasurementSet}},
      {"beacon-ranges", "ranges to known beacons, some outliers, paper 003 §5.2.3 (eq. 5.39, Figs. 5.5-5.7)",
       &MakeBeaconRanges, &DefaultParams<BeaconRangesParams>, &ResolveBeaconRanges,
       {View::kCsp, View::kMeasurementSet, View::kProbabilistic}},
      {"marina-sonar", "an AUV in a marina with DVL, compass and a sector-scan sonar on a binary map, paper 003 ch. 6 (eq. 6.8)",
       &MakeMarinaSonar, &DefaultParams<MarinaSonarParams>, &ResolveMarinaSonar,
       {View::kCsp, View::kMeasurementSet, View::kProbabilistic}, &NoteMarinaSonar},
      {"city-roads", "a car in a city without GPS: speed, compass and the road map through the image contractor, paper 003 §4.8.7 (Fig. 4.17)",
       &MakeCityRoads, &DefaultParams<CityRoadsParams>, &ResolveCityRoads,
       {View::kCsp, View::kMeasurementSet, View::kProbabilistic}},
      {"visual-landmarks", "a car with a camera mapping landmarks as interval cones (teach) and localizing on the map (repeat), paper 004",
       &MakeVisualLandmarks, &DefaultParams<VisualLandmarksParams>, &ResolveVisualLandmarks,
       {View::kCsp}},
      {"indoor-landmarks", "a robot at a corridor's end with wheel odometry and typed range-bearing returns to associate with a map, paper 002",
       &MakeIndoorLandmarks, &DefaultParams<IndoorLandmarksParams>, &ResolveIndoorLandmarks,
       {View::kLandmarkObservations, View::kMeasurementSet, View::kProbabilistic}},
  };
  return table;
}
}  // namespace

const std::deque<ProblemInfo>& Problems() { return Table(); }

const ProblemInfo& FindProblem(const std::string& name) {
  std::string known;
  std::vector<std::string> names;
  for (const ProblemInfo& p : Problems()) {
    if (p.name == name) return p;
    known += (known.empty() ? "" : ", ") + p.name;
    names.push_back(p.name);
  }
  throw std::invalid_argument("unknown problem '" + name + "'" + DidYouMean(name, names) +
                              " (known: " + known + ")");
}

std::vector<Step> ProblemSteps(const std::string& name, const ParamMap& params, std::uint64_t seed) {
  std::unique_ptr<Problem> problem = FindProblem(name).make(params, seed);
  std::vector<Step> steps;
  Step step;
  while (problem->Next(&step)) steps.push_back(std::move(step));
  return steps;
}

void RegisterProblem(ProblemInfo info) {
  for (const ProblemInfo& p : Problems())
    if (p.name == info.name)
      throw std::invalid_argument("problem '" + info.name + "' is already registered");
  // Its parameters are declared now, so that a name declared twice or one
  // that cannot be written (ParamError) refuses the problem, not every run.
  if (info.params != nullptr) info.params(info.name);
  Table().push_back(std::move(info));
}

}  // namespace icp
