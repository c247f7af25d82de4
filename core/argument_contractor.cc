#include "core/argument_contractor.h"

#include <algorithm>
#include <cmath>

namespace icp {

namespace {

// The bounds of p / q for p, q >= 0, rounded down (lower) or up: 0 / q is 0
// and p / 0 is +oo for p > 0; 0 / 0 counts as 0 below and +oo above (the
// origin has every argument).
double RatioLo(double p, double q) {
  if (p == 0 || q == kInf) return 0;
  if (q == 0 || p == kInf) return kInf;
  return (Interval(p) / Interval(q)).lo();
}
double RatioHi(double p, double q) {
  if (q == 0 || p == kInf) return kInf;
  if (p == 0 || q == kInf) return 0;
  return (Interval(p) / Interval(q)).hi();
}

// Bounds of tan t and atan r on the first quadrant, rounded outward; at or
// beyond the lower enclosure of pi/2 tan has no finite upper bound, and its
// lower bound is taken just below it (tan increases).
double TanLo(double t) {
  if (t <= 0) return 0;
  const double below = std::nextafter(HalfPi().lo(), 0.0);
  return std::max(0.0, Tan(Interval(std::min(t, below))).lo());
}
double TanHi(double t) {
  if (t <= 0) return 0;
  if (t >= HalfPi().lo()) return kInf;
  const double hi = Tan(Interval(t)).hi();
  return std::isfinite(hi) && hi >= 0 ? hi : kInf;
}
double AtanLo(double r) { return r == kInf ? HalfPi().lo() : Atan(Interval(r)).lo(); }
double AtanHi(double r) { return r == kInf ? HalfPi().hi() : Atan(Interval(r)).hi(); }

// Bounds of y = x tan(theta) from a bound p of x >= 0 and t of tan(theta) >=
// 0, rounded down or up. A zero tangent (theta = 0) is the x axis: y = 0 for
// any x. An infinite one (theta = pi/2) is the y axis: below, nothing; above,
// no bound, even at x = 0.
double ProductLo(double p, double t) {
  if (p == 0 || t == 0) return 0;
  if (p == kInf || t == kInf) return kInf;
  return (Interval(p) * Interval(t)).lo();
}
double ProductHi(double p, double t) {
  if (t == 0) return 0;
  if (t == kInf || p == kInf) return kInf;
  if (p == 0) return 0;
  return (Interval(p) * Interval(t)).hi();
}

// The core contractor (eq. 4.83) on x, y >= 0, theta in [0, pi/2]: the
// fixpoint of theta <- atan(y / x), x <- y / tan(theta), y <- x tan(theta).
// False when the box holds no point of the set.
bool ContractRoot(Interval& x, Interval& y, Interval& theta) {
  x = Intersect(x, Interval(0.0, kInf));
  y = Intersect(y, Interval(0.0, kInf));
  theta = Intersect(theta, Interval(0.0, HalfPi().hi()));
  if (x.IsEmpty() || y.IsEmpty() || theta.IsEmpty()) return false;
  double a = x.lo(), b = x.hi(), c = y.lo(), d = y.hi(), t0 = theta.lo(), t1 = theta.hi();
  for (int round = 0; round < 50; ++round) {
    const double t0n = std::max(t0, AtanLo(RatioLo(c, b)));
    const double t1n = std::min(t1, AtanHi(RatioHi(d, a)));
    if (t0n > t1n) return false;
    // x in y / tan(theta), y in x tan(theta).
    const double an = std::max(a, RatioLo(c, TanHi(t1n)));
    const double bn = std::min(b, RatioHi(d, TanLo(t0n)));
    if (an > bn) return false;
    const double cn = std::max(c, ProductLo(an, TanLo(t0n)));
    const double dn = std::min(d, ProductHi(bn, TanHi(t1n)));
    if (cn > dn) return false;
    const bool same = an == a && bn == b && cn == c && dn == d && t0n == t0 && t1n == t1;
    a = an, b = bn, c = cn, d = dn, t0 = t0n, t1 = t1n;
    if (same) break;
  }
  x = Interval(a, b);
  y = Interval(c, d);
  theta = Interval(t0, t1);
  return true;
}

// k pi, enclosed.
Interval Offset(int pis) { return Interval(static_cast<double>(pis)) * Pi(); }

}  // namespace

void ContractArgument(Interval& x, Interval& y, Interval& theta) {
  if (x.IsEmpty() || y.IsEmpty() || theta.IsEmpty()) {
    x = y = theta = Interval::Empty();
    return;
  }
  // Four turns or more: every direction is allowed and theta keeps all. So
  // far out that a turn is below the doubles' resolution, likewise.
  if (!(theta.Width() < 4 * Pi().lo()) || !(std::abs(theta.lo()) < 1e12) ||
      !(std::abs(theta.hi()) < 1e12))
    return;
  // theta = sign r + offset pi, r the core's angle of (sx x, sy y).
  struct Piece {
    double sx, sy, sign;
    int offset;
  };
  const Piece quadrants[] = {{1, 1, 1, 0}, {-1, 1, -1, 1}, {1, -1, -1, 0}, {-1, -1, 1, -1}};
  Interval rx = Interval::Empty(), ry = Interval::Empty(), rt = Interval::Empty();
  for (const Piece& q : quadrants) {
    const Interval xq = Intersect(x, q.sx > 0 ? Interval(0.0, kInf) : Interval(-kInf, 0.0));
    const Interval yq = Intersect(y, q.sy > 0 ? Interval(0.0, kInf) : Interval(-kInf, 0.0));
    if (xq.IsEmpty() || yq.IsEmpty()) continue;
    // The quadrant's angles, enclosed: offset pi + sign [0, pi/2].
    const Interval span = Offset(q.offset) + Interval(q.sign) * Interval(0.0, HalfPi().hi());
    const double two_pi = TwoPi().lo();
    const long k_first = static_cast<long>(std::floor((theta.lo() - span.hi()) / two_pi)) - 1;
    const long k_last = static_cast<long>(std::ceil((theta.hi() - span.lo()) / two_pi)) + 1;
    for (long k = k_first; k <= k_last; ++k) {
      const Interval turns = Interval(static_cast<double>(k)) * TwoPi();
      const Interval local = Intersect(theta - turns, span);
      if (local.IsEmpty()) continue;
      Interval cx = Interval(q.sx) * xq, cy = Interval(q.sy) * yq;
      Interval r = Interval(q.sign) * (local - Offset(q.offset));
      if (!ContractRoot(cx, cy, r)) continue;
      const Interval back = Intersect(Interval(q.sign) * r + Offset(q.offset) + turns, theta);
      if (back.IsEmpty()) continue;
      rx = Hull(rx, Intersect(Interval(q.sx) * cx, xq));
      ry = Hull(ry, Intersect(Interval(q.sy) * cy, yq));
      rt = Hull(rt, back);
    }
  }
  if (rx.IsEmpty() || ry.IsEmpty() || rt.IsEmpty()) {
    x = y = theta = Interval::Empty();
    return;
  }
  x = rx, y = ry, theta = rt;
}

Interval Atan2(const Interval& y, const Interval& x) {
  Interval cx = x, cy = y, theta(-Pi().hi(), Pi().hi());
  ContractArgument(cx, cy, theta);
  return theta;
}

void BwdAtan2(const Interval& z, Interval& y, Interval& x) {
  Interval theta = Intersect(z, Interval(-Pi().hi(), Pi().hi()));
  ContractArgument(x, y, theta);
}

ContractSummary ArgumentContractor::Contract(Box& box, ContractContext& /*context*/) {
  const Box before = box;
  ContractArgument(box[x_], box[y_], box[theta_]);
  if (box[x_].IsEmpty()) box.SetEmpty();
  ContractSummary summary;
  summary.status = StatusOf(before, box);
  return summary;
}

}  // namespace icp
