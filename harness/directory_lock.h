// The lock of an output directory: one process at a time writes DIR's
// results store (a `run`, rank 0 of an MPI sweep, or a `merge` into DIR).
#ifndef ICPBENCH_HARNESS_DIRECTORY_LOCK_H_
#define ICPBENCH_HARNESS_DIRECTORY_LOCK_H_

#include <iosfwd>
#include <stdexcept>
#include <string>

namespace icp {

// Another process (a `run`, a `merge`) holds the output directory's lock (bad input: exit 2).
class DirectoryLockedError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// An exclusive flock on DIR/.lock holding the holder's PID; the kernel
// drops it when the holder dies, so a PID left in an unlocked file is stale
// (taking it over is said on `messages`). The file is emptied, not removed,
// on release (removing it would let a waiting process lock a deleted file).
class DirectoryLock {
 public:
  DirectoryLock(const std::string& dir, std::ostream& messages);  // throws DirectoryLockedError
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  int fd() const { return fd_; }

 private:
  std::string ReadPid() const;
  int fd_ = -1;
};

}  // namespace icp

#endif  // ICPBENCH_HARNESS_DIRECTORY_LOCK_H_
