// `icpbench --plugin` (core/plugin.h): the out-of-tree example
// (examples/plugin/), installed and built by tests/plugin_example.sh, which
// ctest runs first, and the fixture plugins of tests/plugin_fixtures/.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
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

TEST(PluginTest, RegisteringANameTwiceIsAnError) {
  ExpectLoadError("--plugin " + kExample + " --plugin " + kExample, kExample,
                  "algorithm 'hc4-twice' is already registered");
}

}  // namespace
