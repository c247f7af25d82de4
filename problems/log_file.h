// The text log files of the problems (car-track, marina-sonar): opening one
// for reading and writing its '#' comment lines.
#ifndef ICPBENCH_PROBLEMS_LOG_FILE_H_
#define ICPBENCH_PROBLEMS_LOG_FILE_H_

#include <fstream>
#include <iosfwd>
#include <string>

namespace icp {

// Opens path for reading; throws std::invalid_argument "<path>: cannot open
// the <what>" when it cannot. Which kinds of file a problem refuses before
// (directories, devices) is its own choice, made before the call.
std::ifstream OpenLogFile(const std::string& path, const std::string& what);

// Writes comment to out as '#' lines, one for each of its lines (none when
// it is empty).
void WriteLogComment(std::ostream& out, const std::string& comment);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_LOG_FILE_H_
