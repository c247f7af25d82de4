#include "problems/visual_landmarks/feature_log.h"

#include <charconv>
#include <cmath>
#include <istream>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/params.h"
#include "problems/csv_fields.h"
#include "problems/log_file.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const char* const kStepFields[] = {"kind",       "t",       "ds",     "ds_error",
                                   "dtheta",     "dtheta_error", "gps_x", "gps_y",
                                   "gps_error",  "truth_x", "truth_y", "truth_theta"};
const char* const kTrackFields[] = {"kind", "t", "landmark", "u", "v", "pixel_error"};
const char* const kLandmarkFields[] = {"kind", "landmark", "x", "y", "z"};

// [centre - half, centre + half], rounded outward.
Interval Around(double centre, double half) { return Interval(centre) + Interval(-half, half); }

class Row {
 public:
  Row(std::vector<std::string_view> fields, const char* const* names, std::string source, int line)
      : fields_(std::move(fields)), names_(names), source_(std::move(source)), line_(line) {}

  std::invalid_argument Error(int i, const std::string& why) const {
    return std::invalid_argument(source_ + ":" + std::to_string(line_) + ": field " +
                                 std::to_string(i + 1) + " (" + names_[i] + "): " + why);
  }
  bool Empty(int i) const { return fields_[i].empty(); }
  // A finite number of magnitude at most limit; NaN when empty and allowed.
  double Number(int i, double limit, bool may_be_empty = false) const {
    if (Empty(i)) {
      if (may_be_empty) return kNaN;
      throw Error(i, "missing");
    }
    double v = 0;
    const std::string_view f = fields_[i];
    auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v))
      throw Error(i, "'" + QuoteForMessage(f) + "' is not a finite number");
    if (std::abs(v) > limit) throw Error(i, FormatDouble(v) + " is beyond " + FormatDouble(limit));
    return v;
  }
  double HalfWidth(int i, double limit) const {
    const double v = Number(i, limit);
    if (v < 0) throw Error(i, "a half-width must be >= 0");
    return v;
  }
  int Identity(int i) const {
    const double v = Number(i, 1e6);
    if (v < 0 || v != std::floor(v)) throw Error(i, "must be a non-negative integer");
    return static_cast<int>(v);
  }
  // All of fields first..last empty (returns false) or none (true).
  bool AllOrNone(int first, int last) const {
    int empty = 0;
    for (int i = first; i <= last; ++i) empty += Empty(i);
    if (empty != 0 && empty != last - first + 1)
      throw Error(first, std::string("give all of ") + names_[first] + " .. " + names_[last] +
                             " or none");
    return empty == 0;
  }

 private:
  std::vector<std::string_view> fields_;
  const char* const* names_;
  std::string source_;
  int line_;
};

constexpr double kPositionLimit = 1e9, kAngleLimit = 1e6;

}  // namespace

VisualDrive ReadFeatureLog(std::istream& in, const std::string& source) {
  VisualDrive drive;
  std::vector<double> times;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    if (++number == 1) StripByteOrderMark(line);
    const std::string_view text = TrimField(line);
    if (text.empty() || text.front() == '#') continue;
    std::vector<std::string_view> fields = SplitCsvFields(text);
    const std::string_view kind = fields[0];
    auto expect = [&](std::size_t n) {
      if (fields.size() != n)
        throw std::invalid_argument(source + ":" + std::to_string(number) + ": a " +
                                    std::string(kind) + " row has " + std::to_string(n) +
                                    " fields, this one " + std::to_string(fields.size()));
    };
    if (kind == "step") {
      expect(std::size(kStepFields));
      const Row row(fields, kStepFields, source, number);
      const double t = row.Number(1, 1e12);
      if (!times.empty() && !(t > times.back())) throw row.Error(1, "t must increase");
      times.push_back(t);
      VisualDriveStep step;
      const bool first = drive.steps.empty();
      step.ds = first ? Interval(0.0) : Around(row.Number(2, kPositionLimit), row.HalfWidth(3, kPositionLimit));
      step.dtheta =
          first ? Interval(0.0) : Around(row.Number(4, kAngleLimit), row.HalfWidth(5, kAngleLimit));
      step.gps = Box{Interval(), Interval()};
      if (row.AllOrNone(6, 8)) {
        const double e = row.HalfWidth(8, kPositionLimit);
        step.gps = Box{Around(row.Number(6, kPositionLimit), e), Around(row.Number(7, kPositionLimit), e)};
      }
      std::array<double, 3> pose{kNaN, kNaN, kNaN};
      if (row.AllOrNone(9, 11))
        pose = {row.Number(9, kPositionLimit), row.Number(10, kPositionLimit), row.Number(11, kAngleLimit)};
      drive.steps.push_back(std::move(step));
      drive.poses.push_back(pose);
    } else if (kind == "track") {
      expect(std::size(kTrackFields));
      const Row row(fields, kTrackFields, source, number);
      if (drive.steps.empty()) throw row.Error(0, "a track row before the first step row");
      if (row.Number(1, 1e12) != times.back())
        throw row.Error(1, "a track row repeats the t of its step row above");
      const int n = row.Identity(2);
      const double e = row.HalfWidth(5, 1e6);
      drive.steps.back().sightings.push_back({n, Around(row.Number(3, 1e9), e), Around(row.Number(4, 1e9), e)});
      if (static_cast<int>(drive.landmarks.size()) <= n)
        drive.landmarks.resize(n + 1, {kNaN, kNaN, kNaN});
    } else if (kind == "landmark") {
      expect(std::size(kLandmarkFields));
      const Row row(fields, kLandmarkFields, source, number);
      const int n = row.Identity(1);
      if (static_cast<int>(drive.landmarks.size()) <= n)
        drive.landmarks.resize(n + 1, {kNaN, kNaN, kNaN});
      // A second reference would silently replace the first (and blame the
      // estimator for the truth it then misses).
      if (!std::isnan(drive.landmarks[n][0]))
        throw row.Error(1, "landmark " + std::to_string(n) + "'s reference position given twice");
      drive.landmarks[n] = {row.Number(2, kPositionLimit), row.Number(3, kPositionLimit),
                            row.Number(4, kPositionLimit)};
    } else {
      throw std::invalid_argument(source + ":" + std::to_string(number) + ": unknown row kind '" +
                                  QuoteForMessage(kind) + "' (step, track, landmark)");
    }
  }
  if (drive.steps.empty()) throw std::invalid_argument(source + ": no step row");
  return drive;
}

VisualDrive ReadFeatureLog(const std::string& path) {
  std::ifstream in = OpenLogFile(path, "feature log");
  return ReadFeatureLog(in, path);
}

void WriteFeatureLog(const VisualDrive& drive, std::ostream& out, const std::string& comment) {
  WriteLogComment(out, comment);
  // Centre and a half-width such that the reader's [c - e, c + e] (Around,
  // rounded outward) holds [lo, hi]: one ulp more where rounding needs it.
  auto centre = [](const Interval& x) { return x.lo() + (x.hi() - x.lo()) / 2; };
  auto half = [&](const Interval& x) {
    const double c = centre(x);
    const double e = std::max(x.hi() - c, c - x.lo());
    return x.IsSubsetOf(Around(c, e)) ? e : std::nextafter(e, kInf);
  };
  auto number = [](double v) { return std::isnan(v) ? std::string() : FormatDouble(v); };
  for (std::size_t k = 0; k < drive.steps.size(); ++k) {
    const VisualDriveStep& s = drive.steps[k];
    const double t = static_cast<double>(k);
    out << "step," << FormatDouble(t) << ',' << FormatDouble(centre(s.ds)) << ','
        << FormatDouble(half(s.ds)) << ',' << FormatDouble(centre(s.dtheta)) << ','
        << FormatDouble(half(s.dtheta)) << ',';
    if (s.gps[0].IsBounded() && s.gps[1].IsBounded())
      out << FormatDouble(centre(s.gps[0])) << ',' << FormatDouble(centre(s.gps[1])) << ','
          << FormatDouble(std::max(half(s.gps[0]), half(s.gps[1])));
    else
      out << ",,";
    const auto& p = drive.poses[k];
    out << ',' << number(p[0]) << ',' << number(p[1]) << ',' << number(p[2]) << '\n';
    for (const LandmarkSighting& f : s.sightings)
      out << "track," << FormatDouble(t) << ',' << f.landmark << ',' << FormatDouble(centre(f.u))
          << ',' << FormatDouble(centre(f.v)) << ','
          << FormatDouble(std::max(half(f.u), half(f.v))) << '\n';
  }
  for (std::size_t n = 0; n < drive.landmarks.size(); ++n) {
    const auto& l = drive.landmarks[n];
    if (std::isnan(l[0])) continue;
    out << "landmark," << n << ',' << FormatDouble(l[0]) << ',' << FormatDouble(l[1]) << ','
        << FormatDouble(l[2]) << '\n';
  }
}

}  // namespace icp
