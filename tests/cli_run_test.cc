// `icpbench run` where its surroundings misbehave (an outside probe): a
// closed stderr, a lock file that is a link, and what its progress lines say.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/cli_helpers.h"

namespace {

using icp::testing::Result;
using icp::testing::WriteFile;

Result Icpbench(const std::string& args) { return icp::testing::RunCommand(ICPBENCH_BINARY, args); }

std::string FreshDir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + name;
  std::filesystem::remove_all(dir);
  return dir;
}

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const char kSpec[] = "seeds: [1, 2]\nalgorithms: [hc4]\nproblems: [{name: chain, params: {w: 3}}]\n";

TEST(CliRunTest, AClosedStderrNeitherStopsTheSweepNorChangesItsExitCode) {
  // SIGPIPE killed it at its first line (nothing ran) or at its summary (141).
  const std::string spec = WriteFile("cli_run_pipe.yaml", kSpec);
  const std::string dir = FreshDir("cli_run_pipe");
  const std::string code = dir + ".code";
  for (int pass = 0; pass < 2; ++pass) {  // a fresh sweep, then one with every run stored
    const std::string command = "sh -c '(sleep 0.3; " + std::string(ICPBENCH_BINARY) + " run " + spec +
                                " --out " + dir + "; echo $? > " + code + ") 2>&1 | true'";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_EQ(ReadAll(code), "0\n") << "pass " << pass;
    EXPECT_TRUE(std::filesystem::exists(dir + "/results.sqlite")) << "pass " << pass;
  }
  const std::string bad = WriteFile("cli_run_pipe_bad.yaml", "algorithms: [hc4]\n");
  const std::string command = "sh -c '(" + std::string(ICPBENCH_BINARY) + " run " + bad + " --out " + dir +
                              "; echo $? > " + code + ") 2>&1 | true'";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(ReadAll(code), "2\n");  // a spec error, said to nobody
  std::filesystem::remove_all(dir);
}

TEST(CliRunTest, ALockFileThatIsALinkIsRefusedAndItsTargetKept) {
  // It was opened through the link, truncated and given the run's PID.
  const std::string dir = FreshDir("cli_run_lock");
  std::filesystem::create_directories(dir);
  const std::string precious = WriteFile("cli_run_precious.txt", "precious data\n");
  std::filesystem::create_symlink(precious, dir + "/.lock");
  const Result r = Icpbench("run " + WriteFile("cli_run_lock.yaml", kSpec) + " --out " + dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(".lock is a symbolic link"), std::string::npos) << r.out;
  EXPECT_EQ(ReadAll(precious), "precious data\n");
  std::filesystem::remove_all(dir);
}

TEST(CliRunTest, ALogsLinesSayTheTimeSoFarAndTheEta) {
  // Only MPI sweeps said them: a Slurm log of a local sweep had neither.
  const std::string dir = FreshDir("cli_run_log");
  const Result r = Icpbench("run " + WriteFile("cli_run_log.yaml", kSpec) + " --out " + dir + " --jobs 1");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("[1/2] ok "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", ETA "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[elapsed "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[2/2] ok "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ETA 0.0s]"), std::string::npos) << r.out;  // nothing left after the last
  std::filesystem::remove_all(dir);
}

}  // namespace
