// `icpbench paper DIR` (docs/figures-and-paper.md): from a small store made
// here, the PDF exists and its text holds the numbers of the generated
// tables (read from `icpbench report`, not typed in) and the store's
// revision; no store exits 2, LaTeX missing exits 3, writing nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli_helpers.h"

namespace {

using icp::testing::Result;
using icp::testing::RunCommand;
using icp::testing::WriteFile;

Result Icpbench(const std::string& args) { return RunCommand(ICPBENCH_BINARY, args); }

bool OnPath(const std::string& program) { return RunCommand("command -v", program).exit_code == 0; }

// The cells of the Markdown row whose first cell is first; empty when none.
std::vector<std::string> Cells(const std::string& md, const std::string& first) {
  std::istringstream lines(md);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| " + first + " |", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream fields(line.substr(1));
    for (std::string cell; std::getline(fields, cell, '|');) {
      cells.push_back(cell.substr(1, cell.size() - 2));
    }
    return cells;
  }
  return {};
}

// What follows key up to the next ". " in text ("Revisions: abc. Note").
std::string After(const std::string& text, const std::string& key) {
  const std::size_t at = text.find(key);
  if (at == std::string::npos) return "";
  const std::size_t start = at + key.size();
  return text.substr(start, text.find(".", start) - start);
}

// Runs of white space as one space (form feeds, between pages, kept), so
// that phrases broken across lines are found.
std::string OneSpaced(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool space = c == ' ' || c == '\n' || c == '\t' || c == '\r';
    if (space && !out.empty() && out.back() == ' ') continue;
    out += space ? ' ' : c;
  }
  return out;
}

class PaperCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One directory per process: ctest runs each test in its own, maybe at
    // once.
    dir_ = ::testing::TempDir() + "paper_cli_" + std::to_string(getpid());
    std::filesystem::remove_all(dir_);
    const std::string spec =
        WriteFile("paper_cli.yaml",
                  "name: paper-cli\n"
                  "seeds: [1]\n"
                  "experiments:\n"
                  "  - name: table1\n"
                  "    algorithms: [hc4, bc4]\n"
                  "    problems: [{name: car-track, params: {w: 5, steps: 40}}]\n"
                  "  - name: window\n"
                  "    algorithms: [hc4, {name: hc4, params: {carry: none}}]\n"
                  "    problems: [{name: car-track, params: {w: [1, 2, 3], steps: 40}}]\n"
                  "  - name: lines-accumulator\n"
                  "    algorithms: [accumulator]\n"
                  "    problems: [{name: line-intersection, params: {lines: 20, outliers: 7}}]\n");
    run_ = Icpbench("run " + spec + " --out " + dir_ + " --jobs 2");
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  static std::string dir_;
  static Result run_;
};
std::string PaperCliTest::dir_;
Result PaperCliTest::run_;

TEST_F(PaperCliTest, ThePdfHoldsTheTablesNumbersAndTheRevision) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  if (!OnPath("latexmk") || !OnPath("pdftotext"))
    GTEST_SKIP() << "latexmk or pdftotext not on PATH (bash scripts/deps.sh installs them)";
  Result r = Icpbench("paper " + dir_);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string pdf = dir_ + "/paper/icpbench.pdf";
  EXPECT_NE(r.out.find(pdf), std::string::npos) << r.out;
  ASSERT_TRUE(std::filesystem::is_regular_file(pdf));
  Result text = RunCommand("pdftotext", pdf + " -");
  ASSERT_EQ(text.exit_code, 0) << text.out;
  text.out = OneSpaced(text.out);

  const Result report = Icpbench("report " + dir_);
  ASSERT_EQ(report.exit_code, 0) << report.out;
  // Table 1's measured ms and CSPs of each algorithm run, and the window
  // sweep's areas, as the report prints them.
  for (const std::string algorithm : {"HC4", "BC4"}) {
    const std::vector<std::string> cells = Cells(report.out, algorithm);
    ASSERT_GE(cells.size(), 8u) << algorithm << "\n" << report.out;
    for (int column : {2, 7}) {
      EXPECT_NE(cells[column], "—");
      EXPECT_NE(text.out.find(cells[column]), std::string::npos)
          << algorithm << " column " << column << ": " << cells[column];
    }
  }
  const std::vector<std::string> sweep = Cells(report.out, "hc4 {carry=none} [steps=40]");
  ASSERT_GE(sweep.size(), 5u) << report.out;
  EXPECT_NE(text.out.find(sweep[4]), std::string::npos) << "area " << sweep[4];
  // The provenance on the first page.
  const std::string revision = After(report.out, "Revisions: ");
  ASSERT_FALSE(revision.empty()) << report.out;
  const std::string first_page = text.out.substr(0, text.out.find('\f'));
  EXPECT_NE(first_page.find(revision), std::string::npos) << revision << "\n" << first_page;
  EXPECT_NE(first_page.find("machine"), std::string::npos);
  // Verdicts, and the sections this store lacks say which spec makes them.
  EXPECT_NE(text.out.find("published vs measured"), std::string::npos);
  EXPECT_NE(text.out.find("match"), std::string::npos);
  EXPECT_NE(text.out.find("specs/marina.yaml"), std::string::npos);
  // Paper 004's post-localization table: the PL area of a window run.
  const std::size_t paper004 = report.out.find("Paper 004: real-time vs post-localization");
  ASSERT_NE(paper004, std::string::npos) << report.out;
  const std::vector<std::string> post = Cells(report.out.substr(paper004), "hc4 {carry=none} [steps=40]");
  ASSERT_GE(post.size(), 8u) << report.out.substr(paper004);
  EXPECT_NE(post[7], "—");
  EXPECT_NE(text.out.find(post[7]), std::string::npos) << "post-localized area " << post[7];
  EXPECT_NE(text.out.find("real-time vs post-localization"), std::string::npos);
}

TEST_F(PaperCliTest, NoStoreExitsTwo) {
  const std::string missing =
      ::testing::TempDir() + "paper_cli_missing_" + std::to_string(getpid());
  std::filesystem::remove_all(missing);
  Result r = Icpbench("paper " + missing);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("no results store"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(missing + "/paper"));
}

TEST_F(PaperCliTest, LatexMissingExitsThreeAndWritesNothing) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  const std::string dir = dir_ + "_nolatex";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(dir_ + "/results.sqlite", dir + "/results.sqlite");
  // A PATH without latexmk (nor anything else).
  Result r = RunCommand("env PATH=/nonexistent " ICPBENCH_BINARY, "paper " + dir);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("latexmk"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("scripts/deps.sh"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/paper"));
  std::filesystem::remove_all(dir);
}

}  // namespace
