// Opening the problems' text logs and writing their comment lines.
#include "problems/log_file.h"

#include <ostream>
#include <sstream>
#include <stdexcept>

namespace icp {

std::ifstream OpenLogFile(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open the " + what);
  return in;
}

void WriteLogComment(std::ostream& out, const std::string& comment) {
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << "\n";
}

}  // namespace icp
