#include "problems/indoor_landmarks/indoor_drive.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "core/random.h"

namespace icp {

void Describe(IndoorLandmarksParams& p, ParamSet& set) {
  set.Add("path", &p.path, "the drive: a, b (the paper's two 46-acquisition paths) or random",
          {"a", "b", "random"});
  set.Add("steps", &p.steps, "number of acquisitions (at most 46 on paths a and b)",
          Range::Closed(1, 100000));
  set.Add("map", &p.map, "map file (walls and typed landmarks); empty: the shipped corridor end");
  set.Add("wheel_radius", &p.wheel_radius, "nominal wheel radius, m", Range::Positive(1));
  set.Add("radius_error", &p.radius_error, "error bound of each wheel's radius, m",
          Range::Positive(0.1));
  set.Add("track", &p.track, "nominal track width, m", Range::Positive(10));
  set.Add("track_error", &p.track_error, "error bound of the track width, m", Range::Positive(1));
  set.Add("rotation_error", &p.rotation_error, "error bound of a wheel's rotation over a step, rad",
          Range::Positive(10));
  set.Add("range_error", &p.range_error, "error bound of a return's range, m", Range::Positive(10));
  set.Add("bearing_error", &p.bearing_error, "error bound of a return's bearing, rad",
          Range::Positive(1));
  set.Add("max_range", &p.max_range, "the sensor's range, m", Range::Positive(1000));
  set.Add("fov", &p.fov, "the sensor's field of view, deg, centred on the heading",
          Range{0, 360, true, false});
  set.Add("spurious_rate", &p.spurious_rate, "mean number of spurious returns per acquisition",
          Range::Closed(0, 100));
  set.Add("dropout_rate", &p.dropout_rate, "probability that a landmark in sight is not returned",
          Range::HalfOpen(0, 1));
  set.Add("start_error", &p.start_error, "half-width of the known start box on x and y, m",
          Range::Positive(100));
  set.Add("start_heading_error", &p.start_heading_error,
          "half-width of the known start heading, rad", Range::Positive(std::numbers::pi));
}

namespace {

constexpr double kStepLength = 0.30;   // m between acquisitions (paper 002 §4)
constexpr int kPaperAcquisitions = 46;
constexpr int kStraightSteps = 35;     // paths a and b: 35 moves, then 10 turning
constexpr double kTurnStep = std::numbers::pi / 20;  // 9 deg: 90 deg over 10 steps
constexpr double kWallMargin = 0.4;    // m: the random drive keeps this far from walls
constexpr double kMaxWander = 0.2;     // rad: the random drive's turn a step
constexpr double kGhostMin = 0.05, kGhostMax = 0.25;  // m: a ghost's offset
constexpr double kMeasured = 0.9;      // a reading's error within this share of its bound
constexpr double kStartX = 0.8;        // m: every path starts here, heading along x

struct Motion {
  double d = 0, turn = 0;
};

// Eq. 2-4: the pose after a motion.
void Move(double& x, double& y, double& heading, const Motion& m) {
  x += m.d * std::cos(heading + m.turn / 2);
  y += m.d * std::sin(heading + m.turn / 2);
  heading += m.turn;
}

std::vector<Motion> PaperPath(int steps, double turn) {
  std::vector<Motion> motions;
  for (int k = 1; k < steps; ++k)
    motions.push_back({kStepLength, k <= kStraightSteps ? 0.0 : turn});
  return motions;
}

// Whether (x, y) lies within the map's bounds (map.Bounds(), computed once
// by the caller) and kWallMargin or more from every wall.
bool Free(const IndoorMap& map, const Box& bounds, double x, double y) {
  return bounds[0].Contains(x) && bounds[1].Contains(y) && DistanceToWalls(map, x, y) >= kWallMargin;
}

// A random drive from (x, y, heading): each step turns by up to kMaxWander,
// or by more (alternating sides, up to a half-turn) when that step would
// come within kWallMargin of a wall or cross one.
std::vector<Motion> RandomPath(const IndoorMap& map, int steps, double x, double y, double heading,
                               RandomEngine& rng) {
  const Box bounds = map.Bounds();
  std::vector<Motion> motions;
  for (int k = 1; k < steps; ++k) {
    const double wander = UniformReal(rng, -kMaxWander, kMaxWander);
    Motion chosen{kStepLength, wander};
    for (int attempt = 0; attempt < 16; ++attempt) {
      const double extra = (attempt + 1) / 2 * (std::numbers::pi / 8) * (attempt % 2 == 0 ? 1 : -1);
      Motion m{kStepLength, wander + extra};
      double nx = x, ny = y, nh = heading;
      Move(nx, ny, nh, m);
      if (Free(map, bounds, nx, ny) && !CrossesWall(map, x, y, nx, ny)) {
        chosen = m;
        break;
      }
      if (attempt == 15) chosen = Motion{0, std::numbers::pi / 2};  // boxed in: turn on the spot
    }
    Move(x, y, heading, chosen);
    motions.push_back(chosen);
  }
  return motions;
}

// x within kMeasured of e around the truth, and the interval of half-width
// e around the reading.
Interval Read(double truth, double e, RandomEngine& rng) {
  const double reading = truth + UniformReal(rng, -kMeasured, kMeasured) * e;
  return Interval(reading) + Interval(-e, e);
}

double WrapAngle(double a) { return std::remainder(a, 2 * std::numbers::pi); }

struct Return {
  PolarObservation observation;
  int identity = -1;
  double bearing = 0;  // the true bearing, for the order
};

Return Sight(const IndoorLandmarksParams& p, double x, double y, double heading, double lx,
             double ly, int type, int identity, RandomEngine& rng) {
  const double range = std::hypot(lx - x, ly - y);
  const double bearing = WrapAngle(std::atan2(ly - y, lx - x) - heading);
  Return r;
  r.observation.type = type;
  r.observation.range = Read(range, p.range_error, rng);
  r.observation.bearing = Read(bearing, p.bearing_error, rng);
  r.identity = identity;
  r.bearing = bearing;
  return r;
}

void Observe(const IndoorLandmarksParams& p, const IndoorMap& map, IndoorRecord& record,
             RandomEngine& rng) {
  const double half_fov = p.fov / 2 * std::numbers::pi / 180;
  std::vector<Return> returns;
  std::vector<const TypedLandmark*> visible;
  for (const TypedLandmark& l : map.landmarks) {
    const double dx = l.x - record.x, dy = l.y - record.y;
    const double range = std::hypot(dx, dy);
    if (range > p.max_range || range < 1e-3) continue;
    if (std::abs(WrapAngle(std::atan2(dy, dx) - record.heading)) > half_fov) continue;
    // The line of sight up to 2 cm short of the landmark, which sits on walls' ends.
    const double stop = (range - 0.02) / range;
    if (CrossesWall(map, record.x, record.y, record.x + stop * dx, record.y + stop * dy)) continue;
    visible.push_back(&l);
    if (UniformReal(rng, 0, 1) < p.dropout_rate) continue;
    returns.push_back(Sight(p, record.x, record.y, record.heading, l.x, l.y, l.type, l.id, rng));
  }
  const int whole = static_cast<int>(std::floor(p.spurious_rate));
  const int ghosts = whole + (UniformReal(rng, 0, 1) < p.spurious_rate - whole ? 1 : 0);
  for (int g = 0; g < ghosts && !visible.empty(); ++g) {
    const TypedLandmark& of = *visible[UniformIndex(rng, visible.size())];
    const double offset = UniformReal(rng, kGhostMin, kGhostMax);
    const double direction = UniformReal(rng, -std::numbers::pi, std::numbers::pi);
    returns.push_back(Sight(p, record.x, record.y, record.heading,
                            of.x + offset * std::cos(direction), of.y + offset * std::sin(direction),
                            of.type, -1, rng));
  }
  std::stable_sort(returns.begin(), returns.end(),
                   [](const Return& a, const Return& b) { return a.bearing < b.bearing; });
  for (const Return& r : returns) {
    record.observations.push_back(r.observation);
    record.identities.push_back(r.identity);
  }
}

double StartY(const IndoorLandmarksParams& p) { return p.path == "b" ? 1.15 : 0.85; }

}  // namespace

void CheckIndoorStart(const IndoorLandmarksParams& p, const IndoorMap& map) {
  if (!Free(map, map.Bounds(), kStartX, StartY(p)))
    throw ParamError("indoor-landmarks.map: the start (" + FormatDouble(kStartX) + ", " +
                     FormatDouble(StartY(p)) + ") of path " + p.path + " is off the map or within " +
                     FormatDouble(kWallMargin) + " m of a wall");
}

std::vector<IndoorRecord> SimulateIndoorDrive(const IndoorLandmarksParams& p, const IndoorMap& map,
                                              std::uint64_t seed) {
  if (p.path != "random" && p.steps > kPaperAcquisitions)
    throw ParamError("indoor-landmarks.steps = " + std::to_string(p.steps) + ": path " + p.path +
                     " has " + std::to_string(kPaperAcquisitions) + " acquisitions");
  CheckIndoorStart(p, map);
  RandomEngine rng(seed);
  double x = kStartX, y = StartY(p), heading = 0;
  const std::vector<Motion> motions =
      p.path == "a"   ? PaperPath(p.steps, kTurnStep)
      : p.path == "b" ? PaperPath(p.steps, -kTurnStep)
                      : RandomPath(map, p.steps, x, y, heading, rng);
  // The true wheels of this robot.
  const double right = p.wheel_radius + UniformReal(rng, -kMeasured, kMeasured) * p.radius_error;
  const double left = p.wheel_radius + UniformReal(rng, -kMeasured, kMeasured) * p.radius_error;
  const double track = p.track + UniformReal(rng, -kMeasured, kMeasured) * p.track_error;
  const Interval radius_bound(-p.radius_error, p.radius_error);
  std::vector<IndoorRecord> records(p.steps);
  for (int k = 0; k < p.steps; ++k) {
    IndoorRecord& r = records[k];
    if (k > 0) {
      const Motion& m = motions[k - 1];
      Move(x, y, heading, m);
      WheelOdometry& o = r.odometry;
      o.right_radius = Interval(p.wheel_radius) + radius_bound;
      o.left_radius = Interval(p.wheel_radius) + radius_bound;
      o.track = Interval(p.track) + Interval(-p.track_error, p.track_error);
      o.right_rotation = Read((m.d + m.turn * track / 2) / right, p.rotation_error, rng);
      o.left_rotation = Read((m.d - m.turn * track / 2) / left, p.rotation_error, rng);
    }
    r.x = x;
    r.y = y;
    r.heading = heading;
    Observe(p, map, r, rng);
  }
  return records;
}

}  // namespace icp
