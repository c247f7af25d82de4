// The commands that write outside a sweep (plot, merge, paper) into a place
// they may not write: permission denied is the environment (exit code 3,
// docs/cli.md#exit-codes), a path that is a file bad input (exit 2), each
// with advice that names the command's own way to write elsewhere.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli_helpers.h"

namespace {

using icp::testing::Result;
using icp::testing::RunCommand;
using icp::testing::WriteFile;

Result Icpbench(const std::string& args) { return RunCommand(ICPBENCH_BINARY, args); }

bool OnPath(const std::string& program) { return RunCommand("command -v", program).exit_code == 0; }

// /sys refuses new files and directories even to root: a real permission
// error on every machine the tests run on (as in tests of `run --out`).
const std::string kUnwritable = "/sys/kernel";

class CliOutputsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = ::testing::TempDir() + "cli_outputs_" + std::to_string(getpid());
    std::filesystem::remove_all(dir_);
    const std::string spec = WriteFile("cli_outputs.yaml", "algorithms: [hc4]\nproblems: [chain]\n");
    run_ = Icpbench("run " + spec + " --out " + dir_ + "/store --jobs 1");
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  static std::string dir_;
  static Result run_;
};
std::string CliOutputsTest::dir_;
Result CliOutputsTest::run_;

TEST_F(CliOutputsTest, PlotIntoAnUnwritableDirectoryIsTheEnvironment) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  for (const std::string& out : {kUnwritable + "/icpbench_figures", kUnwritable}) {
    const Result r = Icpbench("plot " + dir_ + "/store --out " + out);
    EXPECT_EQ(r.exit_code, 3) << out << ": " << r.out;
    EXPECT_NE(r.out.find("permission"), std::string::npos) << out << ": " << r.out;
    EXPECT_NE(r.out.find("another --out"), std::string::npos) << out << ": " << r.out;
  }
}

// /proc takes no files (ENOENT, not a permission): plot exited 0 with no
// figure and gnuplot's PNG bytes on its stdout.
TEST_F(CliOutputsTest, PlotIntoADirectoryThatTakesNoFilesIsTheEnvironment) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  if (!std::filesystem::is_directory("/proc/self")) GTEST_SKIP() << "no /proc";
  const Result r = Icpbench("plot " + dir_ + "/store --out /proc");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("cannot write in /proc"), std::string::npos) << r.out;
  EXPECT_LT(r.out.size(), 2000u) << "gnuplot's output reached icpbench's";
}

TEST_F(CliOutputsTest, MergeIntoAnUnwritableDirectoryIsTheEnvironment) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  for (const std::string& out : {kUnwritable + "/icpbench_merged", kUnwritable}) {
    const Result r = Icpbench("merge " + out + " " + dir_ + "/store");
    EXPECT_EQ(r.exit_code, 3) << out << ": " << r.out;
    EXPECT_NE(r.out.find("permission"), std::string::npos) << out << ": " << r.out;
    EXPECT_NE(r.out.find("another OUT_DIR"), std::string::npos) << out << ": " << r.out;
    EXPECT_EQ(r.out.find("--out"), std::string::npos) << out << ": " << r.out;  // merge has none
  }
  // A new OUT_DIR is made only after the inputs are read: a bad input is
  // still bad input.
  const Result r = Icpbench("merge " + kUnwritable + "/icpbench_merged " + dir_ + "/no_store");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("no_store"), std::string::npos) << r.out;
}

// An output path that is a file, or under one, can never be a directory:
// bad input (exit 2) that names the file and how to write elsewhere, not
// the library's "filesystem error: cannot create directories".
TEST_F(CliOutputsTest, AnOutputPathThatIsAFileIsBadInput) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  const std::string file = WriteFile("cli_outputs_a_file", "not a directory\n");
  const std::string spec = WriteFile("cli_outputs_file.yaml", "algorithms: [hc4]\nproblems: [chain]\n");
  for (const auto& [args, advice] : std::vector<std::pair<std::string, std::string>>{
           {"plot " + dir_ + "/store --out " + file, "another --out"},
           {"plot " + dir_ + "/store --out " + file + "/figures", "another --out"},
           {"merge " + file + " " + dir_ + "/store", "another OUT_DIR"},
           {"run " + spec + " --out " + file + "/sub --jobs 1", "another --out"}}) {
    const Result r = Icpbench(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.out;
    EXPECT_NE(r.out.find(file + " is a file, not a directory"), std::string::npos) << args << ": " << r.out;
    EXPECT_NE(r.out.find(advice), std::string::npos) << args << ": " << r.out;
  }
}

// paper writes DIR/paper: DIR read-only (a user who may not write it; root
// may write anywhere, so the test drops to nobody when it runs as root).
TEST_F(CliOutputsTest, PaperInAnUnwritableDirectoryIsTheEnvironmentAndSaysWhatToDo) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  if (!OnPath("latexmk") || !OnPath("pdflatex"))
    GTEST_SKIP() << "LaTeX not on PATH (bash scripts/deps.sh installs it)";
  std::string as_user;
  if (geteuid() == 0) {
    if (!OnPath("setpriv")) GTEST_SKIP() << "root without setpriv: cannot drop to a user";
    as_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
  }
  const std::string dir = dir_ + "/read_only";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(dir_ + "/store/results.sqlite", dir + "/results.sqlite");
  namespace fs = std::filesystem;
  for (const std::string& d : {dir_, dir_ + "/store", dir})
    fs::permissions(d, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                           fs::perms::others_read | fs::perms::others_exec);
  fs::permissions(dir + "/results.sqlite", fs::perms::owner_read | fs::perms::owner_write |
                                               fs::perms::group_read | fs::perms::others_read);
  fs::permissions(dir, fs::perms::owner_write, fs::perm_options::remove);
  const Result r = RunCommand(as_user + ICPBENCH_BINARY, "paper " + dir);
  fs::permissions(dir, fs::perms::owner_write, fs::perm_options::add);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("permission"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("--out"), std::string::npos) << r.out;  // paper has none
  EXPECT_NE(r.out.find("copy"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir + "/paper"));
}

}  // namespace
