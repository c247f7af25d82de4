#include "problems/visual_landmarks/visual_landmarks.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>

#include "problems/car_track/window.h"
#include "problems/visual_landmarks/feature_log.h"

namespace icp {

void Describe(VisualLandmarksParams& p, ParamSet& set) {
  set.Add("phase", &p.phase, "teach (GPS, landmarks mapped) or repeat (no GPS, a landmark map)",
          {"teach", "repeat"});
  set.Add("w", &p.w, "window Xi in steps (eq. 26)", Range::Closed(1, 10000));
  set.Add("route", &p.route, "straight (paper 004 §5.1) or loop (about 183 m, Fig. 12)",
          {"straight", "loop"});
  set.Add("steps", &p.steps, "number of steps", Range::Closed(1, 1e6));
  set.Add("dt", &p.dt, "time step, s", Range::Positive(3600));
  set.Add("speed", &p.speed, "speed, m/s", Range::Positive(100));
  set.Add("landmarks", &p.landmarks,
          "how many landmarks (the straight route's first five are the paper's)",
          Range::Closed(1, 100000));
  set.Add("layout_seed", &p.layout_seed, "seed of the drawn landmarks (the map, not the drive)",
          Range::Closed(0, 2147483647));
  set.Add("pixel_error", &p.pixel_error, "half-width of a pixel box, px", Range::Positive(1000));
  set.Add("odometry_error", &p.odometry_error, "half-width of [delta s], m per step",
          Range::Positive(100));
  set.Add("gyro_error", &p.gyro_error, "half-width of [delta theta], rad per step",
          Range::Positive(10));
  set.Add("gps_error", &p.gps_error, "half-width of a GPS box (teach) and of the start fix, m",
          Range::Positive(1e6));
  set.Add("heading_error", &p.heading_error, "half-width of the known start heading, rad",
          Range::Closed(0, 4));
  set.Add("focal", &p.focal, "focal length fk_u = fk_v, px", Range::Positive(1e6));
  set.Add("cu", &p.cu, "principal point u, px", Range::Closed(0, 1e6));
  set.Add("cv", &p.cv, "principal point v, px", Range::Closed(0, 1e6));
  set.Add("image_width", &p.image_width, "image width, px", Range::Closed(1, 1e6));
  set.Add("image_height", &p.image_height, "image height, px", Range::Closed(1, 1e6));
  set.Add("camera_height", &p.camera_height, "optical centre above the ground, m",
          Range::Closed(0, 1000));
  set.Add("map", &p.map, "repeat: a landmark map file (icpbench map); empty: a surveyed map");
  set.Add("map_error", &p.map_error, "repeat without a map file: the surveyed map's half-width, m",
          Range::Closed(0, 1e6));
  set.Add("min_parallax", &p.min_parallax,
          "teach: the map metrics score the landmarks whose first and last rays part by this, deg",
          Range::Closed(0, 180));
  set.Add("log", &p.log,
          "a feature-track log replacing the simulator (feature_log.h); empty: simulate");
  set.Add("observation", &p.observation,
          "each sighting on the cone and the position (both) or on the cone alone (the paper's form)",
          {"both", "cone"});
}

ParamMap ResolveVisualLandmarks(const std::string& owner, const ParamMap& values) {
  const auto p = ParseParams<VisualLandmarksParams>(owner, values);
  if (!p.map.empty() && p.phase != "repeat")
    throw ParamError(owner + ".map: only a repeat run reads a map");
  // The files are read here, so that a bad one stops the spec with its line
  // and key, not every run. A map that does not exist yet is read when a
  // run starts: an earlier command may write it (scripts/main.sh: teach,
  // icpbench map, then repeat).
  try {
    if (!p.log.empty()) ReadFeatureLog(p.log);
    std::error_code ec;
    if (!p.map.empty() && std::filesystem::symlink_status(p.map, ec).type() != std::filesystem::file_type::not_found)
      ReadLandmarkMap(p.map);
  } catch (const std::invalid_argument& e) {
    throw ParamError(owner + ": " + e.what());
  }
  return ResolveParams<VisualLandmarksParams>(owner, values);
}

VisualDriveParams DriveParams(const VisualLandmarksParams& p) {
  VisualDriveParams d;
  d.route = p.route;
  d.steps = p.steps;
  d.dt = p.dt;
  d.speed = p.speed;
  d.landmarks = p.landmarks;
  d.layout_seed = static_cast<std::uint64_t>(p.layout_seed);
  d.pixel_error = p.pixel_error;
  d.odometry_error = p.odometry_error;
  d.gyro_error = p.gyro_error;
  d.gps_error = p.gps_error;
  d.camera = {p.focal, p.cu, p.cv, p.image_width, p.image_height, p.camera_height};
  return d;
}

namespace {

const char* const kComponentNames[kLandmarkComponents] = {"xc",  "yc", "zc", "alpha", "phi",
                                                           "d",   "x",  "y",  "z"};

// The true cone parameters of a landmark first seen from pose (in the
// heading's unwrapped frame, as InitialCone computes alpha).
std::array<double, kLandmarkComponents> TrueCone(const std::array<double, 3>& pose,
                                                 const std::array<double, 3>& landmark,
                                                 double height) {
  const double dx = landmark[0] - pose[0], dy = landmark[1] - pose[1], dz = landmark[2] - height;
  const double ahead = dx * std::cos(pose[2]) + dy * std::sin(pose[2]);
  const double right = dx * std::sin(pose[2]) - dy * std::cos(pose[2]);
  return {pose[0],
          pose[1],
          height,
          pose[2] - std::atan(right / ahead),
          std::atan2(dz, std::hypot(dx, dy)),
          std::sqrt(dx * dx + dy * dy + dz * dz),
          landmark[0],
          landmark[1],
          landmark[2]};
}

}  // namespace

namespace {
bool Known(const std::array<double, 3>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}
}  // namespace

VisualLandmarksProblem::VisualLandmarksProblem(const VisualLandmarksParams& params,
                                               std::uint64_t seed)
    : params_(params), drive_params_(DriveParams(params)),
      drive_(params.log.empty() ? SimulateVisualDrive(drive_params_, seed)
                                : ReadFeatureLog(params.log)) {
  const int steps = NumSteps();
  const int count = static_cast<int>(drive_.landmarks.size());
  const CameraIntrinsics& camera = drive_params_.camera;
  const std::string source = params_.log.empty() ? "route " + params_.route : params_.log;
  // Pose domains: the start heading plus the gyro's sum; GPS (teach) or the
  // start fix and dead reckoning (repeat). A log without the first pose
  // starts from the whole circle and, in repeat, from its first GPS fix.
  const auto& start = drive_.poses[0];
  Interval heading = Known(start) ? Interval(start[2] - params_.heading_error,
                                             start[2] + params_.heading_error)
                                  : Interval(-Pi().hi(), Pi().hi());
  Interval x = drive_.steps[0].gps[0], y = drive_.steps[0].gps[1];
  if (Known(start)) {
    x = Interval(start[0] - params_.gps_error, start[0] + params_.gps_error);
    y = Interval(start[1] - params_.gps_error, start[1] + params_.gps_error);
  }
  if (!teach() && !(x.IsBounded() && y.IsBounded()))
    throw std::invalid_argument(source + ": repeat needs the first step's reference pose or a "
                                         "GPS fix to start from");
  for (int k = 0; k < steps; ++k) {
    const VisualDriveStep& s = drive_.steps[k];
    if (k > 0) {
      const Interval mid = heading + s.dtheta / 2.0;
      x = x + s.ds * Cos(mid);
      y = y + s.ds * Sin(mid);
      heading = heading + s.dtheta;
    }
    poses_.push_back(teach() ? Box{s.gps[0], s.gps[1], heading} : Box{x, y, heading});
  }
  first_sighting_.assign(count, -1);
  landmark_domains_.assign(count, Box(kLandmarkComponents));
  landmark_truth_.assign(count, {});
  truth_known_.assign(count, false);
  usable_.assign(count, false);
  if (teach()) {
    std::vector<int> last_sighting(count, -1);
    for (int k = 0; k < steps; ++k) {
      for (const LandmarkSighting& s : drive_.steps[k].sightings) {
        last_sighting[s.landmark] = k;
        if (first_sighting_[s.landmark] >= 0) continue;
        first_sighting_[s.landmark] = k;
        usable_[s.landmark] = true;
        landmark_domains_[s.landmark] = InitialCone(poses_[k], s.u, s.v, camera);
        if (!Known(drive_.poses[k]) || !Known(drive_.landmarks[s.landmark])) continue;
        truth_known_[s.landmark] = true;
        landmark_truth_[s.landmark] =
            TrueCone(drive_.poses[k], drive_.landmarks[s.landmark], camera.mount_height);
      }
    }
    for (int n = 0; n < count; ++n)
      if (truth_known_[n] && Parallax(n, last_sighting[n]) >= params_.min_parallax)
        scored_.push_back(n);
    return;
  }
  LandmarkMap map;
  if (params_.map.empty()) {
    const Interval e(-params_.map_error, params_.map_error);
    for (int n = 0; n < count; ++n) {
      const auto& l = drive_.landmarks[n];
      if (!Known(l))
        throw std::invalid_argument(source + ": landmark " + std::to_string(n) +
                                    " has no reference position for a surveyed map; give map");
      map[n] = {Interval(l[0]) + e, Interval(l[1]) + e, Interval(l[2]) + e};
    }
  } else {
    map = ReadLandmarkMap(params_.map);
  }
  for (const auto& [n, box] : map) {
    if (n >= count) {
      if (!params_.log.empty()) continue;  // a landmark the log never sees
      throw std::invalid_argument(params_.map + ": landmark " + std::to_string(n) + ", but route " +
                                  params_.route + " has " + std::to_string(count) +
                                  " (was the map taught with other landmarks or layout_seed?)");
    }
    const auto& l = drive_.landmarks[n];
    if (Known(l)) {
      for (int axis = 0; axis < 3; ++axis)
        if (!box[axis].Contains(l[axis]))
          throw std::invalid_argument(
              params_.map + ": landmark " + std::to_string(n) + "'s box does not hold its position on " +
              source + " (was it taught on another route or layout_seed, or by an unsound estimator?)");
      truth_known_[n] = true;
      landmark_truth_[n] = {l[0], l[1], l[2], 0, 0, 0, l[0], l[1], l[2]};
    }
    usable_[n] = true;
    landmark_domains_[n] = Box{box[0],        box[1], box[2], Interval(0.0), Interval(0.0),
                               Interval(0.0), box[0], box[1], box[2]};
  }
}

double VisualLandmarksProblem::Parallax(int n, int last) const {
  const auto& l = drive_.landmarks[n];
  auto ray = [&](int k) {
    const auto& p = drive_.poses[k];
    return std::array<double, 3>{l[0] - p[0], l[1] - p[1], l[2] - drive_params_.camera.mount_height};
  };
  const auto a = ray(first_sighting_[n]), b = ray(last);
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double cross = std::hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                  a[0] * b[1] - a[1] * b[0]);
  return std::atan2(cross, dot) * 180 / std::numbers::pi;
}

bool VisualLandmarksProblem::Next(Step* step) {
  if (k_ >= NumSteps()) return false;
  const int k = k_++;
  const int oldest = std::max(0, k - params_.w);
  std::vector<CarWindowState> states;
  for (int j = oldest; j <= k; ++j) {
    const VisualDriveStep& s = drive_.steps[j];
    states.push_back({poses_[j][0], poses_[j][1], poses_[j][2], s.ds, s.dtheta});
  }
  *step = Step();
  CspView view = BuildCarWindow(oldest, states);
  ConstraintSystem& csp = view.csp;
  for (int j = oldest + 1; j <= k; ++j) {
    const int first = 3 * (j - oldest - 1);
    view.icsps.push_back({j, true, {first, first + 1, first + 2}});
  }
  // The landmarks seen in the window, in identity order (StateRef's).
  std::set<int> seen;
  for (int j = oldest; j <= k; ++j)
    for (const LandmarkSighting& s : drive_.steps[j].sightings)
      if (usable_[s.landmark]) seen.insert(s.landmark);
  std::map<int, LandmarkExprs> landmark_exprs;
  std::map<int, std::vector<int>> cone_definition;  // eq. 12's constraints, per landmark
  for (int n : seen) {
    std::vector<Expr> vars;
    for (int c = 0; c < kLandmarkComponents; ++c) {
      vars.push_back(csp.AddVariable("L" + std::to_string(n) + "." + kComponentNames[c],
                                     landmark_domains_[n][c]));
      view.states.push_back(StateRef::Landmark(n, c));
    }
    const LandmarkExprs l{vars[0], vars[1], vars[2], vars[3], vars[4],
                          vars[5], vars[6], vars[7], vars[8]};
    const int before = static_cast<int>(csp.constraints().size());
    AddConeDefinition(csp, l);
    for (int c = before; c < before + 3; ++c) cone_definition[n].push_back(c);
    landmark_exprs.emplace(n, l);
  }
  const CameraIntrinsics& camera = drive_params_.camera;
  for (int j = oldest; j <= k; ++j) {
    const int base = 3 * (j - oldest);
    const PoseExprs pose{csp.Var(base), csp.Var(base + 1), csp.Var(base + 2)};
    for (const LandmarkSighting& s : drive_.steps[j].sightings) {
      if (!usable_[s.landmark]) continue;
      const LandmarkExprs& l = landmark_exprs.at(s.landmark);
      // Its ICSP: the observation, eq. 12 of its landmark, and the link to
      // the pose at the first sighting.
      CspView::Icsp icsp{j, false, cone_definition.at(s.landmark)};
      const int before = static_cast<int>(csp.constraints().size());
      if (teach() && first_sighting_[s.landmark] == j) {
        csp.AddConstraint(l.xc, Relation::kEq, pose.x);
        csp.AddConstraint(l.yc, Relation::kEq, pose.y);
      }
      AddObservation(csp, pose, l, s.u, s.v, camera, params_.observation == "both");
      for (int c = before; c < static_cast<int>(csp.constraints().size()); ++c)
        icsp.constraints.push_back(c);
      view.icsps.push_back(std::move(icsp));
    }
  }
  step->views.step = k;
  step->views.space = CarStateSpace();
  step->views.csp = std::move(view);
  if (Known(drive_.poses[k]))
    step->truth = {drive_.poses[k][0], drive_.poses[k][1], drive_.poses[k][2]};
  bool all_known = true;
  for (int j = oldest; j <= k; ++j) all_known = all_known && Known(drive_.poses[j]);
  for (int n : seen) all_known = all_known && truth_known_[n];
  if (all_known) {
    for (int j = oldest; j <= k; ++j)
      step->csp_truth.insert(step->csp_truth.end(), drive_.poses[j].begin(), drive_.poses[j].end());
    for (int n : seen)
      step->csp_truth.insert(step->csp_truth.end(), landmark_truth_[n].begin(),
                             landmark_truth_[n].end());
  }
  for (int n = 0; n < static_cast<int>(drive_.landmarks.size()); ++n)
    if (Known(drive_.landmarks[n])) step->landmark_truth[n] = drive_.landmarks[n];
  step->landmark_position = &LandmarkPosition;
  step->scored_landmarks = scored_;
  return true;
}

std::unique_ptr<Problem> MakeVisualLandmarks(const ParamMap& params, std::uint64_t seed) {
  return std::make_unique<VisualLandmarksProblem>(
      ParseParams<VisualLandmarksParams>("visual-landmarks", params), seed);
}

}  // namespace icp
