// The car-track CSV log (format at ReadCarTrackLog and in README.md): the
// checked reader of a recorded drive and the writer of one.
#include "problems/car_track/car_track.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <string_view>

#include "problems/csv_fields.h"
#include "problems/log_file.h"

namespace icp {

namespace {

constexpr double kPi = std::numbers::pi;

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
      if (++line_number_ == 1) StripByteOrderMark(line);
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
             QuoteForMessage(name) + "' (known: " + known + ")");
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
      Fail(Where(kT) + ": " + FormatDouble(r.t) + " is not after the previous row's " +
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
    if (ec == std::errc::result_out_of_range && end == f.data() + f.size())
      Fail(Where(column) + ": '" + QuoteForMessage(f) +
           "' is out of the range of a double (too large, or too small to tell from 0)");
    if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
      Fail(Where(column) + ": '" + QuoteForMessage(f) + "' is not a finite number");
    return v;
  }

  std::int64_t Integer(int column) const {
    const std::string_view f = Field(column);
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || ec != std::errc() || end != f.data() + f.size())
      Fail(Where(column) + ": '" + QuoteForMessage(f) + "' is not an integer");
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
      Fail("the row has " + std::to_string(fields_.size()) + " field" +
           (fields_.size() == 1 ? "" : "s") + ", the header " + std::to_string(names_.size()));
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
  // moved within pi of the heading the gyro predicts from the previous known
  // one (not of that one itself: a true turn of more than pi between rows, a
  // spinning robot or a slow log, would unwrap the wrong way). Where the
  // previous row has a truth too, the change must agree with the gyro: a
  // glitch that still lies within kMaxAngle would otherwise shift every later
  // heading by 2 pi.
  void UnwrapTruthHeading(const CarTrackRecord* prev, CarTrackRecord& r) {
    gyro_since_known_heading_ += r.gyro_dtheta;
    if (!r.has_truth) return;
    const double two_pi = 2 * kPi;
    const double raw = r.truth_theta;
    const double predicted = last_known_heading_ + gyro_since_known_heading_;
    const double turns = !have_known_heading_ ? std::ceil((raw - kPi) / two_pi)
                                              : std::round((raw - predicted) / two_pi);
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
    gyro_since_known_heading_ = 0;
  }

  std::string source_;
  int line_number_ = 0;
  std::array<int, kNumColumns> position_{};
  std::vector<std::string> names_;
  std::vector<std::string_view> fields_;
  bool have_known_heading_ = false;
  double last_known_heading_ = 0;
  double gyro_since_known_heading_ = 0;  // the gyro's turn since that row
};

}  // namespace

std::vector<CarTrackRecord> ReadCarTrackLog(std::istream& in, const std::string& source) {
  return LogReader(source).Read(in);
}

std::vector<CarTrackRecord> ReadCarTrackLog(const std::string& path) {
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

}  // namespace icp
