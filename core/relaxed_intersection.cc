#include "core/relaxed_intersection.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace icp {

namespace {
void CheckQ(int q) {
  if (q < 0) throw std::invalid_argument("q-relaxed intersection: q = " + std::to_string(q) + " must be >= 0");
}

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

// Counts over a range of points: add to a range, read the maximum.
class MaxAddTree {
 public:
  explicit MaxAddTree(int points) : points_(points), max_(4 * points, 0), add_(4 * points, 0) {}
  void Add(int first, int last, int value) { Add(1, 0, points_ - 1, first, last, value); }
  int Max() const { return max_[1]; }

 private:
  void Add(int node, int l, int r, int first, int last, int value) {
    if (last < l || r < first) return;
    if (first <= l && r <= last) {
      max_[node] += value;
      add_[node] += value;
      return;
    }
    const int mid = (l + r) / 2;
    Add(2 * node, l, mid, first, last, value);
    Add(2 * node + 1, mid + 1, r, first, last, value);
    max_[node] = add_[node] + std::max(max_[2 * node], max_[2 * node + 1]);
  }
  int points_;
  std::vector<int> max_, add_;
};

// A box's extent along the sweep dimension, negated for a downward sweep so
// that every sweep runs upwards: it enters at `enter`, leaves past `leave`.
struct Extent {
  double enter, leave;
};
Extent ExtentOf(const Interval& x, bool downward) {
  return downward ? Extent{-x.hi(), -x.lo()} : Extent{x.lo(), x.hi()};
}

class Sweep {
 public:
  Sweep(std::span<const Box> boxes, int need) : boxes_(boxes), need_(need) {}

  // The lowest t (negated when downward: the highest) such that some point
  // with x_d = t lies in `need` of the boxes `live` (indices into boxes),
  // the other coordinates ranging over the dimensions `rest`; kInf if none.
  // Such a point, when it exists, is the corner of an intersection of closed
  // boxes, so t is a box bound: only those are tried, in ascending order.
  double FirstCovered(const std::vector<int>& live, std::size_t d, bool downward,
                      std::span<const std::size_t> rest) const {
    if (static_cast<int>(live.size()) < need_) return kInf;
    std::vector<double> enters, leaves;
    if (rest.empty()) {
      for (int i : live) {
        const Extent e = ExtentOf(boxes_[i][d], downward);
        enters.push_back(e.enter);
        leaves.push_back(e.leave);
      }
      std::sort(enters.begin(), enters.end());
      std::sort(leaves.begin(), leaves.end());
      return LowestCovered(enters, leaves, need_);
    }
    std::vector<int> by_enter = live, by_leave = live;
    std::sort(by_enter.begin(), by_enter.end(), [&](int a, int b) {
      return ExtentOf(boxes_[a][d], downward).enter < ExtentOf(boxes_[b][d], downward).enter;
    });
    std::sort(by_leave.begin(), by_leave.end(), [&](int a, int b) {
      return ExtentOf(boxes_[a][d], downward).leave < ExtentOf(boxes_[b][d], downward).leave;
    });
    return rest.size() == 1 ? SweepOverOne(by_enter, by_leave, d, downward, rest[0])
                            : SweepOverMany(by_enter, by_leave, d, downward, rest);
  }

 private:
  // One dimension r left: the boxes open at t as ranges over the sorted
  // bounds of r, the deepest point read from a max-add tree.
  double SweepOverOne(const std::vector<int>& by_enter, const std::vector<int>& by_leave, std::size_t d,
                      bool downward, std::size_t r) const {
    std::vector<double> coords;
    coords.reserve(2 * by_enter.size());
    for (int i : by_enter) {
      coords.push_back(boxes_[i][r].lo());
      coords.push_back(boxes_[i][r].hi());
    }
    std::sort(coords.begin(), coords.end());
    coords.erase(std::unique(coords.begin(), coords.end()), coords.end());
    auto index = [&](double v) {
      return static_cast<int>(std::lower_bound(coords.begin(), coords.end(), v) - coords.begin());
    };
    MaxAddTree tree(static_cast<int>(coords.size()));
    auto add = [&](int i, int value) { tree.Add(index(boxes_[i][r].lo()), index(boxes_[i][r].hi()), value); };
    std::size_t next = 0, closed = 0;
    while (next < by_enter.size()) {
      const double t = ExtentOf(boxes_[by_enter[next]][d], downward).enter;
      // A box whose extent ends below t entered earlier: t is past its enter.
      for (; closed < by_leave.size() && ExtentOf(boxes_[by_leave[closed]][d], downward).leave < t; ++closed)
        add(by_leave[closed], -1);
      for (; next < by_enter.size() && ExtentOf(boxes_[by_enter[next]][d], downward).enter == t; ++next)
        add(by_enter[next], +1);
      if (tree.Max() >= need_) return t;
    }
    return kInf;
  }

  // Several dimensions left: at each candidate t, whether the open boxes
  // share a point of depth `need` in the others, by the same sweep one
  // dimension down.
  double SweepOverMany(const std::vector<int>& by_enter, const std::vector<int>& by_leave, std::size_t d,
                       bool downward, std::span<const std::size_t> rest) const {
    std::vector<char> open(boxes_.size(), 0);
    std::vector<int> live;
    std::size_t next = 0, closed = 0;
    while (next < by_enter.size()) {
      const double t = ExtentOf(boxes_[by_enter[next]][d], downward).enter;
      for (; closed < by_leave.size() && ExtentOf(boxes_[by_leave[closed]][d], downward).leave < t; ++closed)
        open[by_leave[closed]] = 0;
      for (; next < by_enter.size() && ExtentOf(boxes_[by_enter[next]][d], downward).enter == t; ++next)
        open[by_enter[next]] = 1;
      live.clear();
      for (int i : by_enter)
        if (open[i]) live.push_back(i);
      if (FirstCovered(live, rest[0], false, rest.subspan(1)) < kInf) return t;
    }
    return kInf;
  }

  std::span<const Box> boxes_;
  int need_;
};
}  // namespace

Interval RelaxedIntersection(std::span<const Interval> intervals, int q) {
  CheckQ(q);
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
  CheckQ(q);
  const int m = static_cast<int>(boxes.size());
  Box out(n);
  if (q >= m) return out;
  std::vector<int> live;
  for (int i = 0; i < m; ++i)
    if (!boxes[i].IsEmpty()) live.push_back(i);
  const Sweep sweep(boxes, m - q);
  std::vector<std::size_t> rest;
  for (std::size_t d = 0; d < n; ++d) {
    rest.clear();
    for (std::size_t r = 0; r < n; ++r)
      if (r != d) rest.push_back(r);
    const double lo = sweep.FirstCovered(live, d, false, rest);
    if (lo == kInf) {
      out.SetEmpty();
      return out;
    }
    out[d] = Interval(lo, -sweep.FirstCovered(live, d, true, rest));
  }
  return out;
}

}  // namespace icp
