// The text files of the problems (car-track and marina-sonar logs, the
// marina map's frame sidecar, beacon scenes): opening one for reading,
// writing its '#' comment lines, and what every reader does alike (a
// leading byte-order mark, file content quoted in a message).
#ifndef ICPBENCH_PROBLEMS_LOG_FILE_H_
#define ICPBENCH_PROBLEMS_LOG_FILE_H_

#include <fstream>
#include <functional>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace icp {

// Opens path for reading; throws std::invalid_argument "<path>: cannot open
// the <what>" when it cannot, and "<path>: is a directory, not a <what>" or
// "...: is not a regular file (a pipe or a device), not a <what>" for those
// kinds, which could read as nothing or block the reader.
std::ifstream OpenLogFile(const std::string& path, const std::string& what);

// The note (ProblemInfo::note) of a log with more rows than `steps` uses:
// "<problem>: the log <path> has <rows> rows; steps = <steps> uses the first
// <steps> (give steps: <rows> to use them all)", or empty when none is cut.
std::string CutLogNote(const std::string& problem, const std::string& path, std::size_t rows,
                       long long steps);

// Writes comment to out as '#' lines, one for each of its lines (none when
// it is empty).
void WriteLogComment(std::ostream& out, const std::string& comment);

// Removes the UTF-8 byte-order mark (EF BB BF) that some editors write at
// the start of a text file; a reader calls it on its first line.
void StripByteOrderMark(std::string& first_line);

// text as an error message quotes it: every byte outside printable ASCII
// (control bytes, NUL, DEL, bytes >= 0x80) written as \xHH, and the bytes
// after the first 80 as "...", so that a message stays one readable line
// whatever the file holds.
std::string QuoteForMessage(std::string_view text);

// What a row of a CSV file raises: the std::invalid_argument
// "<source>:<line>: <why> (<the row, quoted>)".
using CsvRowError = std::function<std::invalid_argument(const std::string& why)>;

// Reads a CSV file with one header (the landmark and indoor maps): a
// byte-order mark, '#' comment lines and blank lines skipped, the header's
// fields (blanks trimmed) must be `header`, then row(fields, fail) for each
// row after it. Throws std::invalid_argument "<source>:<line>: the header
// must be ..." or "<source>: no header line (...)".
void ReadCsvRows(
    std::istream& in, const std::string& source, const std::string& header,
    const std::function<void(const std::vector<std::string_view>& fields, const CsvRowError& fail)>&
        row);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_LOG_FILE_H_
