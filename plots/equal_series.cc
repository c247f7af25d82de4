// Series that coincide, drawn once under a joined label and named in the
// caption; when an axis spans decades.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "plots/figures_internal.h"

namespace icp::detail::plots {

namespace {

bool SameValue(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return a == b || std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b));
}

bool SameRows(const std::vector<std::vector<double>>& a,
              const std::vector<std::vector<double>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].size() != b[i].size()) return false;
    for (std::size_t j = 0; j < a[i].size(); ++j)
      if (!SameValue(a[i][j], b[i][j])) return false;
  }
  return true;
}

// The parenthesised end of label, " (seed 1)"; "" when none.
std::string Suffix(const std::string& label) {
  if (label.empty() || label.back() != ')') return "";
  const std::size_t open = label.rfind(" (");
  return open == std::string::npos ? "" : label.substr(open);
}

}  // namespace

std::vector<std::vector<std::size_t>> EqualGroups(
    const std::vector<std::vector<std::vector<double>>>& rows) {
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    auto same = std::find_if(groups.begin(), groups.end(),
                             [&](const auto& g) { return SameRows(rows[g.front()], rows[i]); });
    if (same == groups.end())
      groups.push_back({i});
    else
      same->push_back(i);
  }
  return groups;
}

std::string JoinedLabel(const std::vector<std::string>& labels,
                        const std::vector<std::size_t>& group) {
  const std::string suffix = Suffix(labels.at(group.front()));
  const bool shared =
      !suffix.empty() && std::all_of(group.begin(), group.end(),
                                     [&](std::size_t i) { return Suffix(labels.at(i)) == suffix; });
  std::string out;
  for (std::size_t i : group) {
    const std::string& label = labels.at(i);
    out += (out.empty() ? "" : " = ") +
           (shared ? label.substr(0, label.size() - suffix.size()) : label);
  }
  return out + (shared ? suffix : "");
}

void NoteEqualSeries(const std::string& figure, const std::vector<std::string>& labels,
                     const std::vector<std::vector<std::size_t>>& groups, const std::string& where,
                     PlotOutput* out) {
  for (const auto& g : groups) {
    if (g.size() < 2) continue;
    out->messages.push_back(figure + ": note: " + JoinedLabel(labels, g) + " draw the same values" +
                            (where.empty() ? "" : " (" + where + ")") + " and are drawn once");
  }
}

bool SpansDecades(const std::vector<double>& v) {
  double lo = INFINITY, hi = 0;
  for (double x : v) {
    if (std::isnan(x)) continue;
    if (!(x > 0) || !std::isfinite(x)) return false;
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  return hi > 0 && hi >= kLogSpan * lo;
}

}  // namespace icp::detail::plots
