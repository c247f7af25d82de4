// Opening the problems' text files, writing their comment lines, and what
// their readers share.
#include "problems/log_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "problems/csv_fields.h"

namespace icp {

namespace {
// "a " or "an " before what.
std::string Article(const std::string& what) {
  return what.find_first_of("aeiou") == 0 ? "an " + what : "a " + what;
}
}  // namespace

std::ifstream OpenLogFile(const std::string& path, const std::string& what) {
  // A directory opens and reads as nothing; a pipe or a device (/dev/zero)
  // could block the reader, or never end: both are refused by their kind.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(status)) throw std::invalid_argument(path + ": is a directory, not " + Article(what));
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw std::invalid_argument(path + ": is not a regular file (a pipe or a device), not " + Article(what));
  errno = 0;
  std::ifstream in(path);
  if (!in) {
    const int error = errno;  // why: no such file, permission denied, ...
    throw std::invalid_argument(path + ": cannot open the " + what +
                                (error != 0 ? std::string(" (") + std::strerror(error) + ")" : ""));
  }
  return in;
}

std::string CutLogNote(const std::string& problem, const std::string& path, std::size_t rows,
                       long long steps) {
  if (steps < 0 || rows <= static_cast<std::size_t>(steps)) return "";
  const std::string s = std::to_string(steps), n = std::to_string(rows);
  return problem + ": the log " + path + " has " + n + " rows; steps = " + s + " uses the first " +
         s + " (give steps: " + n + " to use them all)";
}

void WriteLogComment(std::ostream& out, const std::string& comment) {
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << "\n";
}

void StripByteOrderMark(std::string& first_line) {
  if (first_line.compare(0, 3, "\xEF\xBB\xBF") == 0) first_line.erase(0, 3);
}

std::string QuoteForMessage(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  constexpr std::size_t kMaxQuoted = 80;
  std::string out;
  for (const char c : text.substr(0, kMaxQuoted)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    }
  }
  if (text.size() > kMaxQuoted) out += "...";
  return out;
}

void ReadCsvRows(
    std::istream& in, const std::string& source, const std::string& header,
    const std::function<void(const std::vector<std::string_view>& fields, const CsvRowError& fail)>&
        row) {
  std::string line;
  int number = 0;
  bool seen_header = false;
  while (std::getline(in, line)) {
    if (++number == 1) StripByteOrderMark(line);
    const std::string_view text = TrimField(line);
    if (text.empty() || text.front() == '#') continue;
    const CsvRowError fail = [&](const std::string& why) {
      return std::invalid_argument(source + ":" + std::to_string(number) + ": " + why + " (" +
                                   QuoteForMessage(text) + ")");
    };
    const std::vector<std::string_view> fields = SplitCsvFields(text);
    if (!seen_header) {
      std::string joined;
      for (std::string_view f : fields) joined += (joined.empty() ? "" : ",") + std::string(f);
      if (joined != header) throw fail("the header must be " + header);
      seen_header = true;
      continue;
    }
    row(fields, fail);
  }
  if (!seen_header) throw std::invalid_argument(source + ": no header line (" + header + ")");
}

}  // namespace icp
