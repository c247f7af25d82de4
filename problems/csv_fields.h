// The comma-separated rows of the problems' log and scene files: fields
// split at every comma, blanks (and a trailing '\r') trimmed.
#ifndef ICPBENCH_PROBLEMS_CSV_FIELDS_H_
#define ICPBENCH_PROBLEMS_CSV_FIELDS_H_

#include <string_view>
#include <vector>

namespace icp {

inline std::string_view TrimField(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// The fields of line, views into it; one (empty) field for an empty line.
inline std::vector<std::string_view> SplitCsvFields(std::string_view line) {
  std::vector<std::string_view> fields;
  while (true) {
    const std::size_t comma = line.find(',');
    fields.push_back(TrimField(line.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
  return fields;
}

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_CSV_FIELDS_H_
