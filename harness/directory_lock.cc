#include "harness/directory_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <ostream>

#include "harness/environment_error.h"

namespace icp {

DirectoryLock::DirectoryLock(const std::string& dir, std::ostream& messages) {
  const std::string path = (std::filesystem::path(dir) / ".lock").string();
  // Not through a symbolic link: the lock is truncated and written, and a
  // link would have it wipe whatever file it names.
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0 && errno == ELOOP)
    throw DirectoryLockedError(path + " is a symbolic link, not icpbench's lock file: remove it, "
                               "or write elsewhere (another --out or OUT_DIR)");
  if (fd_ < 0) ThrowErrno("cannot create the lock file " + path, errno);
  struct stat status {};
  if (fstat(fd_, &status) != 0 || !S_ISREG(status.st_mode)) {
    close(fd_);
    fd_ = -1;
    throw DirectoryLockedError(path + " is not a regular file, not icpbench's lock file: remove it, "
                               "or write elsewhere (another --out or OUT_DIR)");
  }
  const std::string holder = ReadPid();
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    close(fd_);
    fd_ = -1;
    if (e != EWOULDBLOCK) ThrowErrno("cannot lock " + path, e);
    throw DirectoryLockedError("output directory " + dir + " is in use by another run or merge: " + path +
                               " is held by PID " + (holder.empty() ? "?" : holder) +
                               ": wait for it to end, or write elsewhere (another --out or OUT_DIR)");
  }
  if (!holder.empty() && holder != std::to_string(getpid()))
    messages << "icpbench: took over stale lock of PID " << holder << " (" << path << ")\n";
  const std::string pid = std::to_string(getpid()) + "\n";
  if (ftruncate(fd_, 0) != 0 || pwrite(fd_, pid.data(), pid.size(), 0) < 0)
    ThrowErrno("cannot write " + path, errno);
}

DirectoryLock::~DirectoryLock() {
  if (fd_ < 0) return;
  if (ftruncate(fd_, 0) != 0) {
  }
  close(fd_);
}

std::string DirectoryLock::ReadPid() const {
  char buf[32] = {};
  const ssize_t n = pread(fd_, buf, sizeof buf - 1, 0);
  std::string s = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : "";
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  // A PID is digits: anything else is not one, and not echoed to the terminal.
  if (s.find_first_not_of("0123456789") != std::string::npos) return "? (the file holds no PID)";
  return s;
}

}  // namespace icp
