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
  // All counts zero over `points` points (the storage is reused).
  void Reset(int points) {
    points_ = points;
    max_.assign(4 * points, 0);
    add_.assign(4 * points, 0);
  }
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
  int points_ = 0;
  std::vector<int> max_, add_;
};

// The live boxes' bounds, flat (box i, dimension d at i * n + d).
struct Bounds {
  std::size_t n;
  std::vector<double> lo, hi;
  double Lo(int i, std::size_t d) const { return lo[i * n + d]; }
  double Hi(int i, std::size_t d) const { return hi[i * n + d]; }
};

// The sweeps along dimension d with one other dimension r: the boxes by
// lower and by upper bound along d, and their bounds along r as ranks among
// the sorted bounds of r (the points a max-add tree counts over).
struct SweepPlan {
  std::vector<int> by_lo, by_hi;
  std::vector<int> rank_lo, rank_hi;  // indexed by box
  std::vector<double> coords;         // the sorted distinct bounds along r
  int points = 0;
};

void SortBy(const std::vector<int>& live, const std::vector<double>& key, std::size_t n, std::size_t d,
            std::vector<int>& out) {
  out.assign(live.begin(), live.end());
  std::sort(out.begin(), out.end(), [&](int a, int b) { return key[a * n + d] < key[b * n + d]; });
}

std::vector<int> SortedBy(const std::vector<int>& live, const std::vector<double>& key, std::size_t n,
                          std::size_t d) {
  std::vector<int> out;
  SortBy(live, key, n, d, out);
  return out;
}

// Fills plan (its storage reused) for the sweeps along d over r.
void Plan(const Bounds& b, const std::vector<int>& live, std::size_t d, std::size_t r, int boxes,
          SweepPlan& plan) {
  SortBy(live, b.lo, b.n, d, plan.by_lo);
  SortBy(live, b.hi, b.n, d, plan.by_hi);
  std::vector<double>& coords = plan.coords;
  coords.clear();
  for (int i : live) {
    coords.push_back(b.Lo(i, r));
    coords.push_back(b.Hi(i, r));
  }
  std::sort(coords.begin(), coords.end());
  coords.erase(std::unique(coords.begin(), coords.end()), coords.end());
  auto rank = [&](double v) {
    return static_cast<int>(std::lower_bound(coords.begin(), coords.end(), v) - coords.begin());
  };
  plan.rank_lo.resize(boxes);
  plan.rank_hi.resize(boxes);
  for (int i : live) {
    plan.rank_lo[i] = rank(b.Lo(i, r));
    plan.rank_hi[i] = rank(b.Hi(i, r));
  }
  plan.points = static_cast<int>(coords.size());
}

// The lowest box bound t along d (the highest, when downward) at which
// `need` boxes share a point: upward, a box enters at its lower bound and
// has left once t is past its upper bound; downward the reverse.
double SweepOne(const Bounds& b, const SweepPlan& plan, std::size_t d, bool downward, int need,
                MaxAddTree& tree) {
  const std::size_t m = plan.by_lo.size();
  tree.Reset(plan.points);
  auto enter_box = [&](std::size_t k) { return downward ? plan.by_hi[m - 1 - k] : plan.by_lo[k]; };
  auto leave_box = [&](std::size_t k) { return downward ? plan.by_lo[m - 1 - k] : plan.by_hi[k]; };
  auto enter_at = [&](int i) { return downward ? -b.Hi(i, d) : b.Lo(i, d); };
  auto leave_at = [&](int i) { return downward ? -b.Lo(i, d) : b.Hi(i, d); };
  auto add = [&](int i, int value) { tree.Add(plan.rank_lo[i], plan.rank_hi[i], value); };
  std::size_t next = 0, closed = 0;
  while (next < m) {
    const double t = enter_at(enter_box(next));
    // A box whose extent ends below t entered earlier: t is past its enter.
    for (; closed < m && leave_at(leave_box(closed)) < t; ++closed) add(leave_box(closed), -1);
    for (; next < m && enter_at(enter_box(next)) == t; ++next) add(enter_box(next), +1);
    if (tree.Max() >= need) return downward ? -t : t;
  }
  return downward ? -kInf : kInf;
}

// Whether `need` of the boxes `live` share a point, the coordinates ranging
// over the dimensions `dims` (at least two): a sweep along the first that
// stops at the first candidate where the open boxes reach that depth in the
// others. The general path for n > 2.
bool ReachDepth(const Bounds& b, const std::vector<int>& live, std::span<const std::size_t> dims, int need,
                int boxes) {
  if (static_cast<int>(live.size()) < need) return false;
  const std::size_t d = dims[0];
  if (dims.size() == 2) {
    SweepPlan plan;
    MaxAddTree tree;
    Plan(b, live, d, dims[1], boxes, plan);
    return SweepOne(b, plan, d, false, need, tree) < kInf;
  }
  const std::vector<int> by_lo = SortedBy(live, b.lo, b.n, d), by_hi = SortedBy(live, b.hi, b.n, d);
  std::vector<char> open(boxes, 0);
  std::vector<int> active;
  std::size_t next = 0, closed = 0;
  while (next < by_lo.size()) {
    const double t = b.Lo(by_lo[next], d);
    for (; closed < by_hi.size() && b.Hi(by_hi[closed], d) < t; ++closed) open[by_hi[closed]] = 0;
    for (; next < by_lo.size() && b.Lo(by_lo[next], d) == t; ++next) open[by_lo[next]] = 1;
    active.clear();
    for (int i : by_lo)
      if (open[i]) active.push_back(i);
    if (ReachDepth(b, active, dims.subspan(1), need, boxes)) return true;
  }
  return false;
}

// The bound of the hull along d, lowest or highest, for n > 2: the first
// candidate t (in sweep order) where the boxes that hold x_d = t reach depth
// `need` in the other dimensions.
double FirstCovered(const Bounds& b, const std::vector<int>& live, std::size_t d, bool downward,
                    std::span<const std::size_t> rest, int need, int boxes) {
  std::vector<int> by_lo = SortedBy(live, b.lo, b.n, d), by_hi = SortedBy(live, b.hi, b.n, d);
  if (downward) {
    std::reverse(by_lo.begin(), by_lo.end());
    std::reverse(by_hi.begin(), by_hi.end());
    std::swap(by_lo, by_hi);  // enter by upper bound, leave by lower
  }
  auto enter_at = [&](int i) { return downward ? -b.Hi(i, d) : b.Lo(i, d); };
  auto leave_at = [&](int i) { return downward ? -b.Lo(i, d) : b.Hi(i, d); };
  std::vector<char> open(boxes, 0);
  std::vector<int> active;
  std::size_t next = 0, closed = 0;
  while (next < by_lo.size()) {
    const double t = enter_at(by_lo[next]);
    for (; closed < by_hi.size() && leave_at(by_hi[closed]) < t; ++closed) open[by_hi[closed]] = 0;
    for (; next < by_lo.size() && enter_at(by_lo[next]) == t; ++next) open[by_lo[next]] = 1;
    active.clear();
    for (int i : by_lo)
      if (open[i]) active.push_back(i);
    if (ReachDepth(b, active, rest, need, boxes)) return downward ? -t : t;
  }
  return downward ? -kInf : kInf;
}
// The hull when at most one live box may be left out (spare = live boxes -
// need, 0 or 1), in O(m n) instead of a sweep: with none spare it is the
// intersection of the live boxes; with one, the hull over i of the
// intersection of all but box i (prefix and suffix intersections). The
// fixpoints of the relaxed solvers mostly land here: once the outliers'
// boxes are empty, the inliers left are exactly the m - q needed.
Box FewSpare(const Bounds& b, const std::vector<int>& live, int spare) {
  const std::size_t n = b.n, k = live.size();
  Box out(n);
  out.SetEmpty();
  // prefix[j * n + d]: the intersection of live boxes 0..j-1 along d;
  // suffix[j * n + d]: that of boxes j..k-1.
  thread_local std::vector<double> pre_lo, pre_hi, suf_lo, suf_hi;
  pre_lo.assign((k + 1) * n, -kInf);
  pre_hi.assign((k + 1) * n, kInf);
  suf_lo.assign((k + 1) * n, -kInf);
  suf_hi.assign((k + 1) * n, kInf);
  for (std::size_t j = 0; j < k; ++j)
    for (std::size_t d = 0; d < n; ++d) {
      pre_lo[(j + 1) * n + d] = std::max(pre_lo[j * n + d], b.Lo(live[j], d));
      pre_hi[(j + 1) * n + d] = std::min(pre_hi[j * n + d], b.Hi(live[j], d));
      const std::size_t r = k - 1 - j;
      suf_lo[r * n + d] = std::max(suf_lo[(r + 1) * n + d], b.Lo(live[r], d));
      suf_hi[r * n + d] = std::min(suf_hi[(r + 1) * n + d], b.Hi(live[r], d));
    }
  auto add_if_nonempty = [&](auto lo_at, auto hi_at) {
    for (std::size_t d = 0; d < n; ++d)
      if (lo_at(d) > hi_at(d)) return;
    for (std::size_t d = 0; d < n; ++d) out[d] = Hull(out[d], Interval(lo_at(d), hi_at(d)));
  };
  if (spare == 0) {
    add_if_nonempty([&](std::size_t d) { return pre_lo[k * n + d]; }, [&](std::size_t d) { return pre_hi[k * n + d]; });
  } else {
    for (std::size_t i = 0; i < k; ++i)
      add_if_nonempty(
          [&](std::size_t d) { return std::max(pre_lo[i * n + d], suf_lo[(i + 1) * n + d]); },
          [&](std::size_t d) { return std::min(pre_hi[i * n + d], suf_hi[(i + 1) * n + d]); });
  }
  if (out.IsEmpty()) out.SetEmpty();
  return out;
}
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
  const int need = m - q;
  // The fixpoints call this for every round: the storage is kept per thread.
  thread_local Bounds b;
  thread_local std::vector<int> live;
  thread_local SweepPlan plan;
  thread_local MaxAddTree tree;
  b.n = n;
  b.lo.resize(m * n);
  b.hi.resize(m * n);
  live.clear();
  for (int i = 0; i < m; ++i) {
    if (boxes[i].IsEmpty()) continue;
    live.push_back(i);
    for (std::size_t d = 0; d < n; ++d) {
      b.lo[i * n + d] = boxes[i][d].lo();
      b.hi[i * n + d] = boxes[i][d].hi();
    }
  }
  if (static_cast<int>(live.size()) < need) {
    out.SetEmpty();
    return out;
  }
  const int spare = static_cast<int>(live.size()) - need;
  if (spare <= 1) return FewSpare(b, live, spare);
  if (n == 1) {
    std::vector<Interval> xs;
    for (int i : live) xs.push_back(boxes[i][0]);
    out[0] = RelaxedIntersection(xs, static_cast<int>(live.size()) - need);
    return out;
  }
  std::vector<std::size_t> rest;
  for (std::size_t d = 0; d < n; ++d) {
    double lo = kInf, hi = -kInf;
    if (n == 2) {
      Plan(b, live, d, 1 - d, m, plan);
      lo = SweepOne(b, plan, d, false, need, tree);
      if (lo != kInf) hi = SweepOne(b, plan, d, true, need, tree);
    } else {
      rest.clear();
      for (std::size_t r = 0; r < n; ++r)
        if (r != d) rest.push_back(r);
      lo = FirstCovered(b, live, d, false, rest, need, m);
      if (lo != kInf) hi = FirstCovered(b, live, d, true, rest, need, m);
    }
    if (lo == kInf) {
      out.SetEmpty();
      return out;
    }
    out[d] = Interval(lo, hi);
  }
  return out;
}

}  // namespace icp
