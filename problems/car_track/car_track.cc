#include "problems/car_track/car_track.h"

#include "problems/car_track/window.h"
#include "problems/csv_fields.h"
#include "problems/log_file.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <string_view>

#include "core/random.h"

namespace icp {

void Describe(CarTrackParams& p, ParamSet& set) {
  set.Add("w", &p.w, "window length in steps (3w constraints)", Range::Closed(1, 100000));
  set.Add("steps", &p.steps, "number of steps (CSPs); with a log, at most this many rows",
          Range::Closed(1, 1e6));
  set.Add("speed", &p.speed, "mean speed, m/s (simulator)", Range::Positive(100));
  set.Add("rate", &p.rate, "sensor sampling rate, Hz (simulator)", Range::Positive(1000));
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
}

void Validate(const CarTrackParams& p, const std::string& owner) {
  ParamSet set(owner);
  CarTrackParams copy = p;
  Describe(copy, set);
  set.Validate();
  if (!(p.radius_error < p.wheel_radius))
    throw ParamError(owner + ".radius_error = " + FormatDouble(p.radius_error) +
                     ": must be below wheel_radius (" + FormatDouble(p.wheel_radius) + ")");
}

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kHeadingKnownError = 0.1;

// The track as a curvature profile along the arc length: straights (angle 0)
// and bends whose curvature rises and falls smoothly (2 sin^2 profile, so the
// heading changes by `angle` over `length` metres with no curvature jump).
// Four left corners and an S-bend on each long side; 5560 m, one lap at
// 13.9 m/s and 5 Hz in 2000 steps. It closes exactly in continuous geometry.
struct Segment {
  double length;  // m
  double angle;   // heading change over the segment, rad
};
constexpr Segment kTrack[] = {
    {440, 0}, {200, 0.35}, {200, -0.35}, {440, 0}, {400, kPi / 2}, {700, 0}, {400, kPi / 2},
    {440, 0}, {200, 0.35}, {200, -0.35}, {440, 0}, {400, kPi / 2}, {700, 0}, {400, kPi / 2},
};

double TrackLength() {
  double total = 0;
  for (const Segment& s : kTrack) total += s.length;
  return total;
}

// Heading change from the start of the track to arc length s >= 0.
double TrackHeading(double s) {
  static const double kLength = TrackLength();
  const double laps = std::floor(s / kLength);
  double u = s - laps * kLength;
  double heading = laps * 2 * kPi;
  for (const Segment& seg : kTrack) {
    if (u >= seg.length) {
      heading += seg.angle;
      u -= seg.length;
      continue;
    }
    heading += seg.angle * (u / seg.length - std::sin(2 * kPi * u / seg.length) / (2 * kPi));
    break;
  }
  return heading;
}

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

std::vector<CarTrackRecord> SimulateCarTrack(const CarTrackParams& p, std::uint64_t seed) {
  RandomEngine rng(seed);
  auto unit = [&] { return UniformReal(rng, -1, 1); };
  // Bounded noise: at most 0.9 of each bound, so the truth stays strictly
  // inside every measurement interval and rounding cannot push it out.
  auto noise = [&](double bound) { return 0.9 * bound * unit(); };

  const double theta0 = 0.999 * kPi * unit();
  const double speed_phase = kPi * unit();
  const double r_left = p.wheel_radius + noise(p.radius_error);
  const double r_right = p.wheel_radius + noise(p.radius_error);
  // Cumulative wheel rotation in ticks; the encoders read its floor.
  double rot_left = UniformReal(rng, 0, 1), rot_right = UniformReal(rng, 0, 1);

  std::vector<CarTrackRecord> records;
  records.reserve(p.steps);
  double x = 0, y = 0, th = theta0, s = 0;
  for (int k = 0; k < p.steps; ++k) {
    double gyro = 0;
    if (k > 0) {
      // The true motion (ds, dth) and the truth by eq. 12 exactly.
      const double v = p.speed * (1 + 0.05 * std::sin(2 * kPi * k / (60 * p.rate) + speed_phase));
      const double ds = v / p.rate;
      const double dth = TrackHeading(s + ds) - TrackHeading(s);
      s += ds;
      const double heading = th + dth / 2;
      x += ds * std::cos(heading);
      y += ds * std::sin(heading);
      th += dth;
      // Each rear wheel travels ds -+ (track_width / 2) dth, so their mean is
      // ds: eq. 13 holds exactly for the true radii and tick counts.
      const double d_left = ds - p.track_width / 2 * dth;
      const double d_right = ds + p.track_width / 2 * dth;
      const double per_metre = p.ticks_per_rev / (2 * kPi);
      rot_left += d_left * per_metre / r_left + noise(p.odo_slip);
      rot_right += d_right * per_metre / r_right + noise(p.odo_slip);
      gyro = dth + noise(p.gyro_error);
    }
    // Converting a double beyond int64 is undefined behaviour (tiny radius,
    // huge ticks_per_rev and odo_slip over a long drive).
    constexpr double kMaxTicks = 0x1p62;
    if (!(std::fabs(rot_left) < kMaxTicks && std::fabs(rot_right) < kMaxTicks))
      throw ParamError("car-track: the simulated tick count exceeds 2^62 at step " +
                       std::to_string(k) +
                       "; lower ticks_per_rev, odo_slip or steps, or raise wheel_radius");
    CarTrackRecord r;
    r.t = k / p.rate;
    r.odo_left_ticks = static_cast<std::int64_t>(std::floor(rot_left));
    r.odo_right_ticks = static_cast<std::int64_t>(std::floor(rot_right));
    r.gyro_dtheta = gyro;
    r.has_gps = true;
    r.gps_x = x + noise(p.gps_error);
    r.gps_y = y + noise(p.gps_error);
    r.gps_ex = r.gps_ey = p.gps_error;
    r.has_truth = true;
    r.truth_x = x;
    r.truth_y = y;
    r.truth_theta = th;
    records.push_back(r);
  }
  return records;
}

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
      throw ParamError("car-track.heading_known = true: the first row of the log has no truth");
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

namespace {

double Uniform(RandomEngine& rng, const Interval& x) { return UniformReal(rng, x.lo(), x.hi()); }

// The probabilistic view of a step with measurement m (header comment):
// prior, the box of state 0; first, whether this is step 0.
ProbabilisticView CarProbabilisticView(const CarTrackMeasurement& m, const Box& prior, bool first) {
  ProbabilisticView view;
  view.sample_prior = [prior](RandomEngine& rng) {
    if (!prior[0].IsBounded() || !prior[1].IsBounded())
      throw std::invalid_argument("car-track: no GPS fix in the drive to draw the first state from");
    const double x = Uniform(rng, prior[0]);
    const double y = Uniform(rng, prior[1]);
    return std::vector<double>{x, y, Uniform(rng, prior[2])};
  };
  if (first) {
    view.sample_motion = [](std::vector<double>&, RandomEngine&) {};
  } else {
    view.sample_motion = [ds = m.ds, dth = m.dth](std::vector<double>& s, RandomEngine& rng) {
      const double d = Uniform(rng, ds);
      const double turn = Uniform(rng, dth);
      const double heading = s[2] + turn / 2;  // eq. 12
      s[0] += d * std::cos(heading);
      s[1] += d * std::sin(heading);
      s[2] += turn;
    };
  }
  const bool fix = m.x.IsBounded() && m.y.IsBounded();
  view.log_likelihood = [fix, x = m.x, y = m.y](const std::vector<double>& s) {
    if (!fix || (x.Contains(s[0]) && y.Contains(s[1]))) return 0.0;
    return -std::numeric_limits<double>::infinity();
  };
  if (fix)
    view.sample_global = [x = m.x, y = m.y](RandomEngine& rng) {
      const double gx = Uniform(rng, x);
      const double gy = Uniform(rng, y);
      return std::vector<double>{gx, gy, UniformReal(rng, -kPi, kPi)};
    };
  return view;
}

}  // namespace

bool CarTrackProblem::Next(Step* step) {
  if (k_ >= num_steps_) return false;
  const int k = k_++;
  const int oldest = std::max(0, k - params_.w);
  std::vector<CarWindowState> states;
  bool truth_known = true;
  for (int j = oldest; j <= k; ++j) {
    const CarTrackMeasurement& m = measurements_[j];
    // The oldest heading is unknown unless it is the drive's first.
    const Interval th = j == 0 ? heading0_ : j == oldest ? Interval(-Pi().hi(), Pi().hi()) : Interval();
    states.push_back({m.x, m.y, th, m.ds, m.dth});
    truth_known = truth_known && records_[j].has_truth;
  }
  *step = Step();
  step->views.step = k;
  step->views.space = CarStateSpace();
  step->views.csp = BuildCarWindow(oldest, states);
  step->views.probabilistic = CarProbabilisticView(measurements_[k], prior_, k == 0);
  if (const CarTrackMeasurement& m = measurements_[k]; m.x.IsBounded() && m.y.IsBounded())
    step->annotations = {{"gps_x_lo", m.x.lo()}, {"gps_x_hi", m.x.hi()},
                         {"gps_y_lo", m.y.lo()}, {"gps_y_hi", m.y.hi()}};
  const CarTrackRecord& newest = records_[k];
  if (newest.has_truth) step->truth = {newest.truth_x, newest.truth_y, newest.truth_theta};
  if (!truth_known) return true;
  // The window's frame: its oldest heading in [-pi, pi] (from step 0, the
  // drive's own frame).
  const double two_pi = 2 * kPi;
  const double shift =
      oldest == 0 ? 0 : std::ceil((records_[oldest].truth_theta - kPi) / two_pi) * two_pi;
  for (int j = oldest; j <= k; ++j) {
    const CarTrackRecord& r = records_[j];
    step->csp_truth.insert(step->csp_truth.end(), {r.truth_x, r.truth_y, r.truth_theta - shift});
  }
  return true;
}

// --- CSV log ----------------------------------------------------------------

namespace {

enum Column {
  kT,
  kOdoLeft,
  kOdoRight,
  kGyro,
  kGpsX,
  kGpsY,
  kGpsEx,
  kGpsEy,
  kTruthX,
  kTruthY,
  kTruthTheta,
  kNumColumns
};
constexpr const char* kColumnNames[kNumColumns] = {
    "t",      "odo_left_ticks", "odo_right_ticks", "gyro_dtheta", "gps_x",      "gps_y",
    "gps_ex", "gps_ey",         "truth_x",         "truth_y",     "truth_theta"};
constexpr int kFirstOptional = kTruthX;
// Largest tick count change between two rows (README): far above any wheel
// in 0.2 s, far below where the int64 difference overflows.
constexpr std::int64_t kMaxTickStep = std::int64_t{1} << 31;
// Physical bounds on the values (README): beyond them a value is a glitch,
// and one such value corrupts the unwrapped heading of every later row.
constexpr double kMaxTime = 1e12;      // s, about 31700 years
constexpr double kMaxPosition = 1e9;   // m, for gps_x, gps_y, truth_x, truth_y
constexpr double kMaxGpsError = 1e9;   // m, for gps_ex, gps_ey
constexpr double kMaxAngle = 1e6;      // rad, for truth_theta and gyro_dtheta
// Largest gap between the unwrapped truth heading's change and the gyro's
// reading on consecutive rows: a real car's stays far below it.
constexpr double kMaxHeadingMismatch = std::numbers::pi / 2;

class LogReader {
 public:
  explicit LogReader(std::string source) : source_(std::move(source)) {}

  std::vector<CarTrackRecord> Read(std::istream& in) {
    std::string line;
    std::vector<CarTrackRecord> records;
    bool have_header = false;
    while (std::getline(in, line)) {
      ++line_number_;
      const std::string_view text = TrimField(line);
      if (text.empty() || text.front() == '#') continue;
      if (!have_header) {
        ReadHeader(text);
        have_header = true;
        continue;
      }
      records.push_back(ReadRow(text));
      const CarTrackRecord* prev = records.size() > 1 ? &records[records.size() - 2] : nullptr;
      if (prev) CheckStep(*prev, records.back());
      UnwrapTruthHeading(prev, records.back());
    }
    if (!have_header) throw std::invalid_argument(source_ + ": no header line");
    if (records.empty()) throw std::invalid_argument(source_ + ": no data rows");
    return records;
  }

 private:
  [[noreturn]] void Fail(const std::string& what) const {
    throw std::invalid_argument(source_ + ":" + std::to_string(line_number_) + ": " + what);
  }

  void ReadHeader(std::string_view text) {
    position_.fill(-1);
    names_.clear();
    for (std::string_view name : SplitCsvFields(text)) {
      names_.emplace_back(name);
      const int field = static_cast<int>(names_.size()) - 1;
      const auto* it = std::find(std::begin(kColumnNames), std::end(kColumnNames), name);
      if (it == std::end(kColumnNames)) {
        std::string known;
        for (const char* n : kColumnNames) known += (known.empty() ? "" : ", ") + std::string(n);
        Fail("header column " + std::to_string(field + 1) + ": unknown column '" +
             std::string(name) + "' (known: " + known + ")");
      }
      const int column = static_cast<int>(it - std::begin(kColumnNames));
      if (position_[column] >= 0) Fail("header: column '" + std::string(name) + "' repeated");
      position_[column] = field;
    }
    for (int c = 0; c < kFirstOptional; ++c)
      if (position_[c] < 0) Fail("header lacks column '" + std::string(kColumnNames[c]) + "'");
    const int truth_columns =
        (position_[kTruthX] >= 0) + (position_[kTruthY] >= 0) + (position_[kTruthTheta] >= 0);
    if (truth_columns != 0 && truth_columns != 3)
      Fail("header: truth_x, truth_y and truth_theta go together");
  }

  // What the problem derives from two consecutive rows must be meaningful.
  void CheckStep(const CarTrackRecord& prev, const CarTrackRecord& r) const {
    if (!(r.t > prev.t))
      Fail("column 't': " + FormatDouble(r.t) + " is not after the previous row's " +
           FormatDouble(prev.t));
    CheckTicks(kOdoLeft, prev.odo_left_ticks, r.odo_left_ticks);
    CheckTicks(kOdoRight, prev.odo_right_ticks, r.odo_right_ticks);
  }

  // A wrapped or reset counter would overflow the int64 difference or give a
  // displacement of kilometres in one step.
  void CheckTicks(int column, std::int64_t prev, std::int64_t now) const {
    std::int64_t diff = 0;
    if (__builtin_sub_overflow(now, prev, &diff) || diff > kMaxTickStep || diff < -kMaxTickStep)
      Fail(Where(column) + ": " + std::to_string(now) + " ticks after " + std::to_string(prev) +
           " on the previous row: a step of more than 2^31 ticks (a wrapped or reset counter?)");
  }

  std::string Where(int column) const {
    return "column " + std::to_string(position_[column] + 1) + " (" + kColumnNames[column] + ")";
  }

  std::string_view Field(int column) const {
    return position_[column] < 0 ? std::string_view() : fields_[position_[column]];
  }

  // Double(column) within [-limit, limit].
  double Bounded(int column, double limit, const char* unit) const {
    const double v = Double(column);
    if (!(std::fabs(v) <= limit))
      Fail(Where(column) + ": " + FormatDouble(v) + " is beyond +-" + FormatDouble(limit) + " " +
           unit);
    return v;
  }

  double Double(int column) const {
    const std::string_view f = Field(column);
    double v = 0;
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
      Fail(Where(column) + ": '" + std::string(f) + "' is not a finite number");
    return v;
  }

  std::int64_t Integer(int column) const {
    const std::string_view f = Field(column);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || end != f.data() + f.size())
      Fail(Where(column) + ": '" + std::string(f) + "' is not an integer");
    return v;
  }

  // True when every field of the group is given, false when all are empty.
  bool Group(std::initializer_list<int> columns, const char* what) const {
    int given = 0;
    for (int c : columns) given += !Field(c).empty();
    if (given != 0 && given != static_cast<int>(columns.size()))
      Fail(std::string(what) + " columns must be all given or all empty");
    return given != 0;
  }

  CarTrackRecord ReadRow(std::string_view text) {
    fields_ = SplitCsvFields(text);
    if (fields_.size() != names_.size())
      Fail(std::to_string(fields_.size()) + " fields, the header has " +
           std::to_string(names_.size()));
    CarTrackRecord r;
    r.t = Bounded(kT, kMaxTime, "s");
    r.odo_left_ticks = Integer(kOdoLeft);
    r.odo_right_ticks = Integer(kOdoRight);
    r.gyro_dtheta = Bounded(kGyro, kMaxAngle, "rad");
    r.has_gps = Group({kGpsX, kGpsY, kGpsEx, kGpsEy}, "gps_x, gps_y, gps_ex, gps_ey");
    if (r.has_gps) {
      r.gps_x = Bounded(kGpsX, kMaxPosition, "m");
      r.gps_y = Bounded(kGpsY, kMaxPosition, "m");
      r.gps_ex = Bounded(kGpsEx, kMaxGpsError, "m");
      r.gps_ey = Bounded(kGpsEy, kMaxGpsError, "m");
      if (!(r.gps_ex > 0)) Fail(Where(kGpsEx) + ": " + FormatDouble(r.gps_ex) + " must be > 0");
      if (!(r.gps_ey > 0)) Fail(Where(kGpsEy) + ": " + FormatDouble(r.gps_ey) + " must be > 0");
    }
    r.has_truth = position_[kTruthX] >= 0 &&
                  Group({kTruthX, kTruthY, kTruthTheta}, "truth_x, truth_y, truth_theta");
    if (r.has_truth) {
      r.truth_x = Bounded(kTruthX, kMaxPosition, "m");
      r.truth_y = Bounded(kTruthY, kMaxPosition, "m");
      r.truth_theta = Bounded(kTruthTheta, kMaxAngle, "rad");
    }
    return r;
  }

  // The CSP carries the unwrapped heading from th[0] in [-pi, pi]: r's is
  // moved within pi of the previous known one. Where the previous row has a
  // truth too, the change must agree with the gyro: a glitch that still lies
  // within kMaxAngle would otherwise shift every later heading by 2 pi.
  void UnwrapTruthHeading(const CarTrackRecord* prev, CarTrackRecord& r) {
    if (!r.has_truth) return;
    const double two_pi = 2 * kPi;
    const double raw = r.truth_theta;
    const double turns = !have_known_heading_
                             ? std::ceil((raw - kPi) / two_pi)
                             : std::round((raw - last_known_heading_) / two_pi);
    if (turns != 0) r.truth_theta -= turns * two_pi;
    if (prev && prev->has_truth) {
      const double turn = r.truth_theta - prev->truth_theta;
      if (!(std::fabs(turn - r.gyro_dtheta) <= kMaxHeadingMismatch))
        Fail(Where(kTruthTheta) + ": " + FormatDouble(raw) + " turns the heading by " +
             FormatDouble(turn) + " rad since the previous row (unwrapped) but the gyro by " +
             FormatDouble(r.gyro_dtheta) + ": more than pi/2 apart");
    }
    last_known_heading_ = r.truth_theta;
    have_known_heading_ = true;
  }

  std::string source_;
  int line_number_ = 0;
  std::array<int, kNumColumns> position_{};
  std::vector<std::string> names_;
  std::vector<std::string_view> fields_;
  bool have_known_heading_ = false;
  double last_known_heading_ = 0;
};

}  // namespace

std::vector<CarTrackRecord> ReadCarTrackLog(std::istream& in, const std::string& source) {
  return LogReader(source).Read(in);
}

std::vector<CarTrackRecord> ReadCarTrackLog(const std::string& path) {
  // An ifstream opens a directory and then reads nothing ("no header line").
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::invalid_argument(path + ": is a directory, not a log file");
  // A device or a pipe (/dev/zero, /dev/stdin) could be read without end.
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw std::invalid_argument(path + ": is not a regular file, not a log file");
  std::ifstream in = OpenLogFile(path, "car-track log");
  return ReadCarTrackLog(in, path);
}

void WriteCarTrackLog(const std::vector<CarTrackRecord>& records, std::ostream& out,
                      const std::string& comment) {
  WriteLogComment(out, comment);
  for (int c = 0; c < kNumColumns; ++c) out << (c ? "," : "") << kColumnNames[c];
  out << "\n";
  for (const CarTrackRecord& r : records) {
    out << FormatDouble(r.t) << "," << r.odo_left_ticks << "," << r.odo_right_ticks << ","
        << FormatDouble(r.gyro_dtheta);
    if (r.has_gps) {
      out << "," << FormatDouble(r.gps_x) << "," << FormatDouble(r.gps_y) << ","
          << FormatDouble(r.gps_ex) << "," << FormatDouble(r.gps_ey);
    } else {
      out << ",,,,";
    }
    if (r.has_truth) {
      out << "," << FormatDouble(r.truth_x) << "," << FormatDouble(r.truth_y) << ","
          << FormatDouble(r.truth_theta);
    } else {
      out << ",,,";
    }
    out << "\n";
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

std::unique_ptr<Problem> MakeCarTrack(const ParamMap& params, std::uint64_t seed) {
  CarTrackParams p = ParseParams<CarTrackParams>("car-track", params);
  Validate(p);
  std::vector<CarTrackRecord> records =
      p.log.empty() ? SimulateCarTrack(p, seed) : ReadCarTrackLog(p.log);
  return std::make_unique<CarTrackProblem>(p, std::move(records));
}

}  // namespace icp
