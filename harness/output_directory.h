// Whether a command may write its output directory, asked before it writes:
// a directory it may not write is the environment (exit code 3), with what
// to do, even where a later error would lose the cause (SQLite reports a
// store it cannot create in a read-only directory as "unable to open").
#ifndef ICPBENCH_HARNESS_OUTPUT_DIRECTORY_H_
#define ICPBENCH_HARNESS_OUTPUT_DIRECTORY_H_

#include <string>

namespace icp {

// When dir exists, checks that a file can be created in it (by creating
// one, unnamed where the file system allows, and removing it: permission
// bits, read-only mounts and /sys answer alike, for root too); throws
// EnvironmentError "cannot write in DIR: REASON (ADVICE)", the advice ending
// with `elsewhere` (how this command writes elsewhere, e.g. "choose another
// --out"). A dir that does not exist is left alone: creating it reports its
// own error; but a dir that is a file, or lies under one, can never be made:
// std::invalid_argument "DIR: FILE is a file, not a directory (ELSEWHERE)".
void CheckWritableDirectory(const std::string& dir, const std::string& elsewhere);

// Creates dir and its parents for a command's output, checked as above
// first; a failure to create it is "cannot create DIR: REASON (ADVICE)",
// EnvironmentError where the environment is the cause.
void CreateOutputDirectory(const std::string& dir, const std::string& elsewhere);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_OUTPUT_DIRECTORY_H_
