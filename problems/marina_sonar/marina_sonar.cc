#include "problems/marina_sonar/marina_sonar.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "core/constraint_system.h"
#include "core/random.h"
#include "problems/csv_fields.h"
#include "problems/log_file.h"
#include "problems/marina_sonar/sonar_contractor.h"
#include "problems/planar.h"

namespace icp {

constexpr double kPi = std::numbers::pi;

void Describe(MarinaSonarParams& p, ParamSet& set) {
  set.Add("start", &p.start,
          "known: track from the true start ± start_error; unknown: global localization, the "
          "whole map as the first prior",
          {"known", "unknown"});
  set.Add("start_error", &p.start_error, "half-width of the known start box on x and y, m",
          Range::Positive(1000));
  set.Add("steps", &p.steps,
          "number of steps to drive (the route ends after about 1187 at 0.5 m/s); with a log, at "
          "most this many rows",
          Range::Closed(1, 1e6));
  set.Add("dt", &p.dt, "time step, s (simulator)", Range::Positive(60));
  set.Add("speed", &p.speed, "mean forward speed, m/s, varying by ±10 % (simulator)",
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
          "probability that a return is a multiple echo or a fish (simulator)", Range::Closed(0, 1));
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
          "outlier floor of one return's likelihood (probabilistic view)", Range{0, 1, true, true});
  set.Add("log", &p.log, "CSV log replacing the simulator (empty: simulate)");
  set.Add("map", &p.map, "map image with its .yaml frame sidecar (empty: the shipped marina)");
}

namespace {

MarinaSonarParams ParseMarinaSonar(const std::string& owner, const ParamMap& values) {
  MarinaSonarParams p = ParseParams<MarinaSonarParams>(owner, values);
  if (!p.map.empty() && p.log.empty())
    throw ParamError(owner + ".map = " + p.map +
                     ": another map needs a log (the simulator drives the shipped marina)");
  return p;
}

std::string MapPath(const MarinaSonarParams& p) {
  return p.map.empty() ? ShippedMarinaMapPath() : p.map;
}

// x + [-e, e], outward rounded.
Interval Around(double x, double e) { return Interval(x) + Interval(-e, e); }

// --- simulator --------------------------------------------------------------

// Turn rate limit of the simulated robot, rad/s, and the distance at which it
// heads for the next waypoint, m.
constexpr double kMaxTurnRate = 0.2;
constexpr double kWaypointRadius = 3;
// Rays across the beam whose shortest hit is the echo.
constexpr int kBeamRays = 5;

class Simulator {
 public:
  Simulator(const MarinaSonarParams& p, const MarinaMap& map, std::uint64_t seed)
      : p_(p), map_(map), rng_(seed) {}

  std::vector<MarinaRecord> Run() {
    const std::vector<std::vector<double>> route = MarinaRoute();
    double x = route[0][0], y = route[0][1];
    std::size_t target = 1;
    double th = std::atan2(route[1][1] - y, route[1][0] - x);
    const double speed_phase = UniformReal(rng_, 0, 2 * kPi);
    const double drift_phase = UniformReal(rng_, 0, 2 * kPi);
    // Sensor biases for the whole drive (a DVL misalignment, a magnetic
    // deviation), within 0.6 of each bound; the noise adds up to 0.3 more.
    // Dead reckoning drifts by the biases, as in the thesis' Fig. 6.7.
    const double bias_u = 0.6 * p_.dvl_error * UniformReal(rng_, -1, 1);
    const double bias_v = 0.6 * p_.dvl_error * UniformReal(rng_, -1, 1);
    const double bias_th = 0.6 * p_.compass_error * UniformReal(rng_, -1, 1);
    std::vector<MarinaRecord> records;
    for (int k = 0; k < p_.steps; ++k) {
      while (target < route.size() &&
             std::hypot(route[target][0] - x, route[target][1] - y) < kWaypointRadius)
        ++target;
      if (target == route.size()) break;  // the route is driven
      const double desired = std::atan2(route[target][1] - y, route[target][0] - x);
      const double turn = std::remainder(desired - th, 2 * kPi);
      const double max_turn = kMaxTurnRate * p_.dt;
      th += std::clamp(turn, -max_turn, max_turn);
      const double t = k * p_.dt;
      // True body-frame velocity: the speed varies by ±10 %, a current
      // pushes sideways by up to 5 % of it.
      const double u = p_.speed * (1 + 0.1 * std::sin(2 * kPi * t / 120 + speed_phase));
      const double v = 0.05 * p_.speed * std::sin(2 * kPi * t / 90 + drift_phase);
      MarinaRecord r;
      r.t = t;
      r.dvl_u = u + bias_u + Noise(p_.dvl_error, 0.3);
      r.dvl_v = v + bias_v + Noise(p_.dvl_error, 0.3);
      r.dvl_error = p_.dvl_error;
      r.heading = th + bias_th + Noise(p_.compass_error, 0.3);
      r.heading_error = p_.compass_error;
      r.has_truth = true;
      r.truth_x = x;
      r.truth_y = y;
      const int n = p_.returns_per_step;
      for (int j = 0; j < n; ++j) {
        const double alpha =
            std::remainder(static_cast<double>(static_cast<std::int64_t>(k) * n + j) * p_.beam_step,
                           2 * kPi);
        if (std::optional<MarinaReturn> ret = Return(x, y, th, alpha)) r.returns.push_back(*ret);
      }
      records.push_back(std::move(r));
      x += p_.dt * (u * std::cos(th) - v * std::sin(th));
      y += p_.dt * (u * std::sin(th) + v * std::cos(th));
    }
    return records;
  }

 private:
  // Uniform within share (0.9 by default) of bound, so that the truth is
  // strictly inside every interval and rounding cannot push it out.
  double Noise(double bound, double share = 0.9) { return share * bound * UniformReal(rng_, -1, 1); }

  // The return of the beam at angle alpha on the robot at (x, y), heading th.
  std::optional<MarinaReturn> Return(double x, double y, double th, double alpha) {
    const double e = p_.range_error;
    const double limit = p_.max_range + 3 * e;
    double d = kInf, hit_angle = 0;
    for (int i = 0; i < kBeamRays; ++i) {
      const double offset = (-0.9 + 1.8 * i / (kBeamRays - 1)) * p_.beam_half_width;
      const double a = th + alpha + offset;
      const std::optional<double> t = CastRay(*map_.image, x, y, a, limit);
      if (t && *t < d) {
        d = *t;
        hit_angle = a;
      }
    }
    // Every draw is made whatever the case, so that a change of case does
    // not shift the later draws.
    const bool draw_outlier = UniformReal(rng_, 0, 1) < p_.outlier_rate;
    bool echo = UniformInt(rng_, 0, 1) == 0;
    const double noise = Noise(e);
    const double share = UniformReal(rng_, 0, 1);
    MarinaReturn r;
    r.beam_angle = alpha;
    r.range_error = e;
    r.beam_half_width = p_.beam_half_width;
    r.has_outlier_flag = true;
    if (d <= limit) {
      if (draw_outlier) {
        // A multiple echo at twice the wall distance, received within range;
        // a fish short of the wall. Both miss the wall distance d by more
        // than e.
        const bool echo_ok = d > 3 * e && 2 * d + 0.9 * e <= p_.max_range;
        const bool fish_ok = d > 4 * e;
        if (echo && !echo_ok) echo = false;
        if (!echo && !fish_ok) echo = echo_ok;
        if (echo && echo_ok) {
          r.range = 2 * d + noise;
          r.outlier = true;
          return r;
        }
        if (fish_ok) {
          r.range = e + share * (d - 4 * e);  // in [e, d - 3e]
          r.outlier = true;
          return r;
        }
      }
      r.range = std::max(0.0, d + noise);
      r.has_hit = true;
      r.hit_x = x + d * std::cos(hit_angle);
      r.hit_y = y + d * std::sin(hit_angle);
      return r;
    }
    // No wall within max_range + 3e along the beam.
    if (draw_outlier) {
      r.range = e + share * (p_.max_range - 2 * e);  // a fish, in [e, max_range - e]
      r.outlier = true;
      return r;
    }
    if (p_.out_of_range == "drop") return std::nullopt;
    r.range = p_.max_range;
    r.outlier = true;
    return r;
  }

  const MarinaSonarParams& p_;
  const MarinaMap& map_;
  RandomEngine rng_;
};

}  // namespace

std::vector<std::vector<double>> MarinaRoute() {
  // Clockwise round the basin from its east side: south, west along y = 100, north along x = 80, east along y = 180 (25 m clear of
  // the pontoons, the jetty and the island), then out through the canal
  // mouth and 190 m along the canal's axis y = 140.
  return {{190, 140}, {195, 105}, {85, 100}, {80, 180}, {190, 180},
          {205, 140}, {240, 140}, {430, 140}};
}

std::vector<MarinaRecord> SimulateMarinaSonar(const MarinaSonarParams& params, const MarinaMap& map,
                                              std::uint64_t seed) {
  return Simulator(params, map, seed).Run();
}

Displacement DeadReckoning(const MarinaRecord& r, const Interval& dt) {
  const Interval u = Around(r.dvl_u, r.dvl_error), v = Around(r.dvl_v, r.dvl_error);
  const Interval th = Around(r.heading, r.heading_error);
  const Interval c = Cos(th), s = Sin(th);
  return {dt * (u * c - v * s), dt * (u * s + v * c)};
}

double MarinaLogLikelihood(const MarinaMap& map, const MarinaRecord& r, double max_range,
                           double floor, double x, double y) {
  if (!map.bounds[0].Contains(x) || !map.bounds[1].Contains(y))
    return -std::numeric_limits<double>::infinity();
  const double pixel = map.image->frame().pixel_size;
  double sum = 0;
  for (const MarinaReturn& ret : r.returns) {
    if (!(ret.range < max_range)) continue;
    const double a = r.heading + ret.beam_angle;
    const double dist = WallDistance(map, x + ret.range * std::cos(a), y + ret.range * std::sin(a));
    const double sigma =
        std::max(pixel, std::hypot(ret.range_error, ret.range * (r.heading_error + ret.beam_half_width)));
    sum += std::log((1 - floor) * std::exp(-dist * dist / (2 * sigma * sigma)) + floor);
  }
  return sum;
}

// --- CSV log ----------------------------------------------------------------

namespace {

constexpr double kMaxTime = 1e12;      // s
constexpr double kMaxPosition = 1e9;   // m
constexpr double kMaxVelocity = 1e3;   // m/s
constexpr double kMaxAngle = 1e6;      // rad
constexpr double kMaxRange = 1e6;      // m

constexpr const char* kStepFields[] = {"t",       "dvl_u",         "dvl_v",   "dvl_error",
                                       "heading", "heading_error", "truth_x", "truth_y"};
constexpr const char* kReturnFields[] = {"beam_angle", "range",   "range_error", "beam_half_width",
                                         "outlier",    "hit_x",   "hit_y"};

class LogReader {
 public:
  explicit LogReader(std::string source) : source_(std::move(source)) {}

  std::vector<MarinaRecord> Read(std::istream& in) {
    std::vector<MarinaRecord> records;
    std::string line;
    while (std::getline(in, line)) {
      ++line_number_;
      const std::string_view text = TrimField(line);
      if (text.empty() || text.front() == '#') continue;
      fields_ = SplitCsvFields(text);
      if (fields_[0] == "step") {
        records.push_back(ReadStep());
        if (records.size() > 1 && !(records.back().t > records[records.size() - 2].t))
          Fail("field 2 (t): " + FormatDouble(records.back().t) +
               " is not after the previous step's " + FormatDouble(records[records.size() - 2].t));
      } else if (fields_[0] == "return") {
        if (records.empty()) Fail("a return before the first step row");
        records.back().returns.push_back(ReadReturn());
      } else {
        Fail("unknown row kind '" + std::string(fields_[0]) + "' (step, return)");
      }
    }
    if (records.empty()) throw std::invalid_argument(source_ + ": no step rows");
    return records;
  }

 private:
  [[noreturn]] void Fail(const std::string& what) const {
    throw std::invalid_argument(source_ + ":" + std::to_string(line_number_) + ": " + what);
  }

  template <std::size_t N>
  void Expect(const char* const (&names)[N]) {
    names_ = names;
    if (fields_.size() != N + 1)
      Fail("a " + std::string(fields_[0]) + " row has " + std::to_string(N) + " fields after its kind, not " +
           std::to_string(fields_.size() - 1));
  }

  std::string Where(int i) const {
    return "field " + std::to_string(i + 2) + " (" + names_[i] + ")";
  }

  bool Empty(int i) const { return fields_[i + 1].empty(); }

  // Field i (0 = the first after the kind), a finite number within limit.
  double Number(int i, double limit) const {
    const std::string_view f = fields_[i + 1];
    double v = 0;
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
      Fail(Where(i) + ": '" + std::string(f) + "' is not a finite number");
    if (!(std::fabs(v) <= limit)) Fail(Where(i) + ": " + FormatDouble(v) + " is beyond +-" + FormatDouble(limit));
    return v;
  }

  double NonNegative(int i, double limit) const {
    const double v = Number(i, limit);
    if (!(v >= 0)) Fail(Where(i) + ": " + FormatDouble(v) + " must be >= 0");
    return v;
  }

  // Fields i and i + 1, both given (read within limit into *a and *b:
  // true) or both empty (false): a position of a step or a return.
  bool Pair(int i, double limit, double* a, double* b) const {
    if (Empty(i) != Empty(i + 1))
      Fail(std::string(names_[i]) + " and " + names_[i + 1] + " must be both given or both empty");
    if (Empty(i)) return false;
    *a = Number(i, limit);
    *b = Number(i + 1, limit);
    return true;
  }

  MarinaRecord ReadStep() {
    Expect(kStepFields);
    MarinaRecord r;
    r.t = Number(0, kMaxTime);
    r.dvl_u = Number(1, kMaxVelocity);
    r.dvl_v = Number(2, kMaxVelocity);
    r.dvl_error = NonNegative(3, kMaxVelocity);
    r.heading = Number(4, kMaxAngle);
    r.heading_error = NonNegative(5, kPi);
    r.has_truth = Pair(6, kMaxPosition, &r.truth_x, &r.truth_y);
    return r;
  }

  MarinaReturn ReadReturn() {
    Expect(kReturnFields);
    MarinaReturn r;
    r.beam_angle = Number(0, kMaxAngle);
    r.range = NonNegative(1, kMaxRange);
    r.range_error = NonNegative(2, kMaxRange);
    r.beam_half_width = NonNegative(3, kPi);
    if (!Empty(4)) {
      if (fields_[5] != "0" && fields_[5] != "1")
        Fail(Where(4) + ": '" + std::string(fields_[5]) + "' must be 0, 1 or empty");
      r.has_outlier_flag = true;
      r.outlier = fields_[5] == "1";
    }
    r.has_hit = Pair(5, kMaxPosition, &r.hit_x, &r.hit_y);
    return r;
  }

  std::string source_;
  int line_number_ = 0;
  std::vector<std::string_view> fields_;
  const char* const* names_ = nullptr;
};

}  // namespace

std::vector<MarinaRecord> ReadMarinaLog(std::istream& in, const std::string& source) {
  return LogReader(source).Read(in);
}

std::vector<MarinaRecord> ReadMarinaLog(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw std::invalid_argument(path + ": no such log file (a regular file)");
  std::ifstream in = OpenLogFile(path, "marina-sonar log");
  return ReadMarinaLog(in, path);
}

void WriteMarinaLog(const std::vector<MarinaRecord>& records, std::ostream& out,
                    const std::string& comment) {
  WriteLogComment(out, comment);
  out << "# step";
  for (const char* f : kStepFields) out << "," << f;
  out << "\n# return";
  for (const char* f : kReturnFields) out << "," << f;
  out << "\n";
  for (const MarinaRecord& r : records) {
    out << "step," << FormatDouble(r.t) << "," << FormatDouble(r.dvl_u) << "," << FormatDouble(r.dvl_v)
        << "," << FormatDouble(r.dvl_error) << "," << FormatDouble(r.heading) << ","
        << FormatDouble(r.heading_error) << ",";
    if (r.has_truth) out << FormatDouble(r.truth_x) << "," << FormatDouble(r.truth_y);
    else out << ",";
    out << "\n";
    for (const MarinaReturn& s : r.returns) {
      out << "return," << FormatDouble(s.beam_angle) << "," << FormatDouble(s.range) << ","
          << FormatDouble(s.range_error) << "," << FormatDouble(s.beam_half_width) << ","
          << (s.has_outlier_flag ? (s.outlier ? "1" : "0") : "") << ",";
      if (s.has_hit) out << FormatDouble(s.hit_x) << "," << FormatDouble(s.hit_y);
      else out << ",";
      out << "\n";
    }
  }
}

// --- the problem ------------------------------------------------------------

MarinaSonarProblem::MarinaSonarProblem(const MarinaSonarParams& params, MarinaMap map,
                                       std::vector<MarinaRecord> records)
    : params_(params), map_(std::move(map)), records_(std::move(records)) {
  num_steps_ = static_cast<int>(std::min<std::size_t>(records_.size(), params_.steps));
  for (int k = 0; k < num_steps_; ++k) {
    const MarinaRecord& r = records_[k];
    if (r.has_truth && !map_.bounds.Contains({r.truth_x, r.truth_y}))
      throw std::invalid_argument("marina-sonar: step " + std::to_string(k) + ": the truth (" +
                                  FormatDouble(r.truth_x) + ", " + FormatDouble(r.truth_y) +
                                  ") lies outside the map");
  }
  if (params_.start == "known") {
    if (records_.empty() || !records_[0].has_truth)
      throw ParamError("marina-sonar.start = known: the first step has no truth");
    start_box_ = Intersect(Box({Around(records_[0].truth_x, params_.start_error),
                                Around(records_[0].truth_y, params_.start_error)}),
                           map_.bounds);
  }
  motion_.resize(num_steps_);
  for (int k = 1; k < num_steps_; ++k)
    motion_[k] = DeadReckoning(records_[k - 1], Interval(records_[k].t) - Interval(records_[k - 1].t));
}

namespace {

std::vector<double> UniformIn(const Box& box, RandomEngine& rng) {
  return {UniformReal(rng, box[0].lo(), box[0].hi()), UniformReal(rng, box[1].lo(), box[1].hi())};
}

// Uniform over box, away from walls (a few tries; the last one is kept).
std::vector<double> UniformInWater(const Box& box, const BinaryImage& map, RandomEngine& rng) {
  std::vector<double> p = UniformIn(box, rng);
  for (int i = 0; i < 64 && InsideWallPixel(map, p[0], p[1], 0); ++i) p = UniformIn(box, rng);
  return p;
}

}  // namespace

bool MarinaSonarProblem::Next(Step* step) {
  if (k_ >= num_steps_) return false;
  const int k = k_++;
  const bool known = params_.start == "known";
  const MarinaRecord& r = records_[k];
  *step = Step();
  step->views.step = k;
  step->views.space = PlanarStateSpace();

  // The measurement set.
  MeasurementSetView set;
  set.prior = k == 0 && known ? start_box_ : map_.bounds;
  bool flags_known = true;
  std::vector<bool> outliers;
  // From this step back: carried holds the displacement from step j to k.
  Displacement carried{Interval(0), Interval(0)};
  for (int j = k; j >= std::max(0, k - params_.sonar_window); --j) {
    if (j < k) carried = {carried.dx + motion_[j + 1].dx, carried.dy + motion_[j + 1].dy};
    const MarinaRecord& at = records_[j];
    for (const MarinaReturn& ret : at.returns) {
      set.measurements.push_back(std::make_shared<SonarContractor>(
          map_.image, SonarRangeInterval(ret.range, ret.range_error),
          SonarAngleInterval(at.heading, at.heading_error, ret.beam_angle, ret.beam_half_width),
          carried.dx, carried.dy));
      outliers.push_back(ret.outlier);
      flags_known = flags_known && ret.has_outlier_flag;
    }
  }
  if (flags_known) set.outliers = std::move(outliers);
  if (k > 0)
    set.predict = [m = motion_[k]](const Box& previous) {
      if (previous.size() != 2) throw std::invalid_argument("marina-sonar predict: the box must be (x, y)");
      return Box({previous[0] + m.dx, previous[1] + m.dy});
    };
  step->views.measurement_set = std::move(set);

  // The CSP: dead reckoning over the window.
  const int oldest = std::max(0, k - params_.w);
  CspView view;
  ConstraintSystem& csp = view.csp;
  std::optional<Expr> xp, yp;
  bool truth_known = true;
  for (int j = oldest; j <= k; ++j) {
    const std::string index = "[" + std::to_string(j) + "]";
    const Box& domain = j == 0 && known ? start_box_ : map_.bounds;
    Expr xj = csp.AddVariable("x" + index, domain[0]);
    Expr yj = csp.AddVariable("y" + index, domain[1]);
    view.states.push_back({j, 0});
    view.states.push_back({j, 1});
    if (j > oldest) {
      csp.AddConstraint(xj, Relation::kEq, *xp + csp.Constant(motion_[j].dx));
      csp.AddConstraint(yj, Relation::kEq, *yp + csp.Constant(motion_[j].dy));
    }
    xp = xj;
    yp = yj;
    truth_known = truth_known && records_[j].has_truth;
  }
  view.newest = k;
  step->views.csp = std::move(view);
  if (r.has_truth) step->truth = {r.truth_x, r.truth_y};
  if (truth_known)
    for (int j = oldest; j <= k; ++j)
      step->csp_truth.insert(step->csp_truth.end(), {records_[j].truth_x, records_[j].truth_y});

  // The probabilistic view.
  ProbabilisticView pv;
  const Box prior = known ? start_box_ : map_.bounds;
  auto image = map_.image;
  pv.sample_prior = [prior, image](RandomEngine& rng) { return UniformInWater(prior, *image, rng); };
  pv.sample_global = [bounds = map_.bounds, image](RandomEngine& rng) {
    return UniformInWater(bounds, *image, rng);
  };
  if (k == 0) {
    pv.sample_motion = [](std::vector<double>&, RandomEngine&) {};
  } else {
    const MarinaRecord& before = records_[k - 1];
    pv.sample_motion = [u = before.dvl_u, v = before.dvl_v, e = before.dvl_error, th = before.heading,
                        te = before.heading_error, dt = r.t - before.t](std::vector<double>& s,
                                                                        RandomEngine& rng) {
      const double du = u + UniformReal(rng, -e, e), dv = v + UniformReal(rng, -e, e);
      const double h = th + UniformReal(rng, -te, te);
      s[0] += dt * (du * std::cos(h) - dv * std::sin(h));
      s[1] += dt * (du * std::sin(h) + dv * std::cos(h));
    };
  }
  pv.log_likelihood = [map = map_, record = r, max_range = params_.max_range,
                       floor = params_.likelihood_floor](const std::vector<double>& s) {
    return MarinaLogLikelihood(map, record, max_range, floor, s[0], s[1]);
  };
  step->views.probabilistic = std::move(pv);
  return true;
}

ParamMap ResolveMarinaSonar(const std::string& owner, const ParamMap& values) {
  const MarinaSonarParams p = ParseMarinaSonar(owner, values);
  MarinaMap map = LoadMarinaMap(MapPath(p));
  if (!p.log.empty()) {
    const MarinaSonarProblem checked(p, std::move(map), ReadMarinaLog(p.log));
    static_cast<void>(checked);
  }
  return ResolveParams<MarinaSonarParams>(owner, values);
}

std::unique_ptr<Problem> MakeMarinaSonar(const ParamMap& params, std::uint64_t seed) {
  const MarinaSonarParams p = ParseMarinaSonar("marina-sonar", params);
  MarinaMap map = LoadMarinaMap(MapPath(p));
  std::vector<MarinaRecord> records =
      p.log.empty() ? SimulateMarinaSonar(p, map, seed) : ReadMarinaLog(p.log);
  return std::make_unique<MarinaSonarProblem>(p, std::move(map), std::move(records));
}

}  // namespace icp
