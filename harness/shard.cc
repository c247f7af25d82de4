#include "harness/shard.h"

#include <cstdlib>
#include <optional>
#include <stdexcept>

namespace icp {

namespace {

// A variable's value as a non-negative int; nullopt when unset. Anything
// else (empty, signs, spaces, letters, overflow) is an error naming it.
std::optional<long long> Number(const EnvironmentLookup& env, const char* name) {
  const char* value = env(name);
  if (value == nullptr) return std::nullopt;
  const std::string text = value;
  long long v = 0;
  bool ok = !text.empty() && text.size() <= 9;
  for (char c : text) {
    ok = ok && c >= '0' && c <= '9';
    if (ok) v = v * 10 + (c - '0');
  }
  if (!ok)
    throw std::invalid_argument(std::string("--shard auto: ") + name + "='" + text +
                                "' is not a non-negative integer");
  return v;
}

}  // namespace

std::pair<int, int> SlurmShard(const EnvironmentLookup& env) {
  const auto id = Number(env, "SLURM_ARRAY_TASK_ID");
  const auto count = Number(env, "SLURM_ARRAY_TASK_COUNT");
  const auto min = Number(env, "SLURM_ARRAY_TASK_MIN");
  const auto max = Number(env, "SLURM_ARRAY_TASK_MAX");
  if (!id)
    throw std::invalid_argument(
        "--shard auto: SLURM_ARRAY_TASK_ID is not set (run it as a task of a Slurm job array, "
        "sbatch --array=..., or give --shard i/n)");
  if (min.has_value() != max.has_value())
    throw std::invalid_argument(std::string("--shard auto: SLURM_ARRAY_TASK_") +
                                (min ? "MIN" : "MAX") + " is set but SLURM_ARRAY_TASK_" +
                                (min ? "MAX" : "MIN") + " is not");
  std::optional<std::pair<long long, long long>> from_range;
  if (min) {
    if (*min > *max)
      throw std::invalid_argument("--shard auto: SLURM_ARRAY_TASK_MIN=" + std::to_string(*min) +
                                  " is above SLURM_ARRAY_TASK_MAX=" + std::to_string(*max) +
                                  ": not the environment of a Slurm array task");
    if (*id < *min || *id > *max)
      throw std::invalid_argument("--shard auto: SLURM_ARRAY_TASK_ID=" + std::to_string(*id) +
                                  " is outside [SLURM_ARRAY_TASK_MIN, SLURM_ARRAY_TASK_MAX] = [" +
                                  std::to_string(*min) + ", " + std::to_string(*max) + "]");
    from_range = {{*id - *min, *max - *min + 1}};
  }
  if (count) {
    if (*count < 1)
      throw std::invalid_argument(
          "--shard auto: SLURM_ARRAY_TASK_COUNT=0: an array has at least one task (not the environment "
          "of a Slurm array task?)");
    if (from_range && from_range->second != *count)
      throw std::invalid_argument(
          "--shard auto: SLURM_ARRAY_TASK_COUNT=" + std::to_string(*count) +
          " disagrees with SLURM_ARRAY_TASK_MIN/MAX (" + std::to_string(*min) + ".." +
          std::to_string(*max) + ", " + std::to_string(from_range->second) +
          " tasks): a stepped or sparse --array has gaps in its task ids; use a contiguous "
          "range");
    const long long index = from_range ? from_range->first : *id;
    if (index >= *count)
      throw std::invalid_argument("--shard auto: SLURM_ARRAY_TASK_ID=" + std::to_string(*id) +
                                  " is not below SLURM_ARRAY_TASK_COUNT=" + std::to_string(*count) +
                                  " (arrays that start at 1 need SLURM_ARRAY_TASK_MIN and _MAX)");
    return {static_cast<int>(index), static_cast<int>(*count)};
  }
  if (!from_range)
    throw std::invalid_argument(
        "--shard auto: SLURM_ARRAY_TASK_ID is set but neither SLURM_ARRAY_TASK_COUNT nor "
        "SLURM_ARRAY_TASK_MIN/MAX is");
  return {static_cast<int>(from_range->first), static_cast<int>(from_range->second)};
}

std::pair<int, int> ParseShard(const std::string& text, const EnvironmentLookup& env) {
  if (text == "auto") return SlurmShard(env);
  const auto slash = text.find('/');
  try {
    if (slash != std::string::npos) {
      std::size_t a = 0, b = 0;
      const int i = std::stoi(text.substr(0, slash), &a);
      const int n = std::stoi(text.substr(slash + 1), &b);
      if (a == slash && b == text.size() - slash - 1 && n >= 1 && i >= 0 && i < n) return {i, n};
    }
  } catch (const std::exception&) {
  }
  throw std::invalid_argument("--shard " + text +
                              ": expected i/n with 0 <= i < n (shards count from 0: 0/3, 1/3, 2/3), or auto");
}

std::pair<int, int> ParseShard(const std::string& text) {
  return ParseShard(text, [](const char* name) { return std::getenv(name); });
}

std::vector<std::size_t> ShardRuns(const Spec& spec, int index, int count) {
  if (count < 1 || index < 0 || index >= count)
    throw std::invalid_argument("shard " + std::to_string(index) + "/" + std::to_string(count) +
                                ": expected 0 <= i < n");
  std::vector<std::size_t> out;
  for (std::size_t i = static_cast<std::size_t>(index); i < spec.runs.size();
       i += static_cast<std::size_t>(count))
    out.push_back(i);
  return out;
}

}  // namespace icp
