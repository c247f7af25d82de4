#include "harness/progress.h"

#include <cstdio>
#include <ostream>

#include "harness/runner.h"

namespace icp {

Progress::Progress(std::ostream& out, bool terminal, int total)
    : out_(out), terminal_(terminal), total_(total), start_(std::chrono::steady_clock::now()) {}

void Progress::Done(const RunRecord& r, const SweepSummary& s, const std::string& where,
                    const std::string& in_flight) {
  ++done_;
  if (terminal_) {
    DrawBar(s, in_flight);
    if (r.status != RunStatus::kOk && r.status != RunStatus::kSkipped)
      out_ << "\n  " << ToString(r.status) << ": " << WithoutDefaults(r.spec).Key()
           << (where.empty() ? "" : " (" + where + ")") << ": " << r.reason << "\n";
    return;
  }
  out_ << "[" << done_ << "/" << total_ << "] " << ToString(r.status) << " " << WithoutDefaults(r.spec).Key()
       << " (" << FormatSeconds(r.wall_time_s) << (where.empty() ? "" : ", " + where) << ")"
       << (r.reason.empty() ? "" : ": " + r.reason);
  if (!in_flight.empty()) out_ << "  [in flight " << in_flight << ", ETA " << Eta() << "]";
  out_ << "\n" << std::flush;
}

void Progress::InFlight(const SweepSummary& s, const std::string& in_flight) {
  if (terminal_) DrawBar(s, in_flight);
}

void Progress::Finish() {
  if (terminal_ && done_ > 0) out_ << "\n";
}

void Progress::DrawBar(const SweepSummary& s, const std::string& in_flight) {
  const int width = 30;
  const int filled = total_ ? width * done_ / total_ : width;
  out_ << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done_ << "/"
       << total_ << " runs  ok " << s.ok << "  failed " << s.failed + s.timed_out;
  if (!in_flight.empty()) out_ << "  in flight " << in_flight;
  out_ << "  ETA " << Eta() << "   " << std::flush;
}

std::string Progress::FormatSeconds(double s) {
  char buf[32];
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%.1fs", s);
  } else if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%dh%02dm", static_cast<int>(s) / 3600, static_cast<int>(s) % 3600 / 60);
  }
  return buf;
}

std::string Progress::Eta() const {
  if (done_ == 0) return "?";
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return FormatSeconds(elapsed / done_ * (total_ - done_));
}

}  // namespace icp
