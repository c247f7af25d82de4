// A sweep's progress: a bar redrawn in place on a terminal, one line a
// finished run otherwise (a log, a Slurm output file). A failed run's reason
// is always shown.
#ifndef ICPBENCH_HARNESS_PROGRESS_H_
#define ICPBENCH_HARNESS_PROGRESS_H_

#include <chrono>
#include <iosfwd>
#include <string>

#include "harness/run_record.h"

namespace icp {

struct SweepSummary;

class Progress {
 public:
  Progress(std::ostream& out, bool terminal, int total);

  // A run finished (summary: the counts so far). `where` names where it ran
  // ("rank 2"); with `in_flight` ("1:2 2:1", runs in flight per rank) the
  // bar and each line show both, and the ETA.
  void Done(const RunRecord& r, const SweepSummary& s, const std::string& where = "",
            const std::string& in_flight = "");
  // Redraws the bar with the runs now in flight and the time so far (a
  // terminal only: a log gets a line per finished run, with both).
  void InFlight(const SweepSummary& s, const std::string& in_flight);
  void Finish();

 private:
  static std::string FormatSeconds(double s);
  void DrawBar(const SweepSummary& s, const std::string& in_flight);
  double Elapsed() const;  // seconds since the sweep started
  // From the runs that ran (not skipped) so far, for those left.
  std::string Eta() const;
  std::ostream& out_;
  bool terminal_;
  int total_;
  int done_ = 0;
  int ran_ = 0;         // done, not skipped
  bool drawn_ = false;  // the bar is on the terminal's last line
  std::chrono::steady_clock::time_point start_;
};

}  // namespace icp

#endif  // ICPBENCH_HARNESS_PROGRESS_H_
