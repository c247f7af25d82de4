#include "core/projections.h"

#include <cmath>

namespace icp {

namespace {

// x ∩ (p ∪ -p) for an even function value set p >= 0 (sqr, even powers, abs,
// cosh): keeps the hull of both signed branches.
Interval IntersectSymmetric(const Interval& x, const Interval& p) {
  return Hull(Intersect(x, p), Intersect(x, -p));
}

// The hull of x ∩ ⋃_k (piece + k * period) for k in Z, where piece is a
// bounded interval and period an enclosure of the period. Used for the
// inverse images of sin, cos and tan. Bounds far beyond 2^50 are left as they
// are: k * period is too imprecise there to contract soundly.
Interval IntersectPeriodic(const Interval& x, const Interval& piece, const Interval& period) {
  if (x.IsEmpty() || piece.IsEmpty()) return Interval::Empty();
  constexpr double kFar = 0x1p50;
  double lo = x.lo();
  double hi = x.hi();
  if (std::fabs(lo) < kFar) {
    // First k whose copy of piece reaches lo; step down a little for safety.
    double k = std::floor((lo - piece.hi()) / period.lo()) - 1;
    while ((piece + Interval(k) * period).hi() >= lo) k -= 1;
    for (int guard = 0;; ++guard, k += 1) {
      Interval copy = piece + Interval(k) * period;
      if (copy.lo() > hi) return Interval::Empty();
      if (copy.hi() >= lo) {
        lo = std::fmax(lo, copy.lo());
        break;
      }
      if (guard > 8) break;  // unreachable for a valid period; stay sound
    }
  }
  if (std::fabs(hi) < kFar) {
    double k = std::ceil((hi - piece.lo()) / period.lo()) + 1;
    while ((piece + Interval(k) * period).lo() <= hi) k += 1;
    for (int guard = 0;; ++guard, k -= 1) {
      Interval copy = piece + Interval(k) * period;
      if (copy.hi() < lo) return Interval::Empty();
      if (copy.lo() <= hi) {
        hi = std::fmin(hi, copy.hi());
        break;
      }
      if (guard > 8) break;
    }
  }
  return Interval(lo, hi);
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

void BwdAdd(const Interval& z, Interval& x, Interval& y) {
  x = Intersect(x, z - y);
  y = Intersect(y, z - x);
}

void BwdSub(const Interval& z, Interval& x, Interval& y) {
  x = Intersect(x, z + y);
  y = Intersect(y, x - z);
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

void BwdNeg(const Interval& z, Interval& x) { x = Intersect(x, -z); }

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
  const Interval two_pi = TwoPi();
  // sin t in z  <=>  t in (a + 2k pi) or (pi - a + 2k pi).
  x = Hull(IntersectPeriodic(x, a, two_pi), IntersectPeriodic(x, Pi() - a, two_pi));
}

void BwdCos(const Interval& z, Interval& x) {
  Interval a = Acos(Intersect(z, Interval(-1.0, 1.0)));  // in [0, pi]
  if (a.IsEmpty()) {
    x = Interval::Empty();
    return;
  }
  const Interval two_pi = TwoPi();
  // cos t in z  <=>  t in (a + 2k pi) or (-a + 2k pi).
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
