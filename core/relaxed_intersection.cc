#include "core/relaxed_intersection.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace icp {

namespace {
// The lowest point covered by `need` of the closed intervals [lo_i, hi_i]:
// sweeping up, a lower bound opens an interval and an upper bound strictly
// below the current point has closed one. Both lists sorted ascending.
double LowestCovered(const std::vector<double>& los, const std::vector<double>& his, int need) {
  int open = 0;
  std::size_t closed = 0;
  for (double lo : los) {
    while (closed < his.size() && his[closed] < lo) {
      ++closed;
      --open;
    }
    if (++open >= need) return lo;
  }
  return kInf;
}
}  // namespace

Interval RelaxedIntersection(std::span<const Interval> intervals, int q) {
  if (q < 0) throw std::invalid_argument("q-relaxed intersection: q = " + std::to_string(q) + " must be >= 0");
  const int m = static_cast<int>(intervals.size());
  if (q >= m) return Interval::Entire();
  std::vector<double> los, his, neg_los, neg_his;
  los.reserve(intervals.size());
  his.reserve(intervals.size());
  for (const Interval& x : intervals) {
    if (x.IsEmpty()) continue;
    los.push_back(x.lo());
    his.push_back(x.hi());
  }
  const int need = m - q;
  if (static_cast<int>(los.size()) < need) return Interval::Empty();
  std::sort(los.begin(), los.end());
  std::sort(his.begin(), his.end());
  const double lo = LowestCovered(los, his, need);
  if (lo == kInf) return Interval::Empty();
  // The highest covered point: the same sweep on the mirrored intervals.
  neg_los.reserve(his.size());
  neg_his.reserve(los.size());
  for (auto it = his.rbegin(); it != his.rend(); ++it) neg_los.push_back(-*it);
  for (auto it = los.rbegin(); it != los.rend(); ++it) neg_his.push_back(-*it);
  const double hi = -LowestCovered(neg_los, neg_his, need);
  return Interval(lo, hi);
}

Box RelaxedIntersection(std::span<const Box> boxes, int q, std::size_t n) {
  if (q < 0) throw std::invalid_argument("q-relaxed intersection: q = " + std::to_string(q) + " must be >= 0");
  Box out(n);
  std::vector<Interval> components(boxes.size());
  for (std::size_t d = 0; d < n; ++d) {
    for (std::size_t i = 0; i < boxes.size(); ++i)
      components[i] = boxes[i].IsEmpty() ? Interval::Empty() : boxes[i][d];
    out[d] = RelaxedIntersection(components, q);
    if (out[d].IsEmpty()) {
      out.SetEmpty();
      break;
    }
  }
  return out;
}

}  // namespace icp
