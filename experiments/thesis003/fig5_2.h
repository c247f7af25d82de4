// Thesis 003 Fig. 5.2 (§5.1.4): the box polynomials of 20 lines, 7 of them
// outliers, evaluated by the `polynomial` solver's approximations, each with
// its projection on x:
//   (a)  C*(3) at p = 1 (the Horner evaluation, no repetition)
//   (b)  C^(p*) at p = 10 (every coefficient of the Horner evaluation over
//        the lines repeated 10 times)
//   (c)  Ĉ* at p = 10 (every 10th of those: C*(3) at p = 10)
//   (d)  C*(1) at p = 30 (the repeated q-relaxed intersection)
// The white coefficient, degree n - q (n lines, q of them outliers),
// encloses the guaranteed solution; the thesis shows it converging to the
// intersection as p grows, a clear peak in (c), and C*(1) and C*(3) alike at
// a high p.
//
// The runs are those of experiment fig5_2 (specs/default.yaml,
// specs/relaxed.yaml): algorithm polynomial with approximation c3 at p = 1,
// 10 and 30 and c1 at p = 30, each drawn from the ok run with the smallest
// seed. The store keeps hulls, not polynomials, so the coefficients are
// recomputed from the run's definition (problem, params, seed) on the
// problem's first step, as the solver computed them.
#ifndef ICPBENCH_EXPERIMENTS_THESIS003_FIG5_2_H_
#define ICPBENCH_EXPERIMENTS_THESIS003_FIG5_2_H_

#include <array>
#include <string>
#include <vector>

#include "core/box.h"
#include "harness/run_record.h"
#include "plots/figures.h"

namespace icp {

inline constexpr char kThesis003Fig52[] = "fig5_2";

// The ok polynomial run of experiment fig5_2 with this approximation and p
// with the smallest seed; nullptr when there is none.
const RunRecord* Fig52PolynomialRun(const std::vector<RunRecord>& runs,
                                    const std::string& approximation, int p);

// A run's box polynomial, recomputed (see the top).
struct RecomputedPolynomial {
  // The approximation of C*(s): coefficients by degree 0..n.
  std::vector<Box> coefficients;
  // With repeated (c3 only): C^(p*)(s), coefficients by degree 0..p n.
  std::vector<Box> repeated;
  int white = 0;  // n - q: the measurements less the true outliers
  Box prior;
  std::vector<double> truth;  // (x, y); empty when unknown
  // The lines {x0, y0, x1, y1} across the prior, for line-intersection;
  // empty for another problem.
  std::vector<std::array<double, 4>> lines;
};
// Throws std::invalid_argument (or ParamError) when the run's parameters no
// longer parse, or its first step has no measurement-set view.
RecomputedPolynomial RecomputePolynomial(const RunRecord& run, bool repeated = false);

// The widest side of a box (its x-y extent); infinity when empty.
double WidestSide(const Box& box);

// The figure fig5_2_box_polynomials; skipped with a message naming the runs
// it lacks.
void Fig52Figure(const std::vector<RunRecord>& runs, const std::string& out_dir, PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_THESIS003_FIG5_2_H_
