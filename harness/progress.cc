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
  if (r.status != RunStatus::kSkipped) ++ran_;  // a skipped run takes no time: not in the ETA
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
  out_ << "  [" << (in_flight.empty() ? "" : "in flight " + in_flight + ", ") << "elapsed "
       << FormatSeconds(Elapsed()) << ", ETA " << Eta() << "]\n"
       << std::flush;
}

void Progress::InFlight(const SweepSummary& s, const std::string& in_flight) {
  if (terminal_) DrawBar(s, in_flight);
}

void Progress::Finish() {
  if (terminal_ && drawn_) out_ << "\n";
}

void Progress::DrawBar(const SweepSummary& s, const std::string& in_flight) {
  const int width = 30;
  const int filled = total_ ? width * done_ / total_ : width;
  out_ << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done_ << "/"
       << total_ << " runs  ok " << s.ok << "  failed " << s.failed << "  timed out " << s.timed_out
       << "  skipped " << s.skipped;
  if (!in_flight.empty()) out_ << "  in flight " << in_flight;
  out_ << "  " << FormatSeconds(Elapsed()) << ", ETA " << Eta() << "   " << std::flush;
  drawn_ = true;
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

double Progress::Elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string Progress::Eta() const {
  if (done_ >= total_) return "0.0s";
  if (ran_ == 0) return "?";
  return FormatSeconds(Elapsed() / ran_ * (total_ - done_));
}

}  // namespace icp
