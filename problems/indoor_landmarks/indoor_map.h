// An indoor map for paper 002 (§3.1): walls, the segments that block the
// sensor, and typed point landmarks (corner, edge, other), each landmark's
// identity its row order (0, 1, ...). A CSV file:
//   # comment lines and blank lines are ignored
//   kind,x1,y1,x2,y2
//   wall,0,0,3,0          a wall segment, metres
//   corner,3,-0.3         a typed landmark (corner, edge or other), metres
// The shipped map is the end of a corridor (data/corridor_end.csv).
#ifndef ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_MAP_H_
#define ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_MAP_H_

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

#include "core/box.h"
#include "core/view.h"

namespace icp {

// The landmark types, in TypedLandmark::type order.
inline const std::vector<std::string> kIndoorLandmarkTypes = {"corner", "edge", "other"};

struct IndoorMap {
  std::vector<std::array<double, 4>> walls;  // x1, y1, x2, y2
  std::vector<TypedLandmark> landmarks;      // id = index
  // The bounds of every wall end and landmark, x then y.
  Box Bounds() const;
};

// Throws std::invalid_argument naming source and line.
IndoorMap ReadIndoorMap(std::istream& in, const std::string& source);
IndoorMap ReadIndoorMap(const std::string& path);
std::string ShippedCorridorMapPath();

// Whether the segment from (ax, ay) to (bx, by) crosses a wall (touching a
// wall's end counts as crossing).
bool CrossesWall(const IndoorMap& map, double ax, double ay, double bx, double by);
// The distance from (x, y) to the nearest wall, m.
double DistanceToWalls(const IndoorMap& map, double x, double y);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_MAP_H_
