// What a run's worker process hands back to the process that records it: the
// run's summary (status, reason, time, metrics, properties; JSON text, NaN
// and infinities as strings) and, for a run that records its steps, a step
// file of one JSON line per step, written as the run goes so that neither
// process holds the steps. The local runner reads both from its forked
// workers; the MPI dispatcher receives both from the worker ranks.
#ifndef ICPBENCH_HARNESS_WORKER_OUTPUT_H_
#define ICPBENCH_HARNESS_WORKER_OUTPUT_H_

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "harness/results_store.h"
#include "harness/run_record.h"

namespace icp {

// The run without its steps (spec and provenance are the receiver's).
std::string SerializeSummary(const RunRecord& record);
// Throws (nlohmann::json or std::invalid_argument errors) on malformed text.
RunRecord DeserializeSummary(const std::string& text, const RunSpec& spec);

// A worker's output that cannot be read back: the run failed, the sweep goes on.
class WorkerOutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// The reason recorded for such a run.
std::string UnreadableWorkerOutput(const std::string& what);

// Writes one JSON line per step; write errors throw std::runtime_error
// naming the file (the run fails with that reason).
class StepFileWriter {
 public:
  explicit StepFileWriter(const std::string& path);
  ~StepFileWriter();
  StepFileWriter(const StepFileWriter&) = delete;
  StepFileWriter& operator=(const StepFileWriter&) = delete;
  void Write(const StepRecord& step);
  void Close();

 private:
  [[noreturn]] void Fail() const;
  std::string path_;
  std::FILE* file_;
};

// The steps a worker that died mid-run (killed at its time limit, crashed)
// had written: cuts the step file after its last complete step (the one
// being written is dropped) and returns their metrics (steps: how many;
// 0 when the file holds none or cannot be read).
RunMetrics RecoverStepFile(const std::string& path, std::uint64_t seed);

// Reads a step file back one step at a time, for ResultsStore::Insert;
// expects exactly `count` steps. Throws WorkerOutputError.
StepSource ReadStepFile(const std::string& path, int count);

// DIR/.steps-PID-TAG.ndjson: a step file of this process's (PID) in DIR.
std::string StepFilePath(const std::string& dir, const std::string& tag);
// Removes the step files a killed sweep left in DIR (the directory lock
// says no other sweep writes there).
void RemoveStaleStepFiles(const std::string& dir);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_WORKER_OUTPUT_H_
