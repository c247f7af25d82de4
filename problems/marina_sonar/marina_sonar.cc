// The marina-sonar problem's parameters, its dead reckoning and the problem
// over a drive; the simulator, the log and the step views are in
// marina_simulator.cc, marina_log.cc and marina_views.cc.
#include "problems/marina_sonar/marina_sonar.h"

#include <algorithm>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "problems/log_file.h"

namespace icp {

constexpr double kPi = std::numbers::pi;

void Describe(MarinaSonarParams& p, ParamSet& set) {
  set.Add("start", &p.start,
          "known: track from the true start ± start_error; area: a 144 x 72 m box (10,368 m², "
          "the thesis' Fig. 6.9 prior) about the true start; unknown: global localization, the "
          "whole map as the first prior",
          {"known", "area", "unknown"});
  set.Add("start_error", &p.start_error, "half-width of the known start box on x and y, m",
          Range::Positive(1000));
  set.Add("steps", &p.steps,
          "number of steps to drive (the route ends after about 1187 at 0.5 m/s); with a log, at "
          "most this many rows",
          Range::Closed(1, 1e6));
  set.Add("dt", &p.dt, "time step, s; speed x dt <= 20 m (simulator)", Range::Positive(40));
  set.Add("speed", &p.speed,
          "mean forward speed, m/s, varying by ±10 %; speed x dt <= 20 m (simulator)",
          Range{0.05, 5, false, false});
  set.Add("dvl_error", &p.dvl_error, "DVL half-width on each body-frame velocity, m/s (simulator)",
          Range::Positive(1));
  set.Add("compass_error", &p.compass_error, "compass half-width, rad (simulator)",
          Range::Positive(0.5));
  set.Add("returns_per_step", &p.returns_per_step, "sonar returns per step (simulator)",
          Range::Closed(1, 1000));
  set.Add("beam_step", &p.beam_step, "sonar head rotation between two returns, rad (simulator)",
          Range::Positive(2 * kPi));
  set.Add("beam_half_width", &p.beam_half_width, "sonar beam half-width, rad (simulator)",
          Range::Positive(0.5));
  set.Add("range_error", &p.range_error, "half-width of a return's range interval, m (simulator)",
          Range::Positive(10));
  set.Add("max_range", &p.max_range,
          "sonar range, m: no echo beyond it; the likelihood ignores readings at or beyond it",
          Range{1, 1000, false, false});
  set.Add("outlier_rate", &p.outlier_rate,
          "probability that a return is a multiple echo or a fish (simulator)",
          Range::Closed(0, 1));
  set.Add("out_of_range", &p.out_of_range,
          "a beam meeting no wall within max_range: a max_range reading declared an outlier, or "
          "no return (simulator)",
          {"outlier", "drop"});
  set.Add("w", &p.w, "window length of the CSP view in steps (2w dead-reckoning constraints)",
          Range::Closed(1, 100000));
  set.Add("sonar_window", &p.sonar_window,
          "earlier steps whose returns the measurement set carries to this step by dead reckoning "
          "(eq. 6.2; 0: this step's returns only)",
          Range::Closed(0, 1000));
  set.Add("likelihood_floor", &p.likelihood_floor,
          "outlier weight of one return's likelihood (probabilistic view)", Range{0, 1, true, true});
  set.Add("log", &p.log, "CSV log replacing the simulator (empty: simulate)");
  set.Add("map", &p.map,
          "PNG map image of at most 25000000 pixels with its .yaml frame sidecar (empty: the "
          "shipped marina)");
}

namespace {

MarinaSonarParams ParseMarinaSonar(const std::string& owner, const ParamMap& values) {
  MarinaSonarParams p = ParseParams<MarinaSonarParams>(owner, values);
  if (!p.map.empty() && p.log.empty())
    throw ParamError(owner + ".map = " + p.map +
                     ": another map needs a log (the simulator drives the shipped marina)");
  if (p.log.empty() && !(p.speed * p.dt <= kMarinaMaxStep))
    throw ParamError(owner + ".speed = " + FormatDouble(p.speed) + ", dt = " + FormatDouble(p.dt) +
                     ": a step of speed x dt = " + FormatDouble(p.speed * p.dt) +
                     " m; the simulator needs speed x dt <= " + FormatDouble(kMarinaMaxStep) +
                     " m (each step is straight: a longer one cuts through the quays)");
  return p;
}

std::string MapPath(const MarinaSonarParams& p) {
  return p.map.empty() ? ShippedMarinaMapPath() : p.map;
}

// x + [-e, e], outward rounded.
Interval Around(double x, double e) { return Interval(x) + Interval(-e, e); }

}  // namespace

Box MarinaAreaStart(double x, double y, const Box& bounds) {
  // Centred on the truth, then slid along each axis back into the bounds.
  auto side = [](double centre, double width, const Interval& in) {
    double lo = centre - width / 2;
    if (in.Width() >= width) lo = std::clamp(lo, in.lo(), in.hi() - width);
    return Interval(lo, lo + width);
  };
  return Box({side(x, kMarinaAreaStartX, bounds[0]), side(y, kMarinaAreaStartY, bounds[1])});
}

Displacement DeadReckoning(const MarinaRecord& r, const Interval& dt) {
  const Interval u = Around(r.dvl_u, r.dvl_error), v = Around(r.dvl_v, r.dvl_error);
  const Interval th = Around(r.heading, r.heading_error);
  const Interval c = Cos(th), s = Sin(th);
  return {dt * (u * c - v * s), dt * (u * s + v * c)};
}

namespace {

// What the problem needs of a drive on a map covering bounds (the
// constructor's contract, checked at validation too).
void CheckDrive(const MarinaSonarParams& params, const std::vector<MarinaRecord>& records,
                const Box& bounds) {
  const std::size_t n = std::min<std::size_t>(records.size(), params.steps);
  for (std::size_t k = 0; k < n; ++k) {
    const MarinaRecord& r = records[k];
    if (r.has_truth && !bounds.Contains({r.truth_x, r.truth_y}))
      throw std::invalid_argument(
          "marina-sonar: " + (params.log.empty() ? std::string("the simulated drive") : params.log) +
          ", step " + std::to_string(k) + ": the truth (" + FormatDouble(r.truth_x) + ", " +
          FormatDouble(r.truth_y) + ") lies outside the map " +
          (params.map.empty() ? std::string("of the marina") : params.map) + " (x in [" +
          FormatDouble(bounds[0].lo()) + ", " + FormatDouble(bounds[0].hi()) + "], y in [" +
          FormatDouble(bounds[1].lo()) + ", " + FormatDouble(bounds[1].hi()) + "])");
  }
  if (params.start != "unknown" && (records.empty() || !records[0].has_truth))
    throw ParamError("marina-sonar.start = " + params.start + ": the first step has no truth");
}

}  // namespace

MarinaSonarProblem::MarinaSonarProblem(const MarinaSonarParams& params, MarinaMap map,
                                       std::vector<MarinaRecord> records)
    : params_(params), map_(std::move(map)), records_(std::move(records)) {
  num_steps_ = static_cast<int>(std::min<std::size_t>(records_.size(), params_.steps));
  CheckDrive(params_, records_, map_.bounds);
  if (params_.start == "known") {
    start_box_ = Intersect(Box({Around(records_[0].truth_x, params_.start_error),
                                Around(records_[0].truth_y, params_.start_error)}),
                           map_.bounds);
  } else if (params_.start == "area") {
    start_box_ = MarinaAreaStart(records_[0].truth_x, records_[0].truth_y, map_.bounds);
  }
  motion_.resize(num_steps_);
  for (int k = 1; k < num_steps_; ++k)
    motion_[k] =
        DeadReckoning(records_[k - 1], Interval(records_[k].t) - Interval(records_[k - 1].t));
}

ParamMap ResolveMarinaSonar(const std::string& owner, const ParamMap& values) {
  const MarinaSonarParams p = ParseMarinaSonar(owner, values);
  // Validation runs in the parent process, which has no memory limit: the
  // map is checked (bounded in size, decoded, not derived), not loaded.
  const Box bounds = CheckMarinaMap(MapPath(p));
  if (!p.log.empty()) CheckDrive(p, ReadMarinaLog(p.log), bounds);
  return ResolveParams<MarinaSonarParams>(owner, values);
}

std::string NoteMarinaSonar(const ParamMap& resolved) {
  const MarinaSonarParams p = ParseMarinaSonar("marina-sonar", resolved);
  if (p.log.empty()) return "";
  return CutLogNote("marina-sonar", p.log, ReadMarinaLog(p.log).size(), p.steps);
}

std::unique_ptr<Problem> MakeMarinaSonar(const ParamMap& params, std::uint64_t seed) {
  const MarinaSonarParams p = ParseMarinaSonar("marina-sonar", params);
  MarinaMap map = LoadMarinaMap(MapPath(p));
  std::vector<MarinaRecord> records =
      p.log.empty() ? SimulateMarinaSonar(p, map, seed) : ReadMarinaLog(p.log);
  return std::make_unique<MarinaSonarProblem>(p, std::move(map), std::move(records));
}

}  // namespace icp
