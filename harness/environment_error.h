// Failures of the environment rather than of the input or of icpbench: disk
// full, descriptors or processes exhausted, permissions, a read-only file
// system, out of memory. `icpbench` exits 3 on them with what to do.
#ifndef ICPBENCH_HARNESS_ENVIRONMENT_ERROR_H_
#define ICPBENCH_HARNESS_ENVIRONMENT_ERROR_H_

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace icp {

class EnvironmentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether errno value e says the environment is at fault.
inline bool IsEnvironmentErrno(int e) {
  return e == ENOSPC || e == EDQUOT || e == EMFILE || e == ENFILE || e == EACCES || e == EPERM ||
         e == EROFS || e == EAGAIN || e == ENOMEM || e == EIO;
}

// How `run` and `plot` write elsewhere; merge and paper have their own.
inline constexpr char kChooseAnotherOut[] = "choose another --out";

// What the user can do about errno value e; `elsewhere` says how the
// command writes its output elsewhere.
inline std::string EnvironmentAdvice(int e, const std::string& elsewhere = kChooseAnotherOut) {
  switch (e) {
    case ENOSPC:
    case EDQUOT: return "free disk space (or " + elsewhere + ") and rerun";
    case EMFILE:
    case ENFILE: return "raise the descriptor limit (ulimit -n) or reduce --jobs";
    case EACCES:
    case EPERM:
    case EROFS: return "check the permissions of the output directory (or " + elsewhere + ")";
    case EAGAIN:
    case ENOMEM: return "reduce --jobs or free memory / raise the process limit (ulimit -u)";
    default: return "check the disk and the file system";
  }
}

// Throws EnvironmentError for an environment errno, std::runtime_error
// otherwise; the message is "what: strerror(e) (advice)".
[[noreturn]] inline void ThrowErrno(const std::string& what, int e,
                                    const std::string& elsewhere = kChooseAnotherOut) {
  const std::string message = what + ": " + std::strerror(e);
  if (IsEnvironmentErrno(e))
    throw EnvironmentError(message + " (" + EnvironmentAdvice(e, elsewhere) + ")");
  throw std::runtime_error(message);
}

}  // namespace icp

#endif  // ICPBENCH_HARNESS_ENVIRONMENT_ERROR_H_
