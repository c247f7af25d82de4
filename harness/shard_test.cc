#include "harness/shard.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace icp {
namespace {

EnvironmentLookup Env(std::map<std::string, std::string> vars) {
  return [vars = std::move(vars)](const char* name) -> const char* {
    const auto it = vars.find(name);
    return it == vars.end() ? nullptr : it->second.c_str();
  };
}

std::string ErrorOf(const std::map<std::string, std::string>& vars) {
  try {
    SlurmShard(Env(vars));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ShardTest, SlurmArrayTasksGiveTheirShard) {
  EXPECT_EQ(SlurmShard(Env({{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})),
            std::make_pair(2, 4));
  // --array=1-4: the index counts from MIN.
  EXPECT_EQ(SlurmShard(Env({{"SLURM_ARRAY_TASK_ID", "1"},
                            {"SLURM_ARRAY_TASK_MIN", "1"},
                            {"SLURM_ARRAY_TASK_MAX", "4"}})),
            std::make_pair(0, 4));
  EXPECT_EQ(SlurmShard(Env({{"SLURM_ARRAY_TASK_ID", "4"},
                            {"SLURM_ARRAY_TASK_MIN", "1"},
                            {"SLURM_ARRAY_TASK_MAX", "4"},
                            {"SLURM_ARRAY_TASK_COUNT", "4"}})),
            std::make_pair(3, 4));
  EXPECT_EQ(
      ParseShard("auto", Env({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "1"}})),
      std::make_pair(0, 1));
}

TEST(ShardTest, MissingOrInconsistentSlurmVariablesAreErrors) {
  EXPECT_NE(ErrorOf({}).find("SLURM_ARRAY_TASK_ID is not set"), std::string::npos);
  EXPECT_NE(ErrorOf({{"SLURM_ARRAY_TASK_ID", "1"}}).find("neither SLURM_ARRAY_TASK_COUNT"),
            std::string::npos);
  EXPECT_NE(ErrorOf({{"SLURM_ARRAY_TASK_ID", "x1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})
                .find("SLURM_ARRAY_TASK_ID='x1' is not a non-negative integer"),
            std::string::npos);
  EXPECT_NE(ErrorOf({{"SLURM_ARRAY_TASK_ID", "-1"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})
                .find("not a non-negative integer"),
            std::string::npos);
  EXPECT_NE(ErrorOf({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_COUNT", "4"}})
                .find("is not below SLURM_ARRAY_TASK_COUNT=4"),
            std::string::npos);
  EXPECT_NE(ErrorOf({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "0"}})
                .find("SLURM_ARRAY_TASK_COUNT=0"),
            std::string::npos);
  EXPECT_NE(ErrorOf({{"SLURM_ARRAY_TASK_ID", "5"},
                     {"SLURM_ARRAY_TASK_MIN", "1"},
                     {"SLURM_ARRAY_TASK_MAX", "4"}})
                .find("outside [SLURM_ARRAY_TASK_MIN, SLURM_ARRAY_TASK_MAX] = [1, 4]"),
            std::string::npos);
  EXPECT_NE(ErrorOf({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_MIN", "1"}})
                .find("SLURM_ARRAY_TASK_MIN is set but SLURM_ARRAY_TASK_MAX is not"),
            std::string::npos);
  // --array=0-8:2 (tasks 0, 2, ..., 8): 5 tasks over a range of 9 ids.
  EXPECT_NE(ErrorOf({{"SLURM_ARRAY_TASK_ID", "2"},
                     {"SLURM_ARRAY_TASK_MIN", "0"},
                     {"SLURM_ARRAY_TASK_MAX", "8"},
                     {"SLURM_ARRAY_TASK_COUNT", "5"}})
                .find("disagrees"),
            std::string::npos);
  EXPECT_THROW(ParseShard("3/3", Env({})), std::invalid_argument);
  EXPECT_THROW(ParseShard("a/b", Env({})), std::invalid_argument);
  EXPECT_THROW(ParseShard("", Env({})), std::invalid_argument);
}

constexpr const char* kSpec = R"(
seeds: [1, 2, 3]
experiments:
  - name: a
    algorithms: [hc4, {name: bc4, params: {ratio: [0.01, 0.001]}}]
    problems: [chain, {name: car-track, params: {steps: [3, 4], w: [2, 3]}}]
  - name: b
    repetitions: 4
    algorithms: [hc4, bc3]
    problems: [chain]
)";

std::vector<std::string> ShardKeys(const Spec& spec, int index, int count) {
  std::vector<std::string> keys;
  for (std::size_t i : ShardRuns(spec, index, count)) keys.push_back(spec.runs[i].spec.Key());
  return keys;
}

TEST(ShardTest, ShardsAreStableAndPartitionTheMatrix) {
  const Spec first = ParseSpec(kSpec, "spec.yaml");
  const Spec again = ParseSpec(kSpec, "elsewhere/spec.yaml");  // another machine's path
  ASSERT_GT(first.runs.size(), 20u);
  for (int count : {1, 3, 7}) {
    std::set<std::string> all;
    std::size_t total = 0;
    for (int i = 0; i < count; ++i) {
      const std::vector<std::string> keys = ShardKeys(first, i, count);
      EXPECT_EQ(keys, ShardKeys(again, i, count)) << i << "/" << count;
      total += keys.size();
      all.insert(keys.begin(), keys.end());
    }
    EXPECT_EQ(total, first.runs.size()) << count;       // no run in two shards
    EXPECT_EQ(all.size(), first.runs.size()) << count;  // every run in one
  }
  // The documented order (harness/spec.h): problems, then algorithms, then
  // grid points (last key fastest), then seeds.
  EXPECT_EQ(first.runs[0].spec.Key(),
            ParseSpec("algorithms: [hc4]\nproblems: [chain]\n", "x").runs[0].spec.Key());
  EXPECT_EQ(first.runs[1].spec.seed, 2u);
  EXPECT_EQ(first.runs[3].spec.algorithm, "bc4");
  EXPECT_EQ(first.runs[3].spec.algorithm_params.at("ratio"), "0.01");
  EXPECT_EQ(first.runs[6].spec.algorithm_params.at("ratio"), "0.001");
  EXPECT_EQ(first.runs[9].spec.problem, "car-track");
  EXPECT_EQ(first.runs[9].spec.problem_params.at("steps"), "3");
  EXPECT_EQ(first.runs[9].spec.problem_params.at("w"), "2");
  EXPECT_EQ(first.runs[12].spec.problem_params.at("w"), "3");
  EXPECT_EQ(first.runs[12].spec.problem_params.at("steps"), "3");
  EXPECT_THROW(ShardRuns(first, 2, 2), std::invalid_argument);
}

}  // namespace
}  // namespace icp
