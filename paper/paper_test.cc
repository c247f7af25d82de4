// The generated paper without a store's runs: every section says which spec
// produces them, and (with LaTeX installed) the sources compile; long
// tables are cut into parts that fit a page.
#include "paper/paper.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "paper/latex.h"
#include "paper/sections.h"
#include "report/report_testing.h"

namespace icp {
namespace {

std::map<std::string, std::string> Files(const PaperSources& sources) {
  return {sources.files.begin(), sources.files.end()};
}

TEST(PaperTest, AnEmptyStoreNamesTheSpecsOfEverySection) {
  const auto files = Files(GeneratePaper({}, "results/x/results.sqlite", "/nonexistent", {}));
  ASSERT_EQ(files.count("icpbench.tex"), 1u);
  for (const char* fragment : {"meta", "tally", "provenance", "paper000", "thesis003", "paper004",
                               "profiles", "limitations", "conclusion", "registry",
                               "performance"}) {
    const std::string name = std::string("generated/") + fragment + ".tex";
    ASSERT_EQ(files.count(name), 1u) << name;
    EXPECT_NE(files.at("icpbench.tex").find(std::string("\\input{generated/") + fragment + "}"),
              std::string::npos)
        << fragment;
  }
  EXPECT_NE(files.at("generated/provenance.tex").find("results/x/results.sqlite"),
            std::string::npos);
  EXPECT_NE(files.at("generated/paper000.tex").find("icpbench run specs/default.yaml produces"),
            std::string::npos);
  EXPECT_NE(files.at("generated/thesis003.tex").find("specs/marina.yaml"), std::string::npos);
  EXPECT_NE(files.at("generated/thesis003.tex").find("specs/relaxed.yaml"), std::string::npos);
  EXPECT_NE(files.at("generated/paper004.tex").find("specs/default.yaml (experiment window) produces"),
            std::string::npos);
  // A figure the plots skipped says why in its place.
  const auto with_figures = Files(
      GeneratePaper({testing::InExperiment(testing::MakeRun("hc4", {}, {}, 1, {1e-5}), "table1")},
                    "s", "/nonexistent", {"fig3_corridors: skipped: gnuplot not found"}));
  EXPECT_NE(with_figures.at("generated/paper000.tex").find("is not drawn: gnuplot not found."),
            std::string::npos)
      << with_figures.at("generated/paper000.tex");
}

// The rows' verdicts counted: in the abstract's macro and the conclusion,
// and each paper's differences discussed.
TEST(PaperTest, TheTallyCountsTheComparisonRows) {
  using testing::InExperiment;
  using testing::MakeRun;
  std::vector<RunRecord> runs;
  for (const char* a : {"hc4", "bc3", "bc4", "3b-bc4"})
    runs.push_back(InExperiment(MakeRun(a, {}, {{"w", "20"}, {"steps", "2000"}}, 1, {1e-5, 2e-5}),
                                "table1"));
  const PaperComparisons rows = ComparePapers(runs);
  int match = 0, differ = 0, no_data = 0, differ000 = 0;
  for (const ComparisonRow& r : rows.All()) {
    match += r.verdict == Verdict::kMatch;
    differ += r.verdict == Verdict::kDiffers;
    no_data += r.verdict == Verdict::kNoData;
  }
  for (const ComparisonRow& r : rows.paper000) differ000 += r.verdict == Verdict::kDiffers;
  // These runs decide some rows, both ways, and leave others without data.
  ASSERT_GT(match, 0);
  ASSERT_GT(differ000, 0);
  ASSERT_GT(no_data, 0);
  const std::string line = "Verdicts: " + std::to_string(match) + " match, " +
                           std::to_string(differ) + " differ, " + std::to_string(no_data) +
                           " no data";
  const auto files = Files(GeneratePaper(runs, "s", "/nonexistent", {}));
  EXPECT_NE(files.at("generated/tally.tex").find("\\newcommand{\\icpbenchtally}{" + line + "}"),
            std::string::npos)
      << files.at("generated/tally.tex");
  EXPECT_NE(files.at("generated/tally.tex")
                .find("\\newcommand{\\icpbenchclaims}{" +
                      std::to_string(match + differ + no_data) + "}"),
            std::string::npos);
  EXPECT_NE(files.at("generated/conclusion.tex").find(line + "."), std::string::npos)
      << files.at("generated/conclusion.tex");
  EXPECT_NE(files.at("icpbench.tex").find("\\icpbenchtally"), std::string::npos);
  // Paper 000's discussion has a paragraph for each of its differing rows.
  const std::string& p000 = files.at("generated/paper000.tex");
  const std::string discussion = p000.substr(p000.find("\\subsection{Discussion}"));
  for (std::size_t i = 0; i < rows.paper000.size(); ++i) {
    if (rows.paper000[i].verdict != Verdict::kDiffers) continue;
    EXPECT_NE(discussion.find(TexEscape(rows.paper000[i].item + ": the paper gives")),
              std::string::npos)
        << "row " << i + 1;
  }
  // The registries and the timing table are in the appendix.
  const std::string& main = files.at("icpbench.tex");
  EXPECT_LT(main.find("\\appendix"), main.find("\\input{generated/registry}"));
  EXPECT_LT(main.find("\\appendix"), main.find("\\input{generated/performance}"));
  EXPECT_EQ(main.find("every table and figure"), std::string::npos);
  // claims.json holds every row, with the claims file's id, place and quote.
  const nlohmann::json claims = nlohmann::json::parse(files.at("claims.json"));
  ASSERT_EQ(claims.size(), rows.All().size());
  EXPECT_EQ(claims[0]["paper"], "paper000");
  EXPECT_EQ(claims[0]["id"], rows.paper000[0].id);
  EXPECT_FALSE(claims[0]["quote"].get<std::string>().empty());
  EXPECT_EQ(claims[0]["verdict"], std::string(ToString(rows.paper000[0].verdict)));
}

TEST(PaperTest, LongTablesAreCutIntoParts) {
  std::vector<RunRecord> runs;
  for (int w = 1; w <= 50; ++w)
    runs.push_back(testing::MakeRun("hc4", {}, {{"w", std::to_string(w)}}, 1, {1e-5}));
  const std::string tex = PerformanceTex(runs, {"/nonexistent", {}});
  EXPECT_NE(tex.find("\\caption{Time per step of every configuration}"), std::string::npos);
  EXPECT_NE(tex.find("\\caption{Time per step of every configuration, continued}"),
            std::string::npos);
  // The notes once, after the last part.
  EXPECT_EQ(tex.find("Solve time per step over"), tex.rfind("Solve time per step over"));
  EXPECT_GT(tex.find("Solve time per step over"), tex.find("continued"));
}

TEST(PaperTest, TheEmptyPaperCompiles) {
  if (FindOnPath("latexmk").empty() || FindOnPath("pdflatex").empty())
    GTEST_SKIP() << "LaTeX not installed (bash scripts/deps.sh installs it)";
  const std::string dir = ::testing::TempDir() + "paper_test_empty_" + std::to_string(getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/generated");
  for (const auto& [path, text] : GeneratePaper({}, "s", dir + "/figures", {}).files)
    std::ofstream(dir + "/" + path) << text;
  RunLatexmk(dir, "icpbench");
  EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/icpbench.pdf"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace icp
