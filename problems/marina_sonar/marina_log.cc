// The marina-sonar CSV log (format at ReadMarinaLog and in README.md): the
// checked reader of a recorded drive and the writer of one.
#include "problems/marina_sonar/marina_sonar.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "problems/csv_fields.h"
#include "problems/log_file.h"

namespace icp {

namespace {

constexpr double kPi = std::numbers::pi;

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
      if (++line_number_ == 1) StripByteOrderMark(line);
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
        Fail("unknown row kind '" + QuoteForMessage(fields_[0]) + "' (step, return)");
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
      Fail("a " + std::string(fields_[0]) + " row takes " + std::to_string(N) +
           " fields after its kind; this one has " + std::to_string(fields_.size() - 1));
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
      Fail(Where(i) + ": '" + QuoteForMessage(f) + "' is not a finite number");
    if (!(std::fabs(v) <= limit))
      Fail(Where(i) + ": " + FormatDouble(v) + " is beyond +-" + FormatDouble(limit));
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
        Fail(Where(4) + ": '" + QuoteForMessage(fields_[5]) + "' must be 0, 1 or empty");
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
    out << "step," << FormatDouble(r.t) << "," << FormatDouble(r.dvl_u) << ","
        << FormatDouble(r.dvl_v) << "," << FormatDouble(r.dvl_error) << ","
        << FormatDouble(r.heading) << "," << FormatDouble(r.heading_error) << ",";
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

}  // namespace icp
