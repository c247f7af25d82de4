// A landmark map (paper 004 §4.1): what a teach run leaves for repeat, each
// landmark's position box by identity. A CSV file:
//   # comment lines and blank lines are ignored
//   landmark,x_lo,x_hi,y_lo,y_hi,z_lo,z_hi
//   0,11.93,12.08,2.95,3.04,1.97,2.03
// one row per landmark, identities distinct non-negative integers, bounds in
// metres with lo <= hi (finite). `icpbench map` writes one from a teach run
// in a results store (docs/reproduction/paper004.md).
#ifndef ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_LANDMARK_MAP_H_
#define ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_LANDMARK_MAP_H_

#include <array>
#include <iosfwd>
#include <map>
#include <string>

#include "core/interval.h"

namespace icp {

using LandmarkMap = std::map<int, std::array<Interval, 3>>;

// Throws std::invalid_argument naming source and line.
LandmarkMap ReadLandmarkMap(std::istream& in, const std::string& source);
LandmarkMap ReadLandmarkMap(const std::string& path);
// Bounds as the shortest text that reads back to the same double, after '#'
// lines holding comment, if any.
void WriteLandmarkMap(const LandmarkMap& map, std::ostream& out, const std::string& comment = "");

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_LANDMARK_MAP_H_
