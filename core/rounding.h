// Directed rounding for Boost.Interval without touching the FPU rounding mode.
//
// Boost.Interval takes its rounding from a policy class. The stock policies
// switch the processor's rounding mode, which GCC may reorder or constant-fold
// across unless the whole program is built with -frounding-math, and which
// leaks into libm calls. This policy instead computes each bound in the default
// round-to-nearest mode and corrects it with an error-free transformation
// (Fast2Sum, FMA residuals): the result is exactly the directed-rounded value
// (the tightest double bound), is thread safe, and needs no global state.
//
// libm's transcendental functions are not correctly rounded; their results are
// widened outward by kLibmUlps units in the last place. glibc documents its
// measured maximum errors for x86-64 in sysdeps/x86_64/fpu/libm-test-ulps: at
// most 2 ulps for every function used here in round-to-nearest mode, so 4 ulps
// leaves a margin of two. The MPFR oracle tests (core/interval_oracle_test.cc)
// check this on random and edge-case inputs.
#ifndef ICPBENCH_CORE_ROUNDING_H_
#define ICPBENCH_CORE_ROUNDING_H_

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace icp {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr int kLibmUlps = 4;

// The next double above x (x itself for +inf and NaN).
inline double NextUp(double x) {
  if (!(x < kInf)) return x;
  if (x == 0) return std::numeric_limits<double>::denorm_min();
  auto bits = std::bit_cast<std::uint64_t>(x);
  bits = x > 0 ? bits + 1 : bits - 1;
  return std::bit_cast<double>(bits);
}

// The next double below x (x itself for -inf and NaN).
inline double NextDown(double x) { return -NextUp(-x); }

// x moved by ulps doubles (0 <= ulps <= 16). Away from zero and infinity the
// doubles of one sign are consecutive bit patterns, so this is one integer
// step there; elsewhere it steps one double at a time.
inline double StepUp(double x, int ulps) {
  constexpr double kSmall = 0x1p-1000, kLarge = 0x1p1000;
  const auto bits = std::bit_cast<std::uint64_t>(x);
  if (x >= kSmall && x <= kLarge) return std::bit_cast<double>(bits + ulps);
  if (x <= -kSmall && x >= -kLarge) return std::bit_cast<double>(bits - ulps);
  for (int i = 0; i < ulps; ++i) x = NextUp(x);
  return x;
}
inline double StepDown(double x, int ulps) { return -StepUp(-x, ulps); }

// Below this magnitude an FMA residual may underflow and no longer be exact;
// results there are widened by one ulp unconditionally.
inline constexpr double kResidualExactThreshold = 0x1p-960;

// Two of ExactRounding::add_up's usual cases at once, one per lane of an
// SSE2 register: an interval sum or difference needs two rounded-up
// additions (its lower bound is -add_up(-a, -b)), and doing them side by
// side takes half the instructions (PairedSum and PairedDifference in
// interval.h, which say where that is faster). Returns false, leaving sum
// alone, unless every operand is finite and below 2^1020 in magnitude; the
// scalar add_up handles the rest (and everything on processors without
// SSE2, where this function does not exist). Bit for bit add_up's result:
// the same operations in the same order.
#if defined(__SSE2__)
inline bool AddUpPair(__m128d x, __m128d y, __m128d& sum) {
  const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffff));
  const __m128d limit = _mm_set1_pd(0x1p1020);
  const __m128d small = _mm_and_pd(_mm_cmplt_pd(_mm_and_pd(x, magnitude), limit),
                                   _mm_cmplt_pd(_mm_and_pd(y, magnitude), limit));
  if (_mm_movemask_pd(small) != 3) return false;  // NaN compares false too
  // Knuth's TwoSum per lane, as in add_up.
  const __m128d s = _mm_add_pd(x, y);
  const __m128d y_part = _mm_sub_pd(s, x);
  const __m128d x_part = _mm_sub_pd(s, y_part);
  const __m128d err = _mm_add_pd(_mm_sub_pd(x, x_part), _mm_sub_pd(y, y_part));
  // err > 0 only when s is inexact, so finite and not zero: the next double
  // up is one step of its bit pattern, +1 for s > 0 and -1 for s < 0 (the
  // sign copied over each 64-bit lane, or 1).
  const __m128i bits = _mm_castpd_si128(s);
  const __m128i negative = _mm_shuffle_epi32(_mm_srai_epi32(bits, 31), 0xf5);
  const __m128i step = _mm_or_si128(negative, _mm_set1_epi64x(1));
  const __m128i up = _mm_castpd_si128(_mm_cmpgt_pd(err, _mm_setzero_pd()));
  sum = _mm_castsi128_pd(_mm_add_epi64(bits, _mm_and_si128(step, up)));
  return true;
}
#endif

// The rounding policy plugged into boost::numeric::interval (see interval.h).
struct ExactRounding {
  // No processor state to save or restore: Boost may skip its protection.
  using unprotected_rounding = ExactRounding;
  // Conversions from double are exact.
  double conv_down(double v) { return v; }
  double conv_up(double v) { return v; }

  double add_down(double x, double y) { return -add_up(-x, -y); }
  double add_up(double x, double y) {
    // Usual case, finite operands below 2^1020: Knuth's TwoSum, exact
    // (s + err = x + y) when no intermediate overflows, which these bounds
    // guarantee; no branch on the operands' order.
    if (std::fabs(x) < 0x1p1020 && std::fabs(y) < 0x1p1020) {
      const double s = x + y;
      const double y_part = s - x;
      const double x_part = s - y_part;
      const double err = (x - x_part) + (y - y_part);
      return err > 0 ? NextUp(s) : s;
    }
    double s = x + y;
    if (std::isnan(s)) return kInf;              // inf + -inf: no information
    if (std::isinf(s)) {                         // exact if an input is infinite,
      if (std::isinf(x) || std::isinf(y)) return s;  // else an overflow
      return s > 0 ? kInf : -std::numeric_limits<double>::max();
    }
    // Fast2Sum (Dekker), larger magnitude first: s + err = x + y exactly, and
    // unlike Knuth's TwoSum no intermediate can overflow when s is finite
    // (TwoSum's s - x overflowed for x = 8.6e307, y = -DBL_MAX and lost the
    // rounding error).
    double big = std::fabs(x) >= std::fabs(y) ? x : y;
    double small = std::fabs(x) >= std::fabs(y) ? y : x;
    double err = small - (s - big);
    return err > 0 ? NextUp(s) : s;
  }
  double sub_down(double x, double y) { return add_down(x, -y); }
  double sub_up(double x, double y) { return add_up(x, -y); }

  double mul_down(double x, double y) { return -mul_up(-x, y); }
  double mul_up(double x, double y) {
    if (x == 0 || y == 0) return 0;              // 0 * inf is 0 for interval bounds
    double p = x * y;
    if (std::isinf(p)) {
      if (std::isinf(x) || std::isinf(y)) return p;
      return p > 0 ? kInf : -std::numeric_limits<double>::max();
    }
    if (std::fabs(p) < kResidualExactThreshold) return NextUp(p);
    double err = std::fma(x, y, -p);             // exact: x * y = p + err
    return err > 0 ? NextUp(p) : p;
  }

  double div_down(double x, double y) { return -div_up(-x, y); }
  double div_up(double x, double y) {
    if (std::isinf(x) && std::isinf(y)) return kInf;  // no information
    if (std::isinf(y)) return 0;                 // finite / inf: the bound is 0
    double q = x / y;
    if (std::isinf(q)) {
      if (std::isinf(x) || y == 0) return q;
      return q > 0 ? kInf : -std::numeric_limits<double>::max();
    }
    if (std::isnan(q)) return kInf;              // 0 / 0: no information
    if (x == 0) return q;
    if (std::fabs(q) < kResidualExactThreshold ||
        std::fabs(x) < kResidualExactThreshold)
      return NextUp(q);
    double r = std::fma(-q, y, x);               // exact: x = q * y + r
    // x / y - q = r / y: positive when r and y have the same sign.
    return (r > 0 && y > 0) || (r < 0 && y < 0) ? NextUp(q) : q;
  }

  double sqrt_down(double x) {
    if (x <= 0) return 0;
    double s = std::sqrt(x);
    if (std::isinf(s)) return s == kInf ? std::numeric_limits<double>::max() : s;
    if (x < kResidualExactThreshold) return NextDown(s);
    double r = std::fma(-s, s, x);               // exact: x = s * s + r
    return r < 0 ? NextDown(s) : s;
  }
  double sqrt_up(double x) {
    if (x <= 0) return 0;
    double s = std::sqrt(x);
    if (std::isinf(s)) return s;
    if (x < kResidualExactThreshold) return NextUp(s);
    double r = std::fma(-s, s, x);
    return r > 0 ? NextUp(s) : s;
  }

  double median(double x, double y) { return x / 2 + y / 2; }
  double int_down(double x) { return std::floor(x); }
  double int_up(double x) { return std::ceil(x); }

  static bool IsKnownExact(double x, double v) {
    return (x == 0 || x == 1) && (v == 0 || v == 1);
  }

  // Transcendental bounds: libm's result widened by kLibmUlps, clamped to the
  // function's range, exact at the few points where the value is known: every
  // f(0) and f(1) below that equals 0 or 1 does so exactly (exp, cos, cosh at
  // 0; the odd functions at 0; log, acos, acosh at 1), and no other f(0) or
  // f(1) is near 0 or 1.
  static double WidenDown(double x, double v, double lo_clamp) {
    if (std::isnan(v)) return lo_clamp;
    if (IsKnownExact(x, v)) return v;
    const double d = StepDown(v, kLibmUlps);  // not NaN: no fmax call needed
    return d < lo_clamp ? lo_clamp : d;
  }
  static double WidenUp(double x, double v, double hi_clamp) {
    if (std::isnan(v)) return hi_clamp;
    if (IsKnownExact(x, v)) return v;
    const double u = StepUp(v, kLibmUlps);
    return u > hi_clamp ? hi_clamp : u;
  }
  // f_both gives f_down and f_up from one libm call.
#define ICP_WIDENED(f, lo_clamp, hi_clamp)                                  \
  double f##_down(double x) { return WidenDown(x, std::f(x), lo_clamp); }   \
  double f##_up(double x) { return WidenUp(x, std::f(x), hi_clamp); }       \
  void f##_both(double x, double* down, double* up) {                       \
    const double v = std::f(x);                                             \
    *down = WidenDown(x, v, lo_clamp);                                      \
    *up = WidenUp(x, v, hi_clamp);                                          \
  }
  ICP_WIDENED(exp, 0.0, kInf)
  ICP_WIDENED(log, -kInf, kInf)
  ICP_WIDENED(sin, -1.0, 1.0)
  ICP_WIDENED(cos, -1.0, 1.0)
  ICP_WIDENED(tan, -kInf, kInf)
  ICP_WIDENED(asin, -2.0, 2.0)
  ICP_WIDENED(acos, 0.0, 4.0)
  ICP_WIDENED(atan, -2.0, 2.0)
  ICP_WIDENED(sinh, -kInf, kInf)
  ICP_WIDENED(cosh, 1.0, kInf)
  ICP_WIDENED(tanh, -1.0, 1.0)
  ICP_WIDENED(asinh, -kInf, kInf)
  ICP_WIDENED(acosh, 0.0, kInf)
  ICP_WIDENED(atanh, -kInf, kInf)
#undef ICP_WIDENED
};

}  // namespace icp

#endif  // ICPBENCH_CORE_ROUNDING_H_
