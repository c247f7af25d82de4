// Running the icpbench binary from a test (tests/cli_test.cc,
// tests/plugin_test.cc).
#ifndef ICPBENCH_TESTS_CLI_HELPERS_H_
#define ICPBENCH_TESTS_CLI_HELPERS_H_

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>

namespace icp::testing {

struct Result {
  int exit_code;
  std::string out;
};

// Runs `binary args` through the shell, stderr folded into the output.
inline Result RunCommand(const std::string& binary, const std::string& args) {
  const std::string command = binary + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (std::size_t n = fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  int status = pclose(pipe);
  return {WEXITSTATUS(status), out};
}

// Writes text to a file of the test's temporary directory; returns its path.
inline std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace icp::testing

#endif  // ICPBENCH_TESTS_CLI_HELPERS_H_
