#include "report/report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/metrics.h"
#include "report/report_testing.h"
#include "harness/results_store.h"
#include "harness/spec.h"

namespace icp {
namespace {

using testing::InExperiment;
using testing::Lines;
using testing::MakeRun;
using testing::MarkdownRow;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// RFC 4180 fields of one line.
std::vector<std::string> CsvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

TEST(FormatNumberTest, SignificantDigitsWithoutTrailingZeros) {
  EXPECT_EQ(FormatNumber(0.52), "0.52");
  EXPECT_EQ(FormatNumber(1400), "1400");
  EXPECT_EQ(FormatNumber(0.487312), "0.4873");
  EXPECT_EQ(FormatNumber(12.3456), "12.35");
  EXPECT_EQ(FormatNumber(1), "1");
  EXPECT_EQ(FormatNumber(1400000), "1400000");
  EXPECT_EQ(FormatNumber(0), "0");
  EXPECT_EQ(FormatNumber(-2.5), "-2.5");
  EXPECT_EQ(FormatNumber(1.5e-5), "1.500e-05");
  EXPECT_EQ(FormatNumber(kNaN), "—");
  EXPECT_EQ(FormatNumber(std::numeric_limits<double>::infinity()), "∞");
}

TEST(ReportTest, RejectsUnknownFormat) {
  EXPECT_THROW(Report({}, "html"), std::invalid_argument);
  EXPECT_THROW(ReportDirectory("/nonexistent", "pdf"), std::invalid_argument);
}

TEST(ReportTest, MissingStoreIsAnError) {
  EXPECT_THROW(ReportDirectory("/nonexistent/icpbench-report-test", "md"), std::runtime_error);
}

TEST(ReportTest, EmptyStoreGivesHeadersAndDashes) {
  for (const char* format : {"md", "tex", "csv"}) {
    EXPECT_NO_THROW(Report({}, format)) << format;
  }
  const std::string md = Report({}, "md");
  EXPECT_NE(md.find("| algorithm | params | problem |"), std::string::npos);
  EXPECT_EQ(Lines(Report({}, "csv")).size(), 1u);
  // No paper's tables unless a caller adds them.
  EXPECT_EQ(md.find("Paper 000"), std::string::npos);
}

TEST(ReportTest, GroupsPoolStepsOverSeeds) {
  // Two seeds: times {1, 2, 3} and {4, 5} us; pooled median 3, mean 3.
  const std::vector<RunRecord> runs = {MakeRun("hc4", {}, {}, 1, {1e-6, 2e-6, 3e-6}),
                                       MakeRun("hc4", {}, {}, 2, {4e-6, 5e-6}),
                                       MakeRun("hc4", {}, {}, 3, {}, RunStatus::kTimeout, "600 s")};
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  ASSERT_EQ(groups.size(), 1u);
  const GroupSummary& g = groups[0];
  EXPECT_EQ(g.ok, 2);
  EXPECT_EQ(g.timeout, 1);
  EXPECT_TRUE(g.pooled);
  EXPECT_EQ(g.metrics.steps, 5);
  EXPECT_DOUBLE_EQ(g.metrics.time_median_s, 3e-6);
  EXPECT_DOUBLE_EQ(g.metrics.time_mean_s, 3e-6);
  EXPECT_DOUBLE_EQ(g.metrics.mean_area, 4);
  EXPECT_DOUBLE_EQ(g.metrics.consistency_rate, 1);
  EXPECT_LE(g.metrics.time_mean_ci_lo_s, 3e-6);
  EXPECT_GE(g.metrics.time_mean_ci_hi_s, 3e-6);
  ASSERT_EQ(g.problems.size(), 1u);
  EXPECT_EQ(g.problems[0], "timeout (seed 3): 600 s");

  const std::string md = Report(runs, "md");
  const std::string row = MarkdownRow(md, "hc4");
  EXPECT_NE(row.find("| default | car-track | default | 2 ok, 1 timeout | 5 | 4 | 1 | 0 | 3 |"),
            std::string::npos)
      << row;
  EXPECT_NE(md.find("- hc4 on car-track: timeout (seed 3): 600 s"), std::string::npos) << md;
}

TEST(ReportTest, RunsWithoutStepsCombineStoredMetrics) {
  RunRecord a = MakeRun("bc4", {}, {}, 1, {1e-3, 1e-3, 1e-3});
  RunRecord b = MakeRun("bc4", {}, {}, 2, {4e-3});
  a.steps.clear();
  b.steps.clear();
  const std::vector<GroupSummary> groups = SummariseGroups({a, b});
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_FALSE(groups[0].pooled);
  EXPECT_EQ(groups[0].metrics.steps, 4);
  EXPECT_DOUBLE_EQ(groups[0].metrics.time_mean_s, (3 * 1e-3 + 4e-3) / 4);
  EXPECT_TRUE(std::isnan(groups[0].metrics.time_median_s));
}

TEST(ReportTest, FailedOnlyGroupShowsDashes) {
  const std::vector<RunRecord> runs = {
      MakeRun("bc3", {}, {}, 1, {}, RunStatus::kFailed, "threw: bad | input")};
  const std::string md = Report(runs, "md");
  EXPECT_EQ(MarkdownRow(md, "bc3"),
            "| bc3 | default | car-track | default | 0 ok, 1 failed | 0 | — | — | — | — | — | — |");
  EXPECT_NE(md.find("- bc3 on car-track: failed (seed 1): threw: bad | input"), std::string::npos);
}

TEST(ReportTest, CallersTablesFollowInMarkdownAndTexNotCsv) {
  const std::vector<RunRecord> runs = {MakeRun("hc4", {}, {}, 1, {1e-3})};
  int calls = 0;
  const TableMaker more = [&](const std::vector<RunRecord>& seen) {
    ++calls;
    EXPECT_EQ(seen.size(), 1u);
    TextTable t;
    t.title = "Extra";
    t.headers = {"name", "value"};
    t.numeric = {false, true};
    t.rows = {{"a_b", "1"}};
    return std::vector<TextTable>{t};
  };
  const std::string md = Report(runs, "md", more);
  EXPECT_GT(md.find("## Extra"), md.find("## Runs per configuration"));
  EXPECT_EQ(MarkdownRow(md, "a_b"), "| a_b | 1 |");
  EXPECT_NE(Report(runs, "tex", more).find("a\\_b & 1 \\\\"), std::string::npos);
  EXPECT_EQ(Report(runs, "csv", more), Report(runs, "csv"));
  EXPECT_EQ(calls, 2);
}

TEST(ReportTest, ExperimentIsWhatFollowsTheLastHash) {
  RunRecord r = MakeRun("hc4", {}, {}, 1, {1e-3});
  EXPECT_EQ(ExperimentOf(r), "");
  r.spec_file = "specs/default.yaml";
  EXPECT_EQ(ExperimentOf(r), "");
  r.spec_file = "specs/a#b.yaml#table1";
  EXPECT_EQ(ExperimentOf(r), "table1");
  // A group is of an experiment when any of its runs is, whatever its status.
  const std::vector<RunRecord> runs = {
      MakeRun("hc4", {}, {}, 1, {1e-3}),
      InExperiment(MakeRun("hc4", {}, {}, 2, {}, RunStatus::kFailed, "boom"), "window")};
  const std::vector<GroupSummary> groups = SummariseGroups(runs);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].runs.size(), 2u);
  EXPECT_TRUE(HasExperiment(groups[0], "window"));
  EXPECT_FALSE(HasExperiment(groups[0], "table1"));
}

TEST(ReportTest, DisplayDataComeFromTheRegistry) {
  EXPECT_EQ(DisplayOf("3b-bc4").label, FindAlgorithm("3b-bc4").display.label);
  EXPECT_EQ(DisplayOf("hc4").colour, FindAlgorithm("hc4").display.colour);
  // An algorithm no longer registered (an old store) still shows.
  const Display gone = DisplayOf("gone");
  EXPECT_EQ(gone.label, "gone");
  EXPECT_EQ(gone.order, 1000);
  EXPECT_FALSE(gone.colour.empty());
  // Groups follow the display order, unknown names last.
  const std::vector<GroupSummary> groups = SummariseGroups(
      {MakeRun("gone", {}, {}, 1, {1e-3}), MakeRun("3b-bc4", {}, {}, 1, {1e-3}),
       MakeRun("hc4", {}, {}, 1, {1e-3})});
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].algorithm, "hc4");
  EXPECT_EQ(groups[1].algorithm, "3b-bc4");
  EXPECT_EQ(groups[2].algorithm, "gone");
}

TEST(ReportTest, TexUsesBooktabsAndEscapes) {
  const std::vector<RunRecord> runs = {
      MakeRun("hc4", {{"odd_name", "50%&#{x}$"}}, {}, 1, {1e-5}),  // µs: the unit's sign escaped
      MakeRun("hc4", {}, {}, 1, {}, RunStatus::kSkipped, "needs a_b")};
  const std::string tex = Report(runs, "tex");
  for (const char* s : {"\\toprule", "\\midrule", "\\bottomrule", "\\begin{tabular}"}) {
    EXPECT_NE(tex.find(s), std::string::npos) << s;
  }
  EXPECT_NE(tex.find("odd\\_name=50\\%\\&\\#\\{x\\}\\$"), std::string::npos) << tex;
  EXPECT_NE(tex.find("mean area (m$^2$)"), std::string::npos);
  EXPECT_NE(tex.find("time median ($\\mu$s)"), std::string::npos);
  EXPECT_NE(tex.find("\\item hc4 on car-track: skipped (seed 1): needs a\\_b"), std::string::npos);
  // Every escaped special sits in the tabular or in text, never raw.
  for (const std::string& line : Lines(tex)) {
    if (line.empty() || line[0] == '%') continue;
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '_' || line[i] == '&' || line[i] == '#') {
        if (line[i] == '&' && i > 0 && line[i - 1] == ' ' && i + 1 < line.size() &&
            line[i + 1] == ' ') {
          continue;  // a column separator
        }
        EXPECT_TRUE(i > 0 && line[i - 1] == '\\') << line;
      }
    }
  }
  EXPECT_EQ(TexEscape("a_b & {c} 100% #1 ~ ^ \\"),
            "a\\_b \\& \\{c\\} 100\\% \\#1 \\textasciitilde{} \\textasciicircum{} "
            "\\textbackslash{}");
  // Signs the default (OT1) text font lacks or LaTeX cannot read as UTF-8.
  EXPECT_EQ(TexEscape("q ≤ 2 < 3 > 1 | §5 ≥ −1"),
            "q $\\leq$ 2 $<$ 3 $>$ 1 \\textbar{} \\S{}5 $\\geq$ $-$1");
  // Latin-1 letters pass; any other character is its code point (pdflatex
  // stopped on a store named 結果), a byte that is not UTF-8 a '?'.
  EXPECT_EQ(TexEscape("結果 über \xF0\x9F\x98\x80 \xFF \xE7\xB5"),
            "[U+7D50][U+679C] über [U+1F600] ? ??");
}

TEST(ReportTest, CsvParsesBackWithOneColumnPerHeader) {
  const std::vector<RunRecord> runs = {
      MakeRun("hc4", {{"ratio", "0.1"}, {"note", "say \"hi\""}}, {{"w", "5"}}, 1, {2e-6, 4e-6}),
      MakeRun("bc3", {}, {}, 1, {}, RunStatus::kFailed, "boom, twice")};
  const std::vector<std::string> lines = Lines(Report(runs, "csv"));
  ASSERT_EQ(lines.size(), 3u);
  const std::vector<std::string> header = CsvFields(lines[0]);
  EXPECT_EQ(header.size(), 17u);
  EXPECT_EQ(header[0], "algorithm");
  EXPECT_EQ(header[14], "time_mean_us");
  for (std::size_t i = 1; i < lines.size(); ++i) {
    EXPECT_EQ(CsvFields(lines[i]).size(), header.size()) << lines[i];
  }
  // Ordered by problem params (default first), then algorithm.
  const std::vector<std::string> bc3 = CsvFields(lines[1]);
  const std::vector<std::string> hc4 = CsvFields(lines[2]);
  EXPECT_EQ(bc3[0], "bc3");
  EXPECT_EQ(bc3[5], "1");   // runs_failed
  EXPECT_EQ(bc3[9], "");    // mean area: NaN is empty
  EXPECT_EQ(hc4[1], "note=say \"hi\",ratio=0.1");
  EXPECT_EQ(hc4[3], "w=5");
  EXPECT_EQ(hc4[8], "2");   // steps
  EXPECT_EQ(hc4[14], "3");  // mean time, us
}

TEST(ReportTest, ParamSweepOrdersValuesNumerically) {
  std::vector<RunRecord> runs;
  for (const char* w : {"20", "5", "10"}) {
    const double ms = std::stod(w) / 10;
    runs.push_back(MakeRun("bc4", {}, {{"w", w}}, 1, {ms * 1e-3, ms * 1e-3}));
    runs.push_back(MakeRun("hc4", {}, {{"w", w}}, 1, {ms * 1e-3}));
  }
  runs.push_back(MakeRun("hc4", {}, {}, 2, {3e-3}));  // w = 20 by default: pooled with "20"
  runs.push_back(MakeRun("bc3", {}, {}, 1, {1e-3}));  // one w only: no sweep
  const std::vector<SweepPoint> points = ParamSweep(runs, "car-track", "w");
  ASSERT_EQ(points.size(), 6u);
  EXPECT_EQ(points[0].algorithm, "hc4");
  EXPECT_EQ(points[0].label, "hc4");
  EXPECT_EQ(points[0].value, 5);
  EXPECT_EQ(points[1].value, 10);
  EXPECT_EQ(points[2].value, 20);
  EXPECT_EQ(points[2].runs, 2);
  EXPECT_EQ(points[2].ok_runs.size(), 2u);
  EXPECT_DOUBLE_EQ(points[2].mean_time_s, 2.5e-3);
  EXPECT_EQ(points[3].algorithm, "bc4");
  // Other parameters make another configuration, labelled with them.
  runs.push_back(MakeRun("hc4", {{"ratio", "0.1"}}, {{"steps", "9"}, {"w", "5"}}, 1, {1e-3}));
  runs.push_back(MakeRun("hc4", {{"ratio", "0.1"}}, {{"steps", "9"}, {"w", "7"}}, 1, {1e-3}));
  const std::vector<SweepPoint> more = ParamSweep(runs, "car-track", "w");
  ASSERT_EQ(more.size(), 8u);
  EXPECT_EQ(more[3].label, "hc4 {ratio=0.1} [steps=9]");
  EXPECT_TRUE(ParamSweep(runs, "chain", "w").empty());
}

TEST(ReportTest, ReadsTheStoreOfADirectory) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("icpbench_report_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    // The store keeps effective parameters: every one, defaults resolved.
    ParamMap problem = ProblemDefaults("car-track");
    problem["w"] = "5";
    ResultsStore store(StorePath(dir.string()));
    store.Insert(MakeRun("hc4", AlgorithmDefaults("hc4"), problem, 1, {0.5e-3, 0.5e-3}));
  }
  // The tables show only what differs from the current defaults.
  const std::vector<RunRecord> runs = LoadRunsFromDirectory(dir.string());
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_TRUE(runs[0].spec.algorithm_params.empty());
  EXPECT_EQ(runs[0].spec.problem_params, (ParamMap{{"w", "5"}}));
  const std::string md = ReportDirectory(dir.string(), "md");
  EXPECT_EQ(MarkdownRow(md, "hc4"),
            "| hc4 | default | car-track | w=5 | 1 | 2 | 4 | 1 | 0 | 500 | 500 | 500 |");
  std::filesystem::remove_all(dir);
}

TEST(ReportTest, SaysWhenRunsComeFromSeveralRevisions) {
  std::vector<RunRecord> runs = {MakeRun("hc4", {}, {}, 1, {1e-3}), MakeRun("bc4", {}, {}, 1, {1e-3})};
  runs[0].provenance.git_revision = "aaaa";
  runs[1].provenance.git_revision = "aaaa";
  EXPECT_EQ(Report(runs, "md").find("code revisions"), std::string::npos);
  runs[1].provenance.git_revision = "bbbb";
  EXPECT_NE(Report(runs, "md").find("mix runs of 2 code revisions"), std::string::npos);
}

TEST(ReportTest, StoredEffectiveParametersShowAsTheirDifferenceFromTheDefaults) {
  EXPECT_EQ(NonDefaultParams({{"ratio", "0.001"}, {"carry", "first"}},
                             {{"ratio", "0.001"}, {"carry", "all"}, {"gone", "1"}}),
            (ParamMap{{"carry", "all"}, {"gone", "1"}}));
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("icpbench_report_defaults_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  {
    ResultsStore store(StorePath(dir.string()));
    store.Insert(MakeRun("hc4", {{"ratio", "0.001"}, {"carry", "first"}, {"max_revise_calls", "1000000"}},
                         {{"w", "20"}}, 1, {1e-3}));
    store.Insert(MakeRun("hc4", {{"ratio", "0.1"}, {"carry", "first"}, {"max_revise_calls", "1000000"}},
                         {{"w", "20"}}, 1, {1e-3}));
  }
  const std::vector<RunRecord> runs = LoadRunsFromDirectory(dir.string());
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_TRUE(runs[0].spec.algorithm_params.empty());
  EXPECT_EQ(runs[1].spec.algorithm_params, (ParamMap{{"ratio", "0.1"}}));
  std::filesystem::remove_all(dir);
}


// report/plot open the store read-only: an archived store (read-only file
// and directory) is reported and left byte for byte as it was, with no
// -wal/-shm created (checked directly: tests may run as root, where the
// permissions do not stop writes).
TEST(ReportTest, ReportsAReadOnlyStoreWithoutWritingIt) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("icpbench_report_readonly_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = StorePath(dir.string());
  {
    ResultsStore store(path);
    store.Insert(MakeRun("hc4", {}, {}, 1, {1e-3}));
  }
  auto bytes = [&] {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  const std::string before = bytes();
  fs::permissions(path, fs::perms::owner_read);
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string md = ReportDirectory(dir.string(), "md");
  EXPECT_NE(md.find("| hc4 |"), std::string::npos) << md;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"results.sqlite"}));
  EXPECT_EQ(bytes(), before);
  fs::permissions(dir, fs::perms::owner_all);
  fs::remove_all(dir);
}

// A zero-byte results.sqlite is an error, not a new empty store.
TEST(ReportTest, AZeroByteStoreIsAnError) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("icpbench_report_empty_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(StorePath(dir.string())).close();
  try {
    LoadRunsFromDirectory(dir.string());
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("empty file"), std::string::npos) << e.what();
  }
  EXPECT_EQ(fs::file_size(StorePath(dir.string())), 0u);
  EXPECT_THROW(LoadRunsFromDirectory((dir / "missing").string()), std::runtime_error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace icp
