#include "problems/indoor_landmarks/indoor_map.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <istream>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "problems/log_file.h"

namespace icp {

namespace {

constexpr double kMaxCoordinate = 1e9;  // m

constexpr const char* kHeader = "kind,x1,y1,x2,y2";

// Cross product of (b - a) and (c - a).
double Orientation(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

double PointSegmentDistance(double x, double y, const std::array<double, 4>& w) {
  const double dx = w[2] - w[0], dy = w[3] - w[1];
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((x - w[0]) * dx + (y - w[1]) * dy) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(x - (w[0] + t * dx), y - (w[1] + t * dy));
}
}  // namespace

Box IndoorMap::Bounds() const {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  auto add = [&](double x, double y) {
    lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
    lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
  };
  for (const auto& w : walls) add(w[0], w[1]), add(w[2], w[3]);
  for (const TypedLandmark& l : landmarks) add(l.x, l.y);
  return Box({Interval(lo[0], hi[0]), Interval(lo[1], hi[1])});
}

IndoorMap ReadIndoorMap(std::istream& in, const std::string& source) {
  IndoorMap map;
  ReadCsvRows(in, source, kHeader,
              [&](const std::vector<std::string_view>& fields, const CsvRowError& fail) {
    const std::string kind(fields[0]);
    const auto type = std::find(kIndoorLandmarkTypes.begin(), kIndoorLandmarkTypes.end(), kind);
    if (kind != "wall" && type == kIndoorLandmarkTypes.end())
      throw fail("kind must be wall, corner, edge or other");
    const std::size_t expected = kind == "wall" ? 5 : 3;
    if (fields.size() != expected)
      throw fail("a " + kind + " row has " + std::to_string(expected) + " fields, found " +
                 std::to_string(fields.size()));
    double v[4] = {0, 0, 0, 0};
    for (std::size_t i = 1; i < fields.size(); ++i) {
      const std::string_view f = fields[i];
      auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v[i - 1]);
      if (ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v[i - 1]))
        throw fail("field " + std::to_string(i + 1) + " is not a finite number");
      // As the other readers' positions: past this, the geometry's doubles
      // (line of sight, distance to a wall) lose the corridor's centimetres.
      if (std::fabs(v[i - 1]) > kMaxCoordinate)
        throw fail("field " + std::to_string(i + 1) + " is beyond +-1e9 m");
    }
    if (kind == "wall") {
      if (v[0] == v[2] && v[1] == v[3]) throw fail("a wall of zero length");
      map.walls.push_back({v[0], v[1], v[2], v[3]});
    } else {
      map.landmarks.push_back({static_cast<int>(map.landmarks.size()),
                               static_cast<int>(type - kIndoorLandmarkTypes.begin()), v[0], v[1]});
    }
  });
  if (map.landmarks.empty()) throw std::invalid_argument(source + ": no landmark");
  return map;
}

IndoorMap ReadIndoorMap(const std::string& path) {
  std::ifstream in = OpenLogFile(path, "indoor map");
  return ReadIndoorMap(in, path);
}

std::string ShippedCorridorMapPath() {
  return std::string(ICPBENCH_INDOOR_LANDMARKS_DATA) + "/corridor_end.csv";
}

bool CrossesWall(const IndoorMap& map, double ax, double ay, double bx, double by) {
  for (const auto& w : map.walls) {
    const double o1 = Orientation(ax, ay, bx, by, w[0], w[1]);
    const double o2 = Orientation(ax, ay, bx, by, w[2], w[3]);
    const double o3 = Orientation(w[0], w[1], w[2], w[3], ax, ay);
    const double o4 = Orientation(w[0], w[1], w[2], w[3], bx, by);
    if (o1 * o2 <= 0 && o3 * o4 <= 0) {
      // Collinear: they cross only if they overlap.
      if (o1 == 0 && o2 == 0) {
        const bool apart = std::max(ax, bx) < std::min(w[0], w[2]) ||
                           std::max(w[0], w[2]) < std::min(ax, bx) ||
                           std::max(ay, by) < std::min(w[1], w[3]) ||
                           std::max(w[1], w[3]) < std::min(ay, by);
        if (apart) continue;
      }
      return true;
    }
  }
  return false;
}

double DistanceToWalls(const IndoorMap& map, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& w : map.walls) best = std::min(best, PointSegmentDistance(x, y, w));
  return best;
}

}  // namespace icp
