#include "harness/output_directory.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "harness/environment_error.h"

namespace icp {

namespace {

// Creates and removes a file in dir; returns 0 or the errno of the failure.
int TryCreateFileIn(const std::string& dir) {
  // An unnamed file leaves nothing behind, whatever happens next.
  int fd = open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd >= 0) {
    close(fd);
    return 0;
  }
  if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) return errno;
  // A file system without O_TMPFILE: a named file, removed at once.
  const std::string probe = dir + "/.icpbench-write-check-" + std::to_string(getpid());
  fd = open(probe.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0) return errno == EEXIST ? 0 : errno;
  close(fd);
  unlink(probe.c_str());
  return 0;
}

}  // namespace

void CheckWritableDirectory(const std::string& dir, const std::string& elsewhere) {
  std::error_code ec;
  // The nearest part of the path that exists must be a directory.
  for (std::filesystem::path p = dir; !p.empty(); p = p.parent_path()) {
    const auto status = std::filesystem::status(p, ec);
    if (!std::filesystem::exists(status)) {
      if (p == p.parent_path()) break;
      continue;
    }
    if (!std::filesystem::is_directory(status))
      throw std::invalid_argument(dir + ": " + p.string() + " is a file, not a directory (" + elsewhere + ")");
    break;
  }
  if (!std::filesystem::is_directory(dir, ec)) return;
  // Any errno: a directory that takes no files (/proc says ENOENT) is not
  // one to write figures or a store in, whatever the reason.
  const int error = TryCreateFileIn(dir);
  if (error != 0)
    throw EnvironmentError("cannot write in " + dir + ": " + std::strerror(error) + " (" +
                           (IsEnvironmentErrno(error) ? EnvironmentAdvice(error, elsewhere)
                                                      : "this directory takes no files: " + elsewhere) +
                           ")");
}

void CreateOutputDirectory(const std::string& dir, const std::string& elsewhere) {
  CheckWritableDirectory(dir, elsewhere);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) ThrowErrno("cannot create " + dir, ec.value(), elsewhere);
}

}  // namespace icp
