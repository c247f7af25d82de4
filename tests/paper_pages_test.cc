// The paper's pages as a reader sees them (docs/figures-and-paper.md): from a
// small store made here, `icpbench paper` writes figures no larger than the
// page prints them (so that their 8-pt text prints at 8 pt or more), each
// figure draws data (not an empty frame), and no page of the PDF is
// empty or near blank. Pages and figures are rendered to PNG by pdftoppm
// and read with OpenCV; skips when LaTeX or poppler-utils is missing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <string>
#include <vector>

#include "tests/cli_helpers.h"

namespace {

namespace fs = std::filesystem;
using icp::testing::Result;
using icp::testing::RunCommand;
using icp::testing::WriteFile;

// What a page or a figure must hold. At 40 dpi the pages of the default
// suite's paper darken 1.9 to 26 % of their pixels (pixels below 235 of
// 255), a page with a heading alone well under 1 %. A figure's data is drawn
// in colour (algorithms, boxes, counts) and its frame, text and grid in grey:
// the default suite's figures have 0.8 to 47 % coloured pixels (channels
// more than 60 apart), the short marina track of the store below 0.25 %, an
// empty frame with title, labels and grid 0.02 %: 0.1 % parts them.
// Measured 2026-12-05 on results/default (docs/figures-and-paper.md).
constexpr double kMinPageInk = 0.01;
constexpr double kMinFigureColour = 0.001;
// A word's box (pdftotext -bbox) is its font's ascent plus descent, about
// 1.16 em: an 8-pt font gives 9.3 pt, the 5.3 pt of pdfcairo's default
// fontscale 6.2. The median over a figure's words, so that exponents and
// subscripts do not count.
constexpr double kMinWordHeightPt = 8;
// The printed size (plots/figures_internal.h: 6.5 in by 7.5 in), in points.
constexpr double kPrintWidthPt = 6.5 * 72, kPrintHeightPt = 7.5 * 72;

Result Icpbench(const std::string& args) { return RunCommand(ICPBENCH_BINARY, args); }

bool OnPath(const std::string& program) { return RunCommand("command -v", program).exit_code == 0; }

// The share of the PNG's pixels darker than near-white (a channel below
// 235), and of its coloured ones (the channels more than 60 apart).
double Share(const std::string& png, bool coloured) {
  const cv::Mat image = cv::imread(png, cv::IMREAD_COLOR);
  if (image.empty()) return -1;
  cv::Mat channels[3], lo, hi;
  cv::split(image, channels);
  cv::min(channels[0], channels[1], lo);
  cv::min(lo, channels[2], lo);
  cv::max(channels[0], channels[1], hi);
  cv::max(hi, channels[2], hi);
  const cv::Mat marked = coloured ? (hi - lo > 60) : (lo < 235);
  return static_cast<double>(cv::countNonZero(marked)) / static_cast<double>(image.total());
}

// The PNGs pdftoppm wrote for pdf (prefix-1.png, ...), in page order.
std::vector<std::string> Render(const std::string& pdf, const std::string& prefix, int dpi) {
  const Result r =
      RunCommand("pdftoppm", "-r " + std::to_string(dpi) + " -png " + pdf + " " + prefix);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  std::vector<std::string> pages;
  const fs::path dir = fs::path(prefix).parent_path();
  const std::string stem = fs::path(prefix).filename().string() + "-";
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(stem, 0) == 0 && e.path().extension() == ".png") pages.push_back(e.path());
  }
  std::sort(pages.begin(), pages.end());  // pdftoppm pads the numbers
  return pages;
}

// The median height (pt) of the words of a PDF; 0 when it has none.
double MedianWordHeight(const std::string& pdf) {
  const Result r = RunCommand("pdftotext", "-bbox " + pdf + " -");
  static const std::regex kWord(R"re(yMin="([0-9.]+)" xMax="[0-9.]+" yMax="([0-9.]+)")re");
  std::vector<double> heights;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), kWord);
       it != std::sregex_iterator(); ++it)
    heights.push_back(std::stod((*it)[2]) - std::stod((*it)[1]));
  if (heights.empty()) return 0;
  std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
  return heights[heights.size() / 2];
}

// "Page size: 468 x 288 pts" of pdfinfo, as {width, height}.
std::pair<double, double> PageSize(const std::string& pdf) {
  const Result r = RunCommand("pdfinfo", pdf);
  std::smatch m;
  if (!std::regex_search(r.out, m, std::regex(R"(Page size:\s+([0-9.]+) x ([0-9.]+) pts)")))
    return {-1, -1};
  return {std::stod(m[1]), std::stod(m[2])};
}

class PaperPagesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = ::testing::TempDir() + "paper_pages_" + std::to_string(getpid());
    fs::remove_all(dir_);
    // Short runs that draw every kind of figure the paper holds: corridors
    // and areas of equal runs (hc4, bc3 and bc4 agree on this track), a
    // window sweep over a decade, box polynomials, accumulators, the city,
    // a short marina drive and the corridor's two paths (paper 002).
    const std::string spec =
        WriteFile("paper_pages.yaml",
                  "name: paper-pages\n"
                  "seeds: [1]\n"
                  "experiments:\n"
                  "  - name: table1\n"
                  "    algorithms: [hc4, bc3, bc4]\n"
                  "    problems: [{name: car-track, params: {w: 5, steps: 60}}]\n"
                  "  - name: window\n"
                  "    algorithms: [hc4, {name: hc4, params: {carry: none}}]\n"
                  "    problems: [{name: car-track, params: {w: [1, 4, 20], steps: 30}}]\n"
                  "  - name: fig5_2\n"
                  "    algorithms: [{name: polynomial, params: {approximation: c3, p: [1, 10]}}]\n"
                  "    problems: [{name: line-intersection, params: {lines: 20, outliers: 7}}]\n"
                  "  - name: lines-accumulator\n"
                  "    algorithms: [accumulator]\n"
                  "    problems: [{name: line-intersection, params: {lines: 20, outliers: 7}}]\n"
                  "  - name: city-roads\n"
                  "    algorithms: [hc4]\n"
                  "    problems: [{name: city-roads, params: {steps: 40}}, "
                  "{name: city-roads, params: {roads: false, steps: 40}}]\n"
                  "  - name: marina-drive\n"
                  "    algorithms: [{name: q-relaxed, params: {mode: pave, epsilon: 2}}, "
                  "{name: particle-filter, params: {inject: 0}}]\n"
                  "    problems: [{name: marina-sonar, params: {start: known, steps: 60}}]\n"
                  "  - name: indoor\n"
                  "    algorithms: [landmark-tracking, dead-reckoning]\n"
                  "    problems: [{name: indoor-landmarks, params: {path: [a, b]}}]\n");
    run_ = Icpbench("run " + spec + " --out " + dir_ + " --jobs 2");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string dir_;
  static Result run_;
};
std::string PaperPagesTest::dir_;
Result PaperPagesTest::run_;

TEST_F(PaperPagesTest, FiguresPrintAtTheirSizeAndNoPageIsBlank) {
  ASSERT_EQ(run_.exit_code, 0) << run_.out;
  if (!OnPath("latexmk") || !OnPath("pdftoppm") || !OnPath("pdfinfo"))
    GTEST_SKIP() << "latexmk or poppler-utils not on PATH (bash scripts/deps.sh installs them)";
  const Result paper = Icpbench("paper " + dir_);
  ASSERT_EQ(paper.exit_code, 0) << paper.out;
  const std::string paper_dir = dir_ + "/paper";
  const fs::path pngs = fs::path(dir_) / "pngs";
  fs::create_directories(pngs);

  // Every figure: no larger than the page prints it, and drawn.
  std::vector<std::string> figures;
  for (const auto& e : fs::directory_iterator(paper_dir + "/figures"))
    if (e.path().extension() == ".pdf") figures.push_back(e.path());
  std::sort(figures.begin(), figures.end());
  EXPECT_GE(figures.size(), 10u) << paper.out;  // the kinds the spec above draws
  for (const std::string& pdf : figures) {
    const std::string name = fs::path(pdf).stem();
    const auto [width, height] = PageSize(pdf);
    EXPECT_GT(width, 0) << name;
    EXPECT_LE(width, kPrintWidthPt + 0.5) << name << " is shrunk to the page's width";
    EXPECT_LE(height, kPrintHeightPt + 0.5) << name << " is shrunk to the page's height";
    EXPECT_GE(MedianWordHeight(pdf), kMinWordHeightPt) << name << " prints its text below 8 pt";
    const std::vector<std::string> page = Render(pdf, (pngs / name).string(), 40);
    ASSERT_EQ(page.size(), 1u) << name;
    EXPECT_GE(Share(page[0], true), kMinFigureColour) << name << " draws no data: " << page[0];
  }

  // Every page of the paper holds something.
  const std::vector<std::string> pages =
      Render(paper_dir + "/icpbench.pdf", (pngs / "page").string(), 40);
  ASSERT_GE(pages.size(), 5u);
  for (const std::string& page : pages)
    EXPECT_GE(Share(page, false), kMinPageInk) << page << " is empty or near blank";
}

}  // namespace
