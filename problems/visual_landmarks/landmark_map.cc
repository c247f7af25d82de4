#include "problems/visual_landmarks/landmark_map.h"

#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/params.h"
#include "problems/log_file.h"

namespace icp {

namespace {
constexpr const char* kHeader = "landmark,x_lo,x_hi,y_lo,y_hi,z_lo,z_hi";
}  // namespace

LandmarkMap ReadLandmarkMap(std::istream& in, const std::string& source) {
  LandmarkMap map;
  ReadCsvRows(in, source, kHeader,
              [&](const std::vector<std::string_view>& fields, const CsvRowError& fail) {
    if (fields.size() != 7) throw fail("expected 7 fields, found " + std::to_string(fields.size()));
    int id = 0;
    if (auto [end, ec] = std::from_chars(fields[0].data(), fields[0].data() + fields[0].size(), id);
        ec != std::errc() || end != fields[0].data() + fields[0].size() || id < 0)
      throw fail("landmark must be a non-negative integer");
    double bound[6];
    for (int i = 0; i < 6; ++i) {
      const std::string_view f = fields[i + 1];
      auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), bound[i]);
      if (ec != std::errc() || end != f.data() + f.size() || !std::isfinite(bound[i]))
        throw fail("field " + std::to_string(i + 2) + " is not a finite number");
    }
    std::array<Interval, 3> box;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(bound[2 * axis] <= bound[2 * axis + 1])) throw fail("a lower bound above its upper one");
      box[axis] = Interval(bound[2 * axis], bound[2 * axis + 1]);
    }
    if (!map.emplace(id, box).second) throw fail("landmark " + std::to_string(id) + " twice");
  });
  // A repeat run with no landmark would localize by dead reckoning alone.
  if (map.empty()) throw std::invalid_argument(source + ": no landmark");
  return map;
}

LandmarkMap ReadLandmarkMap(const std::string& path) {
  std::ifstream in = OpenLogFile(path, "landmark map");
  return ReadLandmarkMap(in, path);
}

void WriteLandmarkMap(const LandmarkMap& map, std::ostream& out, const std::string& comment) {
  WriteLogComment(out, comment);
  out << kHeader << '\n';
  for (const auto& [id, box] : map) {
    out << id;
    for (const Interval& axis : box) out << ',' << FormatDouble(axis.lo()) << ',' << FormatDouble(axis.hi());
    out << '\n';
  }
}

}  // namespace icp
