// Shards: splitting a spec's run matrix across machines or the tasks of a
// Slurm job array (`icpbench run SPEC --shard i/n|auto`). Shard i of n holds
// the runs whose index in the expanded matrix (Spec::runs, whose order
// depends only on the spec's text: see harness/spec.h) is i modulo n, so the
// same spec gives the same shards on every machine and after a rerun, and
// the n shards together are the whole matrix, each run in exactly one.
#ifndef ICPBENCH_HARNESS_SHARD_H_
#define ICPBENCH_HARNESS_SHARD_H_

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "harness/spec.h"

namespace icp {

// Reads an environment variable: nullptr when it is not set.
using EnvironmentLookup = std::function<const char*(const char*)>;

// "i/n" -> (i, n) with 0 <= i < n; "auto" -> SlurmShard(env). Throws
// std::invalid_argument (exit 2) with a message naming the option or the
// variables.
std::pair<int, int> ParseShard(const std::string& text, const EnvironmentLookup& env);
std::pair<int, int> ParseShard(const std::string& text);  // the process's environment

// The shard of this task of a Slurm job array: from SLURM_ARRAY_TASK_ID and
// SLURM_ARRAY_TASK_COUNT (index = TASK_ID, count = COUNT), or else from
// SLURM_ARRAY_TASK_MIN and _MAX (index = TASK_ID - MIN, count = MAX - MIN + 1;
// arrays may start at 1). Throws std::invalid_argument when TASK_ID is
// missing, a value is not a non-negative integer, or the values disagree
// (TASK_ID outside [MIN, MAX] or not below COUNT, COUNT and MIN/MAX giving
// different counts). A stepped array (--array=0-9:2) has gaps in its task
// ids: it is refused unless COUNT covers them (index < COUNT).
std::pair<int, int> SlurmShard(const EnvironmentLookup& env);

// The indices into spec.runs of shard index of count, in matrix order.
std::vector<std::size_t> ShardRuns(const Spec& spec, int index, int count);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_SHARD_H_
