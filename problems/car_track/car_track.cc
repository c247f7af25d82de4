// The car-track problem's parameters, its measurement intervals (eq. 9-13)
// and the problem over a drive; the simulator, the log and the step views
// are in car_track_simulator.cc, car_track_log.cc and car_track_views.cc.
#include "problems/car_track/car_track.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "problems/log_file.h"

namespace icp {

void Describe(CarTrackParams& p, ParamSet& set) {
  set.Add("w", &p.w, "window length in steps (3w constraints)", Range::Closed(1, 100000));
  set.Add("steps", &p.steps, "number of steps (CSPs); with a log, at most this many rows",
          Range::Closed(1, 1e6));
  set.Add("speed", &p.speed, "mean speed, m/s (simulator)", Range::Positive(100));
  set.Add("rate", &p.rate, "sensor sampling rate, Hz (simulator)", Range::Closed(0.01, 1000));
  set.Add("track_width", &p.track_width, "distance between the rear wheels, m (simulator)",
          Range::Positive(10));
  set.Add("wheel_radius", &p.wheel_radius, "nominal rear wheel radius, m", Range::Positive(5));
  set.Add("radius_error", &p.radius_error,
          "half-width of the wheel radius intervals (eq. 13), m; below wheel_radius",
          Range::Closed(0, 5));
  set.Add("ticks_per_rev", &p.ticks_per_rev, "odometer resolution P (eq. 13), ticks/revolution",
          Range::Closed(1, 1e9));
  set.Add("odo_slip", &p.odo_slip, "wheel slip bound eps_odo (eq. 9), ticks per step",
          Range::Closed(0, 1e9));
  set.Add("gyro_error", &p.gyro_error, "gyro half-width eps_gyro (eq. 10), rad per step",
          Range::Positive(10));
  set.Add("gps_error", &p.gps_error, "simulated GPS half-width on x and y (eq. 11), m",
          Range::Positive(1e6));
  set.Add("gps_period", &p.gps_period, "use a GPS fix every gps_period steps",
          Range::Closed(1, 1e9));
  set.Add("outage_start", &p.outage_start, "first step of a GPS outage", Range::Closed(0, 1e9));
  set.Add("outage_length", &p.outage_length, "GPS outage length in steps (0: none)",
          Range::Closed(0, 1e9));
  set.Add("heading_known", &p.heading_known,
          "th[0] is the true heading ± 0.1 rad (else [-pi, pi])");
  set.Add("log", &p.log, "CSV log replacing the simulator (empty: simulate)");
  set.Add("filter_noise", &p.filter_noise,
          "the particle filter's noise: bounds (uniform in each interval), simulator (in its central 0.9, "
          "with regularisation) or auto (simulator without a log, else bounds)",
          {"auto", "bounds", "simulator"});
}

bool UsesSimulatorNoise(const CarTrackParams& p) {
  return p.filter_noise == "simulator" || (p.filter_noise == "auto" && p.log.empty());
}

void Validate(const CarTrackParams& p, const std::string& owner) {
  ParamSet set(owner);
  CarTrackParams copy = p;
  Describe(copy, set);
  set.Validate();
  if (!(p.radius_error < p.wheel_radius))
    throw ParamError(owner + ".radius_error = " + FormatDouble(p.radius_error) +
                     ": must be below wheel_radius (" + FormatDouble(p.wheel_radius) + ")");
  if (p.filter_noise == "simulator" && !p.log.empty())
    throw ParamError(owner + ".filter_noise = simulator: a recorded drive's noise is not the simulator's; "
                     "use bounds or auto with log");
}

namespace {

constexpr double kHeadingKnownError = 0.1;

// now - prev as a double; records not read by ReadCarTrackLog may hold any
// counts, and a signed overflow there would be undefined behaviour.
double TickStep(std::int64_t prev, std::int64_t now, std::size_t row) {
  std::int64_t diff = 0;
  if (__builtin_sub_overflow(now, prev, &diff))
    throw std::invalid_argument("car-track: row " + std::to_string(row) + ": tick count " +
                                std::to_string(now) + " after " + std::to_string(prev) +
                                " overflows a 64-bit difference");
  return static_cast<double>(diff);
}

// x + [-e, e], outward rounded.
Interval Around(double x, double e) { return Interval(x) + Interval(-e, e); }

}  // namespace

std::vector<CarTrackMeasurement> MeasureCarTrack(const CarTrackParams& p,
                                                 const std::vector<CarTrackRecord>& records) {
  const Interval ticks_error = Interval(1) + Interval(p.odo_slip);  // eq. 9
  const Interval radius = Around(p.wheel_radius, p.radius_error);   // [w_l], [w_r]
  const Interval ticks_per_rev(p.ticks_per_rev);
  std::vector<CarTrackMeasurement> out(records.size());
  for (std::size_t k = 0; k < records.size(); ++k) {
    const CarTrackRecord& r = records[k];
    CarTrackMeasurement& m = out[k];
    if (k > 0) {
      const CarTrackRecord& prev = records[k - 1];
      const Interval dp_left =
          Around(TickStep(prev.odo_left_ticks, r.odo_left_ticks, k), ticks_error.hi());
      const Interval dp_right =
          Around(TickStep(prev.odo_right_ticks, r.odo_right_ticks, k), ticks_error.hi());
      m.ds = Pi() * (radius * dp_left + radius * dp_right) / ticks_per_rev;  // eq. 13
      m.dth = Around(r.gyro_dtheta, p.gyro_error);                           // eq. 10
    }
    const std::int64_t step = static_cast<std::int64_t>(k);
    const bool in_outage = step >= p.outage_start &&
                           step < static_cast<std::int64_t>(p.outage_start) + p.outage_length;
    if (r.has_gps && step % p.gps_period == 0 && !in_outage) {  // eq. 11
      m.x = Around(r.gps_x, r.gps_ex);
      m.y = Around(r.gps_y, r.gps_ey);
    }
  }
  return out;
}

CarTrackProblem::CarTrackProblem(const CarTrackParams& params, std::vector<CarTrackRecord> records)
    : params_(params), records_(std::move(records)) {
  measurements_ = MeasureCarTrack(params_, records_);
  num_steps_ = static_cast<int>(std::min<std::size_t>(records_.size(), params_.steps));
  heading0_ = Interval(-Pi().hi(), Pi().hi());
  if (params_.heading_known) {
    if (records_.empty() || !records_[0].has_truth)
      throw ParamError("car-track.heading_known = true: the first row of the log" +
                       (params_.log.empty() ? std::string() : " " + params_.log) +
                       " has no truth");
    heading0_ = Around(records_[0].truth_theta, kHeadingKnownError);
  }
  prior_ = Box({Interval(), Interval(), heading0_});
  Interval reach(0);  // how far the car may have driven since step 0
  for (std::size_t j = 0; j < measurements_.size(); ++j) {
    const CarTrackMeasurement& m = measurements_[j];
    if (j > 0) reach = reach + Interval(0, std::max(0.0, std::max(m.ds.hi(), -m.ds.lo())));
    if (m.x.IsBounded() && m.y.IsBounded()) {
      const Interval spread(-reach.hi(), reach.hi());
      prior_[0] = m.x + spread;
      prior_[1] = m.y + spread;
      break;
    }
  }
}

ParamMap ResolveCarTrack(const std::string& owner, const ParamMap& values) {
  CarTrackParams p = ParseParams<CarTrackParams>(owner, values);
  Validate(p, owner);
  if (!p.log.empty()) {
    const CarTrackProblem checked(p, ReadCarTrackLog(p.log));  // heading_known needs a truth
    static_cast<void>(checked);
  }
  return ResolveParams<CarTrackParams>(owner, values);
}

std::string NoteCarTrack(const ParamMap& resolved) {
  const CarTrackParams p = ParseParams<CarTrackParams>("car-track", resolved);
  if (p.log.empty()) return "";
  return CutLogNote("car-track", p.log, ReadCarTrackLog(p.log).size(), p.steps);
}

std::unique_ptr<Problem> MakeCarTrack(const ParamMap& params, std::uint64_t seed) {
  CarTrackParams p = ParseParams<CarTrackParams>("car-track", params);
  Validate(p);
  std::vector<CarTrackRecord> records =
      p.log.empty() ? SimulateCarTrack(p, seed) : ReadCarTrackLog(p.log);
  return std::make_unique<CarTrackProblem>(p, std::move(records));
}

}  // namespace icp
