// `icpbench --plugin` (core/plugin.h): the out-of-tree example
// (examples/plugin/), installed and built by tests/plugin_example.sh, which
// ctest runs first, and the fixture plugins of tests/plugin_fixtures/.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli_helpers.h"

namespace {

using icp::testing::Result;
using icp::testing::WriteFile;

const std::string kExample = PLUGIN_EXAMPLE;  // registers the algorithm hc4-twice

Result Icpbench(const std::string& args) { return icp::testing::RunCommand(ICPBENCH_BINARY, args); }

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

// The entry called name in a `list --format json` output, or null.
nlohmann::json Entry(const std::string& list_json, const std::string& name) {
  for (const nlohmann::json& entry : nlohmann::json::parse(list_json))
    if (entry["name"] == name) return entry;
  return nullptr;
}

TEST(PluginTest, ListsThePluginsAlgorithm) {
  Result r = Icpbench("--plugin " + kExample + " list algorithms --format json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json entry = Entry(r.out, "hc4-twice");
  ASSERT_FALSE(entry.is_null()) << r.out;
  std::vector<std::string> params;
  for (const nlohmann::json& p : entry["params"]) params.push_back(p["name"]);
  EXPECT_EQ(params, (std::vector<std::string>{"ratio", "max_revise_calls", "carry"}));
  EXPECT_FALSE(Entry(r.out, "hc4").is_null()) << "the tree's algorithms stay";
}

TEST(PluginTest, IsAcceptedAfterTheSubcommandAndRepeatable) {
  Result r = Icpbench("list problems --format json --plugin " + kExample + " --plugin " +
                      PLUGIN_EXTRA_PROBLEM);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_FALSE(Entry(r.out, "chain-copy").is_null()) << r.out;
}

TEST(PluginTest, SolvesToASoundBox) {
  // Paper 002 §2.2: x3 = x1 + x2 narrows to x1 in [3, 4], x2 in [1, 2],
  // x3 in [5, 6], every point of which is a solution's coordinate.
  Result r = Icpbench("solve " + std::string(ICPBENCH_EXAMPLES) +
                      "/paper002_sum.bch --algorithm hc4-twice --format json --plugin " + kExample);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["algorithm"], "hc4-twice");
  EXPECT_EQ(j["status"], "nonempty");
  EXPECT_EQ(j["box"]["x1"], nlohmann::json::parse("[3, 4]"));
  EXPECT_EQ(j["box"]["x2"], nlohmann::json::parse("[1, 2]"));
  EXPECT_EQ(j["box"]["x3"], nlohmann::json::parse("[5, 6]"));
}

TEST(PluginTest, RunsInTheWorkersAndReports) {
  const std::string spec = WriteFile("plugin_spec.yaml",
                                     "name: plugin\n"
                                     "algorithms: [hc4-twice]\n"
                                     "problems:\n"
                                     "  - {name: car-track, params: {steps: 5}}\n");
  const std::string out = ::testing::TempDir() + "plugin_run";
  std::filesystem::remove_all(out);
  Result run = Icpbench("--plugin " + kExample + " run " + spec + " --out " + out + " --jobs 1");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("1 ok, 0 failed"), std::string::npos) << run.out;

  Result report = Icpbench("report " + out + " --format csv --plugin " + kExample);
  ASSERT_EQ(report.exit_code, 0) << report.out;
  // The first table's header and its one row.
  std::istringstream lines(report.out);
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  const std::vector<std::string> names = SplitCsv(header), values = SplitCsv(row);
  ASSERT_EQ(names.size(), values.size()) << report.out;
  std::map<std::string, std::string> column;
  for (std::size_t i = 0; i < names.size(); ++i) column[names[i]] = values[i];
  EXPECT_EQ(column["algorithm"], "hc4-twice") << report.out;
  EXPECT_EQ(column["runs_ok"], "1") << report.out;
  EXPECT_EQ(column["runs_failed"], "0") << report.out;
  EXPECT_EQ(column["consistency_rate"], "1") << report.out;
}

// Loading plugin fails with exit code 2 and "plugin PLUGIN: CAUSE...".
void ExpectLoadError(const std::string& plugins, const std::string& plugin,
                     const std::string& cause) {
  Result r = Icpbench(plugins + " list algorithms");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("icpbench: plugin " + plugin + ": " + cause), std::string::npos) << r.out;
}

TEST(PluginTest, AMissingFileIsAnError) {
  const std::string missing = ::testing::TempDir() + "no_such_plugin.so";
  ExpectLoadError("--plugin " + missing, missing, "no such file");
}

TEST(PluginTest, AFileThatIsNoLibraryIsAnError) {
  const std::string text = WriteFile("not_a_library.so", "not a library\n");
  ExpectLoadError("--plugin " + text, text, "cannot load it: ");
}

TEST(PluginTest, ALibraryWithoutTheEntryPointIsAnError) {
  ExpectLoadError("--plugin " PLUGIN_NO_ENTRY_POINT, PLUGIN_NO_ENTRY_POINT,
                  "no entry point: a plugin defines extern \"C\" int icpbench_register_v1");
}

TEST(PluginTest, AFailingEntryPointIsAnError) {
  ExpectLoadError("--plugin " PLUGIN_FAILING, PLUGIN_FAILING,
                  "icpbench_register_v1 failed (returned 3): the fixture always fails");
}

TEST(PluginTest, ANameTheTreeHasIsAnError) {
  ExpectLoadError("--plugin " PLUGIN_TAKEN_NAME, PLUGIN_TAKEN_NAME,
                  "problem 'chain' is already registered");
}

// The same library given twice (or through another path to the same file)
// is loaded once: its names are not "already registered" by itself.
TEST(PluginTest, ALibraryGivenTwiceIsLoadedOnce) {
  const std::string link = ::testing::TempDir() + "plugin_link.so";
  std::filesystem::remove(link);
  std::filesystem::create_symlink(kExample, link);
  Result r = Icpbench("--plugin " + kExample + " list algorithms --format json --plugin " +
                      kExample + " --plugin " + link);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  int count = 0;
  for (const nlohmann::json& entry : nlohmann::json::parse(r.out))
    count += entry["name"] == "hc4-twice";
  EXPECT_EQ(count, 1) << r.out;
  std::filesystem::remove(link);
}

// A FIFO or a directory is refused before dlopen, which would wait on a
// FIFO forever (timeout stops the test's icpbench if it does).
TEST(PluginTest, APathThatIsNotARegularFileIsAnError) {
  const std::string fifo = ::testing::TempDir() + "plugin_fifo.so";
  std::filesystem::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const std::string dir = ::testing::TempDir() + "plugin_dir.so";
  std::filesystem::create_directories(dir);
  for (const auto& [path, kind] : {std::pair{fifo, "a FIFO"}, std::pair{dir, "a directory"}}) {
    Result r = icp::testing::RunCommand("timeout 20 " ICPBENCH_BINARY,
                                        "--plugin " + path + " list algorithms");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find("icpbench: plugin " + path + ": not a regular file (" + kind + ")"),
              std::string::npos)
        << r.out;
  }
  std::filesystem::remove(fifo);
}

// Names a plugin registers: lower-case letters, digits, '-' and '_' (as the
// tree's), so that keys, specs and the one-line progress stay readable.
TEST(PluginTest, ANameOutsideTheNamingRuleIsAnError) {
  const std::string rule = "a name is lower-case letters, digits, '-' and '_'";
  // The name, and as the message shows it (a control character escaped).
  const std::pair<std::string, std::string> cases[] = {
      {"Chain", "'Chain'"},   {"a|b", "'a|b'"},
      {"a{b}", "'a{b}'"},     {"a=b", "'a=b'"},
      {"a\nb", "'a\\nb'"},    {"a b", "'a b'"},
      {"-chain", "'-chain'"}, {std::string(65, 'a'), "'" + std::string(65, 'a') + "'"},
  };
  for (const auto& [name, shown] : cases) {
    setenv("ICPBENCH_TEST_PLUGIN_NAME", name.c_str(), 1);  // a newline stays one
    Result r = Icpbench("--plugin " PLUGIN_NAMED_PROBLEM " list problems");
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.out;
    EXPECT_NE(r.out.find("icpbench: plugin " PLUGIN_NAMED_PROBLEM ": problem " + shown +
                         " is not a valid name: " + rule),
              std::string::npos)
        << name << ": " << r.out;
  }
  for (const std::string good : {"chain_2", "3b-chain"}) {
    setenv("ICPBENCH_TEST_PLUGIN_NAME", good.c_str(), 1);
    Result r = Icpbench("--plugin " PLUGIN_NAMED_PROBLEM " list problems");
    EXPECT_EQ(r.exit_code, 0) << good << ": " << r.out;
    EXPECT_NE(r.out.find(good), std::string::npos) << r.out;
  }
  unsetenv("ICPBENCH_TEST_PLUGIN_NAME");
}

// The rule is the tree's own: every built-in name follows it.
TEST(PluginTest, TheTreesNamesFollowTheNamingRule) {
  const std::regex rule("[a-z0-9][a-z0-9_-]{0,63}");
  for (const std::string what : {"algorithms", "problems"}) {
    Result r = Icpbench("list " + what + " --format json");
    ASSERT_EQ(r.exit_code, 0) << r.out;
    for (const nlohmann::json& entry : nlohmann::json::parse(r.out))
      EXPECT_TRUE(std::regex_match(entry["name"].get<std::string>(), rule)) << entry["name"];
  }
}

// A parameter declared twice would be one key for two fields (the run key
// showing one value, the algorithm reading another), and one the command
// line cannot write could never be set: loading refuses both.
TEST(PluginTest, AParameterDeclaredTwiceOrUnwritableIsAnError) {
  const std::pair<std::string, std::string> cases[] = {
      {"fault", "faulty: parameter 'fault' is declared twice"},
      {"carry", "faulty: parameter 'carry' is declared twice"},  // the window adapter's
      {"my weird=key", "faulty: parameter 'my weird=key' is not a valid name"},
      {"", "faulty: parameter '' is not a valid name"},
  };
  for (const auto& [name, message] : cases) {
    setenv("ICPBENCH_TEST_PLUGIN_PARAM", name.c_str(), 1);
    Result r = Icpbench("--plugin " PLUGIN_FAULTY_CONTRACTOR " list algorithms");
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.out;
    EXPECT_NE(r.out.find("icpbench: plugin " PLUGIN_FAULTY_CONTRACTOR ": " + message), std::string::npos)
        << name << ": " << r.out;
  }
  setenv("ICPBENCH_TEST_PLUGIN_PARAM", "max_boxes-2", 1);
  Result r = Icpbench("--plugin " PLUGIN_FAULTY_CONTRACTOR " list algorithms");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  unsetenv("ICPBENCH_TEST_PLUGIN_PARAM");
}

// `solve` checks what a plugin's contractor returns, as `run` does: a NaN
// bound (which would read as an empty box, "no solution"), a box wider than
// its domains, another size, no contractor, an exception of any type; each
// exits 1 naming the algorithm instead of printing a wrong box or crashing.
TEST(PluginTest, SolveRefusesAnInvalidResultNamingTheAlgorithm) {
  const std::string file = std::string(ICPBENCH_EXAMPLES) + "/paper002_sum.bch";
  const std::pair<std::string, std::string> cases[] = {
      {"nan", "algorithm 'faulty' returned an invalid box: x1 has a NaN bound"},
      {"outside", "algorithm 'faulty' returned an invalid box: x1 grew beyond its initial domain"},
      {"extra", "algorithm 'faulty' returned an invalid box: the box has 4 components, the CSP 3"},
      {"null", "algorithm 'faulty' made no contractor"},
      {"throw", "algorithm 'faulty' failed: faulty: deliberate failure"},
      {"throw-int", "algorithm 'faulty' threw an exception of unknown type"},
  };
  for (const auto& [fault, message] : cases) {
    Result r = Icpbench("solve " + file + " -a faulty -p fault=" + fault + " -f json --plugin " PLUGIN_FAULTY_CONTRACTOR);
    EXPECT_EQ(r.exit_code, 1) << fault << ": " << r.out;
    EXPECT_NE(r.out.find("icpbench: " + message), std::string::npos) << fault << ": " << r.out;
  }
  Result good = Icpbench("solve " + file + " -a faulty -f json --plugin " PLUGIN_FAULTY_CONTRACTOR);
  EXPECT_EQ(good.exit_code, 0) << good.out;
}

// With stdout and stderr closed (a daemon, 2>&-), the files a sweep opens
// must not become descriptors 1 and 2: an algorithm's debug print would
// then land in its worker's step file and fail the run.
TEST(PluginTest, ARunWithClosedOutputsKeepsAChattyAlgorithmsSteps) {
  const std::string spec = WriteFile("chatty_spec.yaml",
                                     "algorithms: [{name: faulty, params: {fault: chatty}}]\n"
                                     "problems: [{name: car-track, params: {steps: 5}}]\n");
  const std::string out = ::testing::TempDir() + "chatty_run";
  std::filesystem::remove_all(out);
  Result run = icp::testing::RunCommand(
      "sh", "-c '" ICPBENCH_BINARY " --plugin " PLUGIN_FAULTY_CONTRACTOR " run " + spec + " --out " + out +
                " --jobs 1 >&- 2>&-; echo exit=$?'");
  EXPECT_NE(run.out.find("exit=0"), std::string::npos) << run.out;
  Result runs = icp::testing::RunCommand("sqlite3", out + "/results.sqlite \"SELECT status, steps FROM runs\"");
  EXPECT_EQ(runs.out, "ok|5\n");
}

// A contraction that never checks its stop condition cannot hang `solve
// --timeout`: 5 s past the limit the command ends, naming the algorithm.
TEST(PluginTest, SolveEndsAContractionThatOutlivesItsTimeout) {
  const auto start = std::chrono::steady_clock::now();
  Result r = Icpbench("solve " + std::string(ICPBENCH_EXAMPLES) +
                      "/paper002_sum.bch -a faulty -p fault=hang --timeout 0.5 --plugin " PLUGIN_FAULTY_CONTRACTOR);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("icpbench: algorithm 'faulty' did not stop within 5 s past --timeout 0.5"), std::string::npos)
      << r.out;
  EXPECT_LT(seconds, 30);
}

}  // namespace
