#include "core/projections.h"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace icp {

namespace {

// x ∩ (p ∪ -p) for an even function value set p >= 0 (sqr, even powers, abs,
// cosh): keeps the hull of both signed branches.
Interval IntersectSymmetric(const Interval& x, const Interval& p) {
  return Hull(Intersect(x, p), Intersect(x, -p));
}

// The enclosure piece + Interval(k) * period of the k-th copy of piece, on
// the bounds (period > 0, k an integer).
struct Copies {
  const Interval& piece;
  const Interval& period;
  double Lo(double k) const {
    ExactRounding rnd;
    return rnd.add_down(piece.lo(), rnd.mul_down(k, k >= 0 ? period.lo() : period.hi()));
  }
  double Hi(double k) const {
    ExactRounding rnd;
    return rnd.add_up(piece.hi(), rnd.mul_up(k, k >= 0 ? period.hi() : period.lo()));
  }
};

// The hull of x ∩ ⋃_k (piece + k * period) for k in Z, where piece is a
// bounded interval and period an enclosure of the period. Used for the
// inverse images of sin, cos and tan. Bounds far beyond 2^50 are left as they
// are: k * period is too imprecise there to contract soundly.
//
// The copies' enclosures are increasing in k, so the new lower bound comes
// from the first copy that reaches lo (and the upper bound from the last one
// that reaches hi); the quotient estimates are within one of those k, and
// the loops walk to them from a k verified to be on the far side.
Interval IntersectPeriodic(const Interval& x, const Interval& piece, const Interval& period) {
  if (x.IsEmpty() || piece.IsEmpty()) return Interval::Empty();
  constexpr double kFar = 0x1p50;
  const Copies copies{piece, period};
  double lo = x.lo();
  double hi = x.hi();
  if (std::fabs(lo) < kFar) {
    double k = std::floor((lo - piece.hi()) / period.lo());
    while (copies.Hi(k) >= lo) k -= 1;
    for (int guard = 0;; ++guard) {
      k += 1;
      if (copies.Hi(k) >= lo) {
        const double copy_lo = copies.Lo(k);
        if (copy_lo > hi) return Interval::Empty();
        if (copy_lo > lo) lo = copy_lo;
        break;
      }
      if (guard > 8) break;  // unreachable for a valid period; stay sound
    }
  }
  if (std::fabs(hi) < kFar) {
    double k = std::ceil((hi - piece.lo()) / period.lo());
    while (copies.Lo(k) <= hi) k += 1;
    for (int guard = 0;; ++guard) {
      k -= 1;
      if (copies.Lo(k) <= hi) {
        const double copy_hi = copies.Hi(k);
        if (copy_hi < lo) return Interval::Empty();
        if (copy_hi < hi) hi = copy_hi;
        break;
      }
      if (guard > 8) break;
    }
  }
  return Interval(lo, hi);
}

// x ∩ (piece + k * period) for one copy k.
Interval IntersectCopy(const Interval& x, const Interval& piece, double k, const Interval& period) {
  const Copies copies{piece, period};
  const double copy_lo = copies.Lo(k), copy_hi = copies.Hi(k);
  return Interval(x.lo() < copy_lo ? copy_lo : x.lo(), x.hi() < copy_hi ? x.hi() : copy_hi);
}

// Whether x lies inside one branch (m pi - shift, (m + 1) pi - shift) of
// sin or cos (shift pi / 2 and 0: the maximal intervals on which they are
// monotone), clear of its ends by a margin; sets *m. The margin, 1e-12 of
// the quotient, dwarfs the rounding of the quotients (a few 1e-16 of them)
// and how far the enclosures of the other branches' copies in
// IntersectPeriodic can reach past the branch ends (a few ulps of k * 2 pi),
// so none of them meets x.
bool InOneBranch(const Interval& x, double shift_in_pi, std::int64_t* m) {
  constexpr double kPiApprox = std::numbers::pi;  // only to count branches
  if (x.IsEmpty() || !(x.Mag() < 0x1p40)) return false;
  const double q_lo = x.lo() / kPiApprox + shift_in_pi;
  const double q_hi = x.hi() / kPiApprox + shift_in_pi;
  const double m_lo = std::floor(q_lo - 1e-12 * (std::fabs(q_lo) + 1));
  const double m_hi = std::floor(q_hi + 1e-12 * (std::fabs(q_hi) + 1));
  if (m_lo != m_hi) return false;
  *m = static_cast<std::int64_t>(m_lo);
  return true;
}

}  // namespace

Interval DivideRelational(const Interval& x, const Interval& z, const Interval& y) {
  if (x.IsEmpty() || z.IsEmpty() || y.IsEmpty()) return Interval::Empty();
  if (!y.ContainsZero()) return Intersect(x, z / y);
  if (z.ContainsZero()) return x;  // t = 0 * anything: nothing removed
  if (y.lo() == 0 && y.hi() == 0) return Interval::Empty();  // t * 0 = c != 0
  // 0 in y, 0 not in z: the solutions are two half lines, one per sign of y.
  Interval negative_part = Intersect(y, Interval(-kInf, 0.0));
  Interval positive_part = Intersect(y, Interval(0.0, kInf));
  Interval result = Interval::Empty();
  if (negative_part.lo() < 0) result = Hull(result, Intersect(x, z / negative_part));
  if (positive_part.hi() > 0) result = Hull(result, Intersect(x, z / positive_part));
  return result;
}

void BwdMul(const Interval& z, Interval& x, Interval& y) {
  x = DivideRelational(x, z, y);
  y = DivideRelational(y, z, x);
}

void BwdDiv(const Interval& z, Interval& x, Interval& y) {
  // z = x / y  <=>  x = z * y with y != 0.
  x = Intersect(x, z * y);
  y = DivideRelational(y, x, z);
}

void BwdSqr(const Interval& z, Interval& x) {
  x = IntersectSymmetric(x, Sqrt(z));
}

void BwdPow(const Interval& z, Interval& x, int n) {
  if (n == 0) {
    if (!z.Contains(1.0)) x = Interval::Empty();
    return;
  }
  if (n < 0) {
    // z = 1 / x^m with m = -n: x^m = 1 / z.
    Interval w = DivideRelational(Pow(x, -n), Interval(1.0), z);
    BwdPow(w, x, -n);
    return;
  }
  if (n % 2 == 0) {
    x = IntersectSymmetric(x, Root(z, n));
  } else {
    x = Intersect(x, Root(z, n));
  }
}

void BwdSqrt(const Interval& z, Interval& x) {
  Interval root = Intersect(z, Interval(0.0, kInf));
  x = Intersect(x, Intersect(Sqr(root), Interval(0.0, kInf)));
}

void BwdExp(const Interval& z, Interval& x) { x = Intersect(x, Log(z)); }

void BwdLog(const Interval& z, Interval& x) { x = Intersect(x, Exp(z)); }

void BwdSin(const Interval& z, Interval& x) {
  Interval a = Asin(Intersect(z, Interval(-1.0, 1.0)));  // in [-pi/2, pi/2]
  if (a.IsEmpty()) {
    x = Interval::Empty();
    return;
  }
  const Interval& two_pi = TwoPi();
  // sin t in z  <=>  t in (a + 2k pi) or (pi - a + 2k pi). On one monotone
  // branch [m pi - pi/2, m pi + pi/2] only one copy can meet x: the same
  // result as the general case below, found directly.
  std::int64_t m;
  if (InOneBranch(x, 0.5, &m)) {
    if ((m & 1) == 0) {
      x = IntersectCopy(x, a, static_cast<double>(m / 2), two_pi);
    } else {
      x = IntersectCopy(x, Pi() - a, static_cast<double>((m - 1) / 2), two_pi);
    }
    return;
  }
  x = Hull(IntersectPeriodic(x, a, two_pi), IntersectPeriodic(x, Pi() - a, two_pi));
}

void BwdCos(const Interval& z, Interval& x) {
  Interval a = Acos(Intersect(z, Interval(-1.0, 1.0)));  // in [0, pi]
  if (a.IsEmpty()) {
    x = Interval::Empty();
    return;
  }
  const Interval& two_pi = TwoPi();
  // cos t in z  <=>  t in (a + 2k pi) or (-a + 2k pi). On one monotone
  // branch [m pi, (m + 1) pi] only one copy can meet x (see BwdSin).
  std::int64_t m;
  if (InOneBranch(x, 0.0, &m)) {
    if ((m & 1) == 0) {
      x = IntersectCopy(x, a, static_cast<double>(m / 2), two_pi);
    } else {
      x = IntersectCopy(x, -a, static_cast<double>((m + 1) / 2), two_pi);
    }
    return;
  }
  x = Hull(IntersectPeriodic(x, a, two_pi), IntersectPeriodic(x, -a, two_pi));
}

void BwdTan(const Interval& z, Interval& x) {
  if (z.IsEmpty()) {
    x = Interval::Empty();
    return;
  }
  // tan t in z  <=>  t in atan(z) + k pi (the poles are not in the domain).
  x = IntersectPeriodic(x, Atan(z), Pi());
}

void BwdAtan(const Interval& z, Interval& x) {
  const Interval half_pi = HalfPi();
  Interval w = Intersect(z, Interval(-half_pi.hi(), half_pi.hi()));
  if (w.IsEmpty()) {
    x = Interval::Empty();
    return;
  }
  // atan is increasing onto ]-pi/2, pi/2[: a bound that may reach a pole
  // leaves that side of x open.
  double lo = w.lo() <= -half_pi.lo() ? -kInf : Tan(Interval(w.lo())).lo();
  double hi = w.hi() >= half_pi.lo() ? kInf : Tan(Interval(w.hi())).hi();
  x = Intersect(x, Interval(lo, hi));
}

void BwdSinh(const Interval& z, Interval& x) { x = Intersect(x, Asinh(z)); }

void BwdCosh(const Interval& z, Interval& x) {
  x = IntersectSymmetric(x, Acosh(Intersect(z, Interval(1.0, kInf))));
}

void BwdTanh(const Interval& z, Interval& x) {
  x = Intersect(x, Atanh(Intersect(z, Interval(-1.0, 1.0))));
}

void BwdAbs(const Interval& z, Interval& x) {
  x = IntersectSymmetric(x, Intersect(z, Interval(0.0, kInf)));
}

void BwdMin(const Interval& z, Interval& x, Interval& y) {
  // min(x, y) = z: both are >= z.lo; one of them lies in z.
  Interval at_least = Interval(z.lo(), kInf);
  x = Intersect(x, at_least);
  y = Intersect(y, at_least);
  if (z.IsEmpty()) x = y = Interval::Empty();
  if (x.IsEmpty() || y.IsEmpty()) {
    x = y = Interval::Empty();
    return;
  }
  if (Intersect(y, z).IsEmpty()) x = Intersect(x, z);
  if (Intersect(x, z).IsEmpty()) y = Intersect(y, z);
  if (x.IsEmpty() || y.IsEmpty()) x = y = Interval::Empty();
}

void BwdMax(const Interval& z, Interval& x, Interval& y) {
  // max(x, y) = -min(-x, -y).
  Interval nx = -x, ny = -y;
  BwdMin(-z, nx, ny);
  x = -nx;
  y = -ny;
}

}  // namespace icp
